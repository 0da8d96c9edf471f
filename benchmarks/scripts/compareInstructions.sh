#!/bin/sh
# Do two versions of the core compile the constant-coefficient wall hit to the
# same instructions? Builds benchmarks/core/hitLoop.cc (the plain loop of
# wall hits, constant e, mu0, muD) from the commit REV and from the working
# tree with the same compiler and flags as the CMake Release build, and
# compares the disassembled .text (instructions and addresses; symbol names,
# which carry template arguments, are dropped). Exit 0 when identical.
#   benchmarks/scripts/compareInstructions.sh [REV]     (default HEAD)
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
set -eu
rev=${1:-HEAD}
top=$(git rev-parse --show-toplevel)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/old"
git -C "$top" archive "$rev" src/roughWallCore benchmarks/core | tar -x -C "$work/old"
flags="-O3 -DNDEBUG -std=c++17 -I${EIGEN3_INCLUDE_DIR:-/usr/include/eigen3}"
${CXX:-g++} $flags -I"$work/old/src/roughWallCore" -I"$work/old/benchmarks/core" \
    "$work/old/benchmarks/core/hitLoop.cc" -o "$work/hitLoop.old"
${CXX:-g++} $flags -I"$top/src/roughWallCore" -I"$top/benchmarks/core" \
    "$top/benchmarks/core/hitLoop.cc" -o "$work/hitLoop.new"
for b in old new
do
    objdump -d --no-show-raw-insn "$work/hitLoop.$b" | tail -n +3 \
        | sed -E 's/<[^>]*>//g' | awk -F'\t' 'NF >= 2 {print $2" "$3}' > "$work/$b.s"
done
if cmp -s "$work/old.s" "$work/new.s"
then
    echo "identical: $(wc -l < "$work/new.s") instructions of hitLoop ($rev and the working tree)"
else
    echo "DIFFERENT: hitLoop of $rev and of the working tree"
    diff "$work/old.s" "$work/new.s" | head -20
    exit 1
fi
