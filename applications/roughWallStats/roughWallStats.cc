// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Command-line tool: statistics of the restitution coefficients k_n, k_t,
// k_Omega (eq. (2.5)) against the incidence angle, by quadrature or Monte
// Carlo, or the pdf of one coefficient at one angle (eq. (2.8) as corrected)
// next to its Monte Carlo histogram; optional plot through matplotlib.
// Usage: roughWallStats --help; documentation: docs/roughWallStats.md.

#include "commandLine.hh"
#include "coefficientDistribution.hh"
#include "monteCarloStatistics.hh"
#include "profileFile.hpp"
#include "profileStatistics.hh"
#include "quadratureStatistics.hh"
#include "tables.hh"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits.h>
#include <memory>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <exception>
#include <mutex>
#include <thread>
#include <tuple>
#include <unistd.h>

extern char** environ;

using namespace roughWallStats;

namespace
{

constexpr int usageExitCode = 2;

//- Where the plot script is: next to the executable (bin/ after install, the
//  build folder before), else in the source tree
std::string plotScript()
{
    char path[PATH_MAX];
    const ssize_t length = readlink("/proc/self/exe", path, sizeof path - 1);
    if (length > 0)
    {
        path[length] = '\0';
        std::string dir(path);
        dir = dir.substr(0, dir.rfind('/'));
        const std::string script = dir + "/plotRoughWallStats.py";
        if (access(script.c_str(), R_OK) == 0)
        {
            return script;
        }
    }
    return ROUGHWALLSTATS_SOURCE_DIR "/plotRoughWallStats.py";
}

std::string modelLabel(const Options& o)
{
    std::ostringstream label;
    const ImpactDependence& f = o.model.impact;
    label << "Delta = " << o.DeltaDeg << " deg, e = ";
    if (f.e) label << "e(" << roughWall::name(f.eArgument) << ")"; else label << o.model.material.e;
    label << ", mu0 = ";
    if (f.mu0) label << "mu0(angle)"; else label << o.model.material.mu0;
    label << ", muD = ";
    if (f.muD) label << "muD(angle)"; else label << o.model.material.muD;
    label << ", A_Omega = " << o.model.AOmega;
    if (o.monteCarlo.recollide) label << ", recollide";
    if (o.monteCarlo.lateral) label << ", lateral tilt";
    return label.str();
}

//- Run python3 plotRoughWallStats.py; true on success
bool plot(const std::string& kind, const std::string& csv, const Options& o)
{
    const std::string python = "/usr/bin/python3";
    const std::string script = plotScript();
    const std::string label = kind == "delta" ? o.plotLabel : modelLabel(o);
    std::vector<std::string> args{python, script, kind, csv, "--output", o.plotFile, "--labels", label};
    if (kind == "pdf")
    {
        std::ostringstream alpha;
        alpha << o.alphaDeg[0];
        args.insert(args.end(), {"--quantity", name(o.pdfOf), "--alpha", alpha.str()});
    }
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    pid_t pid;
    if (posix_spawn(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    {
        std::cerr << "roughWallStats: cannot run " << python << " for --plot\n";
        return false;
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    {
        std::cerr << "roughWallStats: plotting with " << script << " failed (needs "
                  << "python3-matplotlib)\n";
        return false;
    }
    return true;
}

//- Write the table to --output or stdout, and plot it; the exit code
int writeAndPlot
(
    const Options& o,
    const std::string& kind,
    const std::function<void(std::ostream&)>& write
)
{
    std::string csv = o.outputFile;
    bool temporary = false;
    if (!o.outputFile.empty())
    {
        std::ofstream file(o.outputFile);
        write(file);
        file.close();
        if (!file)
        {
            std::cerr << "roughWallStats: cannot write --output " << o.outputFile << '\n';
            return 1;
        }
    }
    else
    {
        write(std::cout);
        std::cout.flush();
        if (!o.plotFile.empty())
        {
            // In the system's temporary folder ($TMPDIR, else /tmp)
            std::string name =
                (std::filesystem::temp_directory_path()/"roughWallStats-XXXXXX").string();
            const int fd = mkstemp(name.data());
            if (fd < 0)
            {
                std::cerr << "roughWallStats: cannot create a temporary file for --plot\n";
                return 1;
            }
            close(fd);
            csv = name;
            temporary = true;
            std::ofstream file(csv);
            write(file);
        }
    }
    int code = 0;
    if (!o.plotFile.empty() && !plot(kind, csv, o))
    {
        code = 1;
    }
    if (temporary)
    {
        std::remove(csv.c_str());
    }
    return code;
}

int runStatistics(const Options& o)
{
    std::vector<Statistics> rows(o.alphaDeg.size());
    std::atomic<std::size_t> next{0};
    // An error in a thread (a coefficient function out of its bounds) is
    // passed on to main, which reports it
    std::mutex errorMutex;
    std::exception_ptr error;
    const auto work = [&]()
    {
        try
        {
            for (std::size_t i; (i = next++) < rows.size();)
            {
                const Incidence incidence = Incidence::fromDegrees(o.alphaDeg[i]);
                rows[i] = o.method == Method::quadrature
                    ? quadratureStatistics(o.model, incidence, o.quadrature)
                    : monteCarloStatistics(o.model, incidence, o.monteCarlo);
            }
        }
        catch (...)
        {
            const std::lock_guard<std::mutex> lock(errorMutex);
            if (!error) error = std::current_exception();
            next = rows.size();
        }
    };
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t threads = std::min<std::size_t>
    (
        rows.size(), o.threads > 0 ? static_cast<unsigned>(o.threads) : cores
    );
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (error)
    {
        std::rethrow_exception(error);
    }

    bool normalIncidence = false;
    for (const Statistics& s : rows)
    {
        if (!s.converged)
        {
            std::cerr << "roughWallStats: warning: quadrature at alpha = " << s.alphaDeg
                      << " deg did not reach --tolerance (estimated relative error "
                      << s.errorEstimate << ")\n";
        }
        normalIncidence = normalIncidence || !s.tangentialDefined;
    }
    if (normalIncidence)
    {
        std::cerr << "roughWallStats: note: k_t and k_Omega are undefined at alpha = 90 deg "
                     "(V'_x = 0): their fields are empty\n";
    }

    TableLayout layout;
    layout.monteCarlo = o.method == Method::montecarlo;
    layout.recollide = o.monteCarlo.recollide;
    layout.digits = o.digits;
    return writeAndPlot(o, "stats", [&](std::ostream& os) { writeStatisticsTable(os, rows, layout); });
}

//- The Delta(d) table of the wall's profile (--d)
int runEnvelope(const Options& options)
{
    Options o = options;
    EnvelopeResult result;
    try
    {
        result = envelopeStatistics(o.envelopeSettings);
    }
    catch (const roughWall::ProfileFileError& error)
    {
        std::cerr << "roughWallStats: error: --profile " << error.what() << '\n';
        return usageExitCode;
    }
    std::cerr << "roughWallStats: " << result.description << '\n';
    std::ostringstream label;
    label.precision(4);
    label << (o.envelopeSettings.profileFile.empty() ? "synthetic Gaussian, " : "profile, ")
          << "Rq = " << result.Rq*1e6 << " um, RSm = " << result.RSm*1e6 << " um";
    o.plotLabel = label.str();
    return writeAndPlot(o, "delta", [&](std::ostream& os)
    {
        writeEnvelopeTable(os, result, o.digits);
    });
}

int runPdf(const Options& o)
{
    const Incidence incidence = Incidence::fromDegrees(o.alphaDeg[0]);
    // The change of variables is of one in-plane facet collision
    const bool withDensity = !o.monteCarlo.recollide && !o.monteCarlo.lateral;

    std::unique_ptr<CoefficientDistribution> distribution;
    if (withDensity)
    {
        distribution = std::make_unique<CoefficientDistribution>(o.model, incidence, o.pdfOf);
    }

    double lo = o.rangeLo, hi = o.rangeHi;
    if (!o.rangeGiven)
    {
        if (distribution)
        {
            std::tie(lo, hi) = distribution->essentialRange(1e-4);
        }
        else
        {
            // From a pilot sample: the 1e-4 and 1 - 1e-4 quantiles
            MonteCarloSettings pilot = o.monteCarlo;
            pilot.samples = 100000;
            pilot.seed = o.monteCarlo.seed ^ 0x9e3779b97f4a7c15ULL;
            const WallHitSampler sample(o.model, incidence, pilot);
            Uniform01 uniform01(pilot.seed, incidence.degrees);
            std::vector<double> k(pilot.samples);
            for (double& kv : k)
            {
                kv = select(coefficientsOf(sample(uniform01).rebound, incidence), o.pdfOf);
            }
            std::sort(k.begin(), k.end());
            lo = k[10];
            hi = k[k.size() - 11];
            if (!(hi > lo)) { lo -= 0.5; hi += 0.5; }
        }
    }

    std::vector<double> edges(o.bins + 1);
    for (int i = 0; i <= o.bins; ++i)
    {
        edges[i] = i == o.bins ? hi : lo + (hi - lo)*i/o.bins;
    }
    const Histogram histogram = sampleHistogram(o.model, incidence, o.pdfOf, edges, o.monteCarlo);

    std::vector<PdfBin> bins(o.bins);
    double inRange = 0;
    for (int i = 0; i < o.bins; ++i)
    {
        PdfBin& b = bins[i];
        b.lo = edges[i];
        b.hi = edges[i + 1];
        b.count = histogram.counts[i];
        if (distribution)
        {
            const double p = distribution->probability(b.lo, b.hi);
            inRange += p;
            b.pdfBin = p/(b.hi - b.lo);
            b.pdf = distribution->density(0.5*(b.lo + b.hi));
        }
    }

    std::ostringstream summary;
    summary << "roughWallStats: pdf of " << name(o.pdfOf) << " at alpha = " << incidence.degrees
            << " deg on [" << lo << ", " << hi << "): probability in range ";
    if (distribution)
    {
        summary << inRange << " (exact), ";
    }
    summary << static_cast<double>(histogram.samples - histogram.below - histogram.above)/histogram.samples
            << " (Monte Carlo, " << histogram.samples << " samples)";
    if (distribution)
    {
        for (const auto& atom : distribution->atoms())
        {
            summary << "; atom (left out of pdf, in pdf_bin) at k = " << atom.k
                    << " with probability " << atom.probability;
        }
    }
    std::cerr << summary.str() << '\n';

    return writeAndPlot(o, "pdf", [&](std::ostream& os)
    {
        writePdfTable(os, bins, histogram.samples, withDensity, o.digits);
    });
}

} // namespace

int main(int argc, char* argv[])
{
    Options options;
    try
    {
        options = parseCommandLine(argc, argv);
    }
    catch (const UsageError& error)
    {
        std::cerr << "roughWallStats: error: " << error.what() << '\n'
                  << "Try 'roughWallStats --help'.\n";
        return usageExitCode;
    }
    if (options.help)
    {
        std::cout << usage();
        return 0;
    }
    for (const std::string& note : options.notes)
    {
        std::cerr << "roughWallStats: note: " << note << '\n';
    }
    try
    {
        if (options.envelope)
        {
            return runEnvelope(options);
        }
        return options.pdf ? runPdf(options) : runStatistics(options);
    }
    catch (const std::exception& error)
    {
        std::cerr << "roughWallStats: error: " << error.what() << '\n';
        return 1;
    }
}
