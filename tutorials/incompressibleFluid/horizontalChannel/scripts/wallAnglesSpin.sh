#!/bin/bash
# Writes results/wallAnglesSpin.txt: the model's k_n, k_t at 35 deg against
# the incident spin ratio, at the steel wall's Delta for 195 um beads.
cd "${0%/*}/.." || exit 1
stats="${ROUGHWALL_ROOT:-../../..}/bin/roughWallStats"
{
echo "# The rough-wall model's k_n, k_t at 35 deg incidence against the incident"
echo "# spin ratio A_Omega = r Omega_z / V'_x (Omega_z along t x N), at the steel"
echo "# wall's Delta for 195 um beads (results/summary.csv, roughnessAngle), e 0.8,"
echo "# mu0 = muD = 0.4, sideways tilt, the full operator (README, section"
echo "# \"k_n and k_t against the incidence angle\")."
echo "# Made by scripts/wallAnglesSpin.sh at commit $(git rev-parse --short HEAD)."
for A in -2 -1 -0.5 0 0.5 1 2
do
    echo "\$ roughWallStats --Delta 7.0203 --alpha 35 --method montecarlo --recollide --lateral --samples 100000 --spin $A"
    "$stats" --Delta 7.0203 --alpha 35 --method montecarlo --recollide --lateral \
        --samples 100000 --spin "$A" --digits 4 | cut -d, -f1,2,5,14,17
done
} > results/wallAnglesSpin.txt
