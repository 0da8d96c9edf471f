#!/usr/bin/env python3
"""Bad input stops the run with a FatalIOError naming the dictionary, the
keyword and the allowed range.

Runs the solver on a small 2-D wall-impact case once per bad entry of
roughWallInteractionCoeffs and checks that it fails (non-zero exit code, no
crash) with "FOAM FATAL IO ERROR", the dictionary name, the keyword and the
allowed values in the log.  The dictionary name differs between the
platforms (the settings are #include'd from constant/roughWallSettings):
  v1912  .../constant/kinematicCloudProperties.subModels.
         roughWallInteractionCoeffs.patches.<entry>
  13     .../constant/roughWallSettings/roughWallInteractionCoeffs/
         patches.<entry> (OpenFOAM-13 names an included dictionary after
         its file and scopes with '/')  Controls: the unmodified settings
run, write the statistics file and summarise each patch's settings in the
log (a rebound outlet too), writeToFile false writes none, an entry
that only matches patches of an earlier entry runs with the earlier one and
is warned of ("The patches entry lowerWall is never applied"); without the
libs entry the run fails with OpenFOAM's "Unknown patchInteractionModel type
roughWallInteraction" (v1912) or "Unknown patch interaction model type
roughWallInteraction" (OpenFOAM-13), the troubleshooting symptom of the docs.

Usage: testPatchSettingsBadInput.py --platform openfoam13|openfoam1912 [--cloud KIND]
           [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import os
import shutil

from foamcase import testing as t
import foamcase as fc

ROUGH = {
    "type": "rough",
    "e": "0.8",
    "mu0": "0.4",
    "muD": "0.4",
    "roughnessAngle": "8",
}


def settings(rough=None, outlet="outlet { type escape; }", patches=True,
             coeffs=""):
    """roughWallSettings with the lowerWall/upperWall entry rough (None:
    remove a keyword), the outlet entry given and extra coefficients."""
    entries = dict(ROUGH)
    entries.update(rough or {})
    # (a sub-dictionary value, "{ ... }", takes no semicolon)
    body = "\n".join("            %-15s %s%s" % (k, v, "" if v.endswith("}")
                                                   else ";")
                     for k, v in entries.items() if v is not None)
    patch_list = """    patches
    (
        "(lowerWall|upperWall)"
        {
%s
        }
        %s
    );
""" % (body, outlet)
    return """
patchInteractionModel roughWallInteraction;

