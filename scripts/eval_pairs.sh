#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Runs the reference CLI on the bundled pairs and prints the Middlebury "all"
# error (threshold 1) per pair and the average, one row per gamma.
#   scripts/eval_pairs.sh [-b BUILD_DIR] [-s middlebury|cif] [-g "GAMMA ..."] [-o OUT_DIR]
# middlebury: native size, D = 16/20/60/60.  cif: the 352x288 crops, D = 64.
# Default gamma: the one built into the CLI. Used by `make sim` and for the sweep
# documented in docs/algorithm.md (-g "6 8 10 ... 40").
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build; set_name=middlebury; gammas=(""); out=""
while getopts "b:s:g:o:" opt; do
  case $opt in
    b) build=$OPTARG ;; s) set_name=$OPTARG ;; g) read -ra gammas <<<"$OPTARG" ;; o) out=$OPTARG ;;
    *) echo "usage: $0 [-b BUILD] [-s middlebury|cif] [-g \"G ...\"] [-o OUT_DIR]" >&2; exit 2 ;;
  esac
done
bin=$build/bin/mcadsw
[ -x "$bin" ] || { echo "eval_pairs: $bin is not built (run: make build)" >&2; exit 1; }
case $set_name in
  middlebury) pairs=("tsukuba 16 16" "venus 20 8" "teddy 60 4" "cones 60 4") ;;
  cif)        pairs=("tsukuba 64 16" "venus 64 8" "teddy 64 4" "cones 64 4") ;;
  *) echo "eval_pairs: unknown set '$set_name' (middlebury or cif)" >&2; exit 2 ;;
esac
if [ -z "$out" ]; then out=$(mktemp -d); trap 'rm -rf "$out"' EXIT; else mkdir -p "$out"; fi
printf "| set | gamma | Tsukuba | Venus | Teddy | Cones | average |\n|---|---|---|---|---|---|---|\n"
for g in "${gammas[@]}"; do
  row="| $set_name | ${g:-default}"; sum=0
  for p in "${pairs[@]}"; do
    read -r name d scale <<<"$p"; dir=$root/data/$set_name/$name
    "$bin" match "$dir/left.png" "$dir/right.png" -d "$d" ${g:+--gamma "$g"} \
      -o "$out/${set_name}_$name.png" >/dev/null
    e=$("$bin" eval "$out/${set_name}_$name.png" "$dir/gt.png" --scale "$scale" --masks "$dir" |
        awk '$1=="all"{print $2}')
    row="$row | $e"; sum=$(awk -v a="$sum" -v b="$e" 'BEGIN{print a+b}')
  done
  printf "%s | %.2f |\n" "$row" "$(awk -v s="$sum" 'BEGIN{print s/4}')"
done
