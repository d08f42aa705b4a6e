#!/usr/bin/env bash
# Packings in other units (docs/reliability.md, "Units"; issue 65), for ctest:
#   units.sh SBANALYZE PACKING WORK PYTHON
# 1. PACKING with every length times 1e-6, 1e-3, 1e3, 1e40 and 1e52 gives, for --compute all,
#    the results of PACKING: dimensionless and reduced values within 1e-12 relative, integers
#    (solid voxels, so phi_voxel; contacts; shells) bit for bit, lengths^k divided by factor^k;
# 2. at 1e-6 the --vdb grids are written (in the analyses' unit, recorded as length_unit);
# 3. `sbanalyze info` of the 1e-6 packing gives the unscaled contacts, Z and rattlers;
# 4. lengths times 1e-300 are refused up front, the file and the range named, nothing written.
set -euo pipefail
sbanalyze=$1 packing=$2 work=$3 python=$4
tests=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"
options=(--compute all --voxels 64 --pore-voxels 64 --bootstrap 20 --fft-plan estimate
         --fft-wisdom none --quiet)
"$sbanalyze" "$packing" "${options[@]}" --out reference.h5
for factor in 1e-6 1e-3 1e3 1e40 1e52; do
    "$python" "$tests/scale_packing.py" "$packing" "scaled-$factor.h5" "$factor"
    "$sbanalyze" "scaled-$factor.h5" "${options[@]}" --out "results-$factor.h5"
    echo -n "x $factor: "
    "$python" "$tests/compare_results.py" reference.h5 "results-$factor.h5" --rtol 1e-12 \
        --scale "$factor"
done
mkdir vdb
"$sbanalyze" scaled-1e-6.h5 --compute voxels,pores --voxels 64 --pore-voxels 64 --quiet \
    --vdb vdb --out vdb.h5
ls vdb
# (The smallest gap, -4e-16 D, is rounding: scaling the positions moves them by as much.)
info() { "$sbanalyze" info "$1" | grep -E "contacts \(gap|mean contacts|rattler fraction"; }
diff <(info "$packing") <(info scaled-1e-6.h5)
echo "info: the same contacts"
"$python" "$tests/scale_packing.py" "$packing" scaled-1e-300.h5 1e-300
status=0
"$sbanalyze" scaled-1e-300.h5 "${options[@]}" --out tiny.h5 2>tiny.log || status=$?
cat tiny.log
test "$status" = 1 && test ! -e tiny.h5 && echo "refused: exit 1, nothing written"
echo "units: ok"
