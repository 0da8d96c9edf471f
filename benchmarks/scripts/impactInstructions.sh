#!/bin/sh
# Instructions per wall hit in the core with e and muD tabulated against the
# facet impact angle, against constants (issue 31): impactHitLoop under
# callgrind at 5e4 and 1.5e5 hits, the difference over 1e5. 3-D, alpha
# U(0, 90 deg), Delta 8 deg, no lateral tilt, v1912's random source.
#   benchmarks/scripts/impactInstructions.sh build/benchmarks/impactHitLoop
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
set -eu
loop=${1:-build/benchmarks/impactHitLoop}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
count()
{
    valgrind --tool=callgrind --callgrind-out-file="$out" "$loop" "$1" "$2" 8 "$3" 2>&1 \
        | sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
echo "| coefficients | spin | instructions per hit |"
echo "|---|---|---|"
for c in constant table
do
    for s in 1 0
    do
        a=$(count $c $s 50000)
        b=$(count $c $s 150000)
        echo "| $c | $s | $(( (b - a)/100000 )) |"
    done
done