roughWallInteractionCoeffs
{
%s%s}
""" % (patch_list if patches else "", coeffs)


class Scope:
    """The dictionary scope of a patches entry in the error message:
    v1912 roughWallInteractionCoeffs.patches.<entry>; OpenFOAM-13 scopes
    with '/' (roughWallInteractionCoeffs/patches, then '.' or '/' and the
    entry), OpenFOAM-14 with '!' then '/'
    (roughWallInteractionCoeffs!patches/<entry>), in the dictionary of the
    included roughWallSettings."""

    def __init__(self, entry):
        self.entry = entry

    def texts(self, platform):
        if platform.foundation:
            return ["roughWallInteractionCoeffs%spatches%s%s"
                    % (sep0, sep, self.entry)
                    for sep0, sep in (("/", "."), ("/", "/"), ("!", "/"))]
        return ["roughWallInteractionCoeffs.patches." + self.entry]


IN_PATCH = Scope("(lowerWall|upperWall)")
IN_OUTLET = Scope("outlet")

#: The parts of a message that a test asserts (not its sentences, which a
#: clean-up may reword): the keyword, quoted; the reason: the allowed range
#: or type, the value found, or for an unknown keyword its closest match
def key(name):
    return "'%s'" % name


def closest(name):
    return "closest: " + name


NUMBER = "number"
INTEGER = "integer"

#: name, settings, fragments of the error message: the keyword, the
#: dictionary scope (a Scope, or the coefficients' name) and the reason
#: (the value found is quoted)
CASES = [
    ("unknown type", settings({"type": "bouncy"}),
     [key("type"), IN_PATCH, "rough rebound stick escape none", "'bouncy'"]),
    ("e negative", settings({"e": "-0.1"}),
     [key("e"), IN_PATCH, NUMBER, "[0, 1]", "'-0.1'"]),
    ("e above 1", settings({"e": "1.3"}),
     [key("e"), IN_PATCH, NUMBER, "[0, 1]", "'1.3'"]),
    ("e not a number", settings({"e": "abc"}),
     [key("e"), IN_PATCH, NUMBER, "[0, 1]", "'abc'"]),
    ("e two numbers", settings({"e": "0.8 0.9"}),
     [key("e"), IN_PATCH, NUMBER, "[0, 1]", "'0.8 0.9'"]),
    ("e missing", settings({"e": None}),
     [key("e"), IN_PATCH, NUMBER, "[0, 1]", "missing"]),
    ("mu0 negative", settings({"mu0": "-0.4"}),
     [key("mu0"), IN_PATCH, NUMBER, "[0, inf]", "'-0.4'"]),
    ("mu0 missing", settings({"mu0": None}),
     [key("mu0"), IN_PATCH, NUMBER, "[0, inf]", "missing"]),
    ("muD negative", settings({"muD": "-0.1"}),
     [key("muD"), IN_PATCH, NUMBER, "[0, 0.4]", "'-0.1'"]),
    # muD's upper bound is mu0's value
    ("muD above mu0", settings({"muD": "0.5"}),
     [key("muD"), IN_PATCH, NUMBER, "[0, 0.4]", "'0.5'"]),
    ("roughnessAngle above 45", settings({"roughnessAngle": "50"}),
     [key("roughnessAngle"), IN_PATCH, NUMBER, "[0, 45]", "'50'"]),
    ("roughnessAngle negative", settings({"roughnessAngle": "-1"}),
     [key("roughnessAngle"), IN_PATCH, NUMBER, "[0, 45]", "'-1'"]),
    ("roughnessAngle not a number", settings({"roughnessAngle": "eight"}),
     [key("roughnessAngle"), IN_PATCH, NUMBER, "[0, 45]", "'eight'"]),
    ("roughnessAngle missing", settings({"roughnessAngle": None}),
     [key("roughnessAngle"), IN_PATCH, "missing"]),
    # A table: the rule broken and the row that breaks it
    ("roughnessAngle table not increasing",
     settings({"roughnessAngle": "((2e-4 8) (1e-4 5))"}),
     [key("roughnessAngle"), IN_PATCH, "increasing", "row 2"]),
    ("roughnessAngle table angle out of range",
     settings({"roughnessAngle": "((1e-4 8) (2e-4 60))"}),
     [key("roughnessAngle"), IN_PATCH, "[0, 45]", "row 2"]),
    ("roughnessAngle table negative diameter",
     settings({"roughnessAngle": "((-1e-4 8) (2e-4 6))"}),
     [key("roughnessAngle"), IN_PATCH, "d >= 0", "row 1"]),
    ("roughnessAngle table malformed",
     settings({"roughnessAngle": "((1e-4 8) (2e-4))"}),
     [key("roughnessAngle"), IN_PATCH, "(d1 Delta1)"]),
    ("maxFacetCollisions zero", settings({"maxFacetCollisions": "0"}),
     [key("maxFacetCollisions"), IN_PATCH, INTEGER, "[1, 1000]", "'0'"]),
    ("maxFacetCollisions not an integer",
     settings({"maxFacetCollisions": "2.5"}),
     [key("maxFacetCollisions"), IN_PATCH, INTEGER, "[1, 1000]", "'2.5'"]),
    ("lateralTilt not a switch", settings({"lateralTilt": "maybe"}),
     [key("lateralTilt"), IN_PATCH, "true/false", "'maybe'"]),
    ("rebound e above 1",
     settings(outlet="outlet { type rebound; e 2; }"),
     [key("e"), IN_OUTLET, NUMBER, "[0, 1]", "'2'"]),
    ("rebound mu negative",
     settings(outlet="outlet { type rebound; mu -1; }"),
     [key("mu"), IN_OUTLET, NUMBER, "[0, 1]", "'-1'"]),
    # The patch list: the patches named, and what is wrong with them
    ("none on a wall", settings({"type": "none", "e": None, "mu0": None,
                                 "muD": None, "roughnessAngle": None}),
     [key("patches"), "roughWallInteractionCoeffs", "none", "lowerWall",
      "upperWall"]),
    ("patch not covered", settings(outlet=""),
     [key("patches"), "roughWallInteractionCoeffs", "no entry", "outlet"]),
    ("misspelt patch keyword", settings({"lateralTlit": "yes"}),
     [key("lateralTlit"), IN_PATCH, closest("lateralTilt")]),
    ("rebound keyword of rough", settings(outlet="outlet { type rebound; "
                                          "mu0 0.4; }"),
     [key("mu0"), IN_OUTLET, "rebound", closest("mu")]),
    ("patch setting at coefficient level", settings(coeffs="    e 0.8;\n"),
     [key("e"), "roughWallInteractionCoeffs", closest("patches")]),
    ("velocity name at coefficient level", settings(coeffs="    U U;\n"),
     [key("U"), "roughWallInteractionCoeffs", "writeToFile"]),
    ("patches missing", settings(patches=False),
     [key("patches"), "roughWallInteractionCoeffs", "missing"]),
    ("tokens after the patches list",
     settings().replace("    );\n", "    ) upperWall { type stick; };\n"),
     [key("patches"), "roughWallInteractionCoeffs", "after", "stick"]),
    ("patches entry a bad regular expression",
     settings().replace('"(lowerWall|upperWall)"', '"(lowerWall|upperWall"'),
     [key("patches"), "roughWallInteractionCoeffs", "(lowerWall|upperWall"]),
    ("patches entry without dictionary",
     settings(outlet="outlet escape;"),
     [key("patches"), "roughWallInteractionCoeffs", "outlet", "{"]),
    ("incidenceAngleBins zero",
     settings(coeffs="    incidenceAngleBins 0;\n"),
     [key("incidenceAngleBins"), "roughWallInteractionCoeffs", INTEGER,
      "[1, 900]", "'0'"]),
    ("incidenceAngleBins not an integer",
     settings(coeffs="    incidenceAngleBins 4.5;\n"),
     [key("incidenceAngleBins"), "roughWallInteractionCoeffs", INTEGER,
      "[1, 900]", "'4.5'"]),
]

#: Signs of a crash instead of a clean fatal error (a stack trace; not the
#: floating point trapping notes of the log headers, v1912's "trapFpe:
#: Floating point exception trapping enabled" and OpenFOAM-13's "sigFpe :
#: Enabling floating point exception trapping"); a process killed by a
#: signal (rc < 0) is one too
CRASH_SIGNS = ["sigSegv::sigHandler", "sigFpe::sigHandler",
               "Segmentation fault", "core dumped", "printStack"]


def check_bad_cases(case, platform, cases):
    """Run case once per (name, settings, texts) of cases: each must stop
    cleanly (rc != 0, no crash) with a FatalIOError whose message has the
    texts, the settings file and, for a Scope, the platform's form of it."""
    # The file named in the message: v1912 names an #include'd dictionary
    # after the including file, OpenFOAM-13 after the included one
    settings_file = "constant/roughWallSettings" if platform.foundation \
        else "constant/" + platform.properties
    for i, (name, text, expected) in enumerate(cases):
        case.write_settings(text)
        log = "log.bad%02d" % i
        rc, _ = case.solve(log, check_rc=False)
        out = case.log(log)
        # The fragments are looked for in the error message only
        error = out[out.rfind("FOAM FATAL IO ERROR"):] \
            if "FOAM FATAL IO ERROR" in out else ""
        expected = [e.texts(platform) if isinstance(e, Scope) else e
                    for e in [settings_file] + expected]
        missing = ([] if error else ["FOAM FATAL IO ERROR"]) + [
            e for e in expected if not (
                any(alt in error for alt in e) if isinstance(e, list)
                else e in error)]
        crashed = [s for s in CRASH_SIGNS if s in out] \
            + (["signal %d" % -rc] if rc < 0 else [])
        t.check(rc != 0 and not missing and not crashed,
                "%s: rc %d, %s%s" % (
                    name, rc,
                    "missing text %s" % missing if missing else
                    "error names %s" % ", ".join(
                        e if isinstance(e, str) else " or ".join(e)
                        for e in expected),
                    ", CRASH %s" % crashed if crashed else ""))


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p)
    return p.parse_args()


