#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Another configuration: the reference, the RTL and the harness built
# for DMAX disparities, PAR a step, the ASIC or (FPGA = 1) the FPGA target, with or
# (RECT = 0) without the rectifier, in their own build directory
# (BUILD/dmax<DMAX>_par<PAR>[_fpga][_norect], as `make sim-build DMAX=<DMAX> PAR=<PAR>
# FPGA=<FPGA> RECT=<RECT>`), then
#   - on the FPGA target, the block benches of the blocks whose buffers it reshapes
#     (census, weight generator, cost aggregator: docs/blocks/fpga_target.md);
#   - the reference's tests (the fast kernels against the plain model for every D
#     up to DMAX, among others);
#   - the engine's tests (crops at D = DMAX with random memory timing, invalid
#     configurations: D = DMAX + 1 is code 3);
#   - mcadsw_sim on a Teddy crop at D = DMAX in every output mode, bit-exact;
#   - mcadsw_sim_random: random cases with D up to DMAX (none rectified without the rectifier;
#     its engine tests then check that RECT_CTRL.ENABLE is rejected, code 24).
#   tests/dmax/run.sh BUILD_DIR [DMAX] [RANDOM_CASES] [PAR] [FPGA] [RECT]
# It builds with as many jobs as the machine has cores, or MCADSW_DMAX_JOBS (ctest: 1).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
parent=${1:?usage: tests/dmax/run.sh BUILD_DIR [DMAX] [RANDOM_CASES] [PAR] [FPGA] [RECT]}
dmax=${2:-128}
cases=${3:-20}
par=${4:-1}
fpga=${5:-0}
rect=${6:-1}
case $fpga in
  0) suffix=; target=ASIC; fpga_opt=OFF; blocks=() ;;
  1) suffix=_fpga; target=FPGA; fpga_opt=ON; blocks=(rtl_census_test rtl_weight_gen_test rtl_cost_agg_test) ;;
  *) echo "dmax: FPGA='$fpga': 0 or 1" >&2; exit 2 ;;
esac
case $rect in
  1) rect_opt=ON; with="" ;;
  # Without the rectifier the blocks above are the same RTL: their benches ran with it.
  0) rect_opt=OFF; suffix=${suffix}_norect; with=", without the rectifier"; blocks=() ;;
  *) echo "dmax: RECT='$rect': 0 or 1" >&2; exit 2 ;;
esac
dir=$parent/dmax${dmax}_par$par$suffix
echo "dmax: configuring and building $dir (DMAX = $dmax, PAR = $par, $target target$with)"
# Only the models it runs (CMakeLists.txt, MCADSW_BLOCK_BENCHES): the same options as
# make sim-build's for this directory (Makefile), so neither reconfigures the other's.
benches=$(IFS=';'; echo "${blocks[*]#rtl_}" | sed 's/_test//g')
cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMCADSW_DMAX="$dmax" -DMCADSW_PAR="$par" \
  -DMCADSW_FPGA="$fpga_opt" -DMCADSW_RECT="$rect_opt" -DMCADSW_BLOCK_BENCHES="${benches:-none}" \
  -DMCADSW_CORE_MODEL=OFF > "$dir.configure.log" 2>&1 ||
  { tail -20 "$dir.configure.log"; echo "dmax: configure failed" >&2; exit 1; }
cmake --build "$dir" -j "${MCADSW_DMAX_JOBS:-$(nproc)}" --target ref_tests rtl_engine_test mcadsw_sim mcadsw_sim_random "${blocks[@]}" \
  > "$dir.build.log" 2>&1 ||
  { grep -E "error|Error" -A5 "$dir.build.log" | head -40; echo "dmax: build failed" >&2; exit 1; }
echo "dmax: reference tests"
"$dir/bin/ref_tests" --gtest_brief=1
for b in "${blocks[@]}"; do
  echo "dmax: $b"
  "$dir/bin/$b" --gtest_brief=1
done
echo "dmax: engine tests"
"$dir/bin/rtl_engine_test" --gtest_brief=1
left=$root/data/cif/teddy/left.png
right=$root/data/cif/teddy/right.png
for mode in "" "--subpixel" "--right" "--lr --subpixel -T 2" "--random-latency 5"; do
  # shellcheck disable=SC2086
  "$dir/bin/mcadsw_sim" "$left" "$right" -d "$dmax" --crop 100,100,75,39 --name "dmax${dmax}_par$par$suffix" $mode | tail -1 |
    tee "$dir.sim.log"
  grep -q "BIT-EXACT" "$dir.sim.log" || { echo "dmax: mcadsw_sim $mode at D = $dmax, PAR = $par, $target target failed" >&2; exit 1; }
done
echo "dmax: $cases random cases"
"$dir/bin/mcadsw_sim_random" --cases "$cases" --seed 18 | tail -1