def test():
    args = parse_args()
    platform = fc.Platform(args.platform)
    case = t.wall_impact_case(platform, os.path.join(args.work, "case"),
                              args.cloud, two_d=True, parcels=10)
    case.set_control(endTime="0.001")
    case.mesh()

    # Control: the unmodified settings run
    case.write_settings(settings())
    rc, _ = case.solve("log.good", check_rc=False)
    t.check(rc == 0, "control: the valid settings run (rc %d)" % rc)

    # The settings' summary in the log: each keyword of the type with the
    # value ROUGH gives it or its default (lateralTilt false,
    # maxFacetCollisions 10; rebound's e 1 and mu 0), per mesh patch
    t.check_summary(case, "log.good", [
        "%s: rough: e = 0.8, mu0 = 0.4, muD = 0.4, roughnessAngle = 8 deg, "
        "lateralTilt = false, maxFacetCollisions = 10" % patch
        for patch in ("lowerWall", "upperWall")] + ["outlet: escape"])
    case.write_settings(settings(outlet="outlet { type rebound; mu 0.2; }"))
    rc, _ = case.solve("log.rebound", check_rc=False)
    t.check(rc == 0, "control: rebound on the outlet runs (rc %d)" % rc)
    t.check_summary(case, "log.rebound", ["outlet: rebound: e = 1, mu = 0.2"])
    # v1912 counts a hit on a patch that is not a wall as an escape before
    # the model sees it: a rebound outlet is warned of there, and only there
    kept = ("Patches 1(outlet) are not of type wall but keep the parcels "
            "that hit them")
    t.check((kept in case.log("log.rebound")) == (not platform.foundation),
            "control: the warning '%s...' %s" % (
                kept, "absent (Foundation)" if platform.foundation
                else "given (v1912)"))

    # Control: writeToFile false writes no statistics file
    stats_dir = case.file("postProcessing")
    t.check(os.path.isdir(stats_dir), "control: statistics file written")
    shutil.rmtree(stats_dir)
    case.write_settings(settings().replace(
        "roughWallInteractionCoeffs\n{\n",
        "roughWallInteractionCoeffs\n{\n    writeToFile false;\n"))
    rc, _ = case.solve("log.noFile", check_rc=False)
    t.check(rc == 0 and not os.path.exists(stats_dir),
            "control: writeToFile false runs and writes no statistics file")

    # Control: an entry whose patches all take an earlier entry (here a
    # name after a regular expression that covers it) runs with the
    # earlier one and is warned of
    case.write_settings(settings(outlet="lowerWall { type stick; }\n"
                                 "        lowerWal { type stick; }\n"
                                 "        outlet { type escape; }"))
    rc, _ = case.solve("log.neverApplied", check_rc=False)
    out = case.log("log.neverApplied")
    warning = ("The patches entry lowerWall is never applied: every patch "
               "it matches (lowerWall) takes an earlier entry")
    # An entry that matches no patch at all (a typo) is warned of too
    typo = "The patches entry lowerWal is never applied: no patch matches it"
    t.check(typo in out, "control: an entry matching no patch is warned of "
            "('%s')" % typo)
    t.check(rc == 0 and warning in out
            and "lowerWall: rough" in out and "stick" not in out.split(
                "Patch interactions:")[-1].split("outlet:")[0],
            "control: an entry never applied runs (rc %d) and warns '%s'"
            % (rc, warning))

    check_bad_cases(case, platform, CASES)

    # Control: without libs the model is unknown (troubleshooting symptom)
    case = t.wall_impact_case(platform, os.path.join(args.work, "case"),
                              args.cloud, two_d=True, parcels=10,
                              with_libs=False)
    case.set_control(endTime="0.001")
    case.mesh()
    rc, _ = case.solve("log.noLibs", check_rc=False)
    message = platform.unknown_model_message()
    t.check(rc != 0 and message in case.log("log.noLibs"),
            "without libs: '%s' (rc %d)" % (message, rc))


if __name__ == "__main__":
    t.main(test)
