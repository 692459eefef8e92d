#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# make mutate: mutation testing of the RTL. How much would the tests catch?
#
#   make mutate N=200 SEED=1            the N mutants Yosys's `mutate -list N -seed SEED`
#                                       spreads over the design, each run against the kill suite
#   make mutate N=200 SEED=1 SAMPLE=12  a seeded sample of 12 of those N (CI), drawn from
#                                       those tests/mutate/survivors.txt does not give as
#                                       equivalent
#   JOBS=k                              mutants run in parallel (default: the cores)
#   MUTANTS="3 17"                      only these mutants of the list, again (after a new
#                                       test); the other results of the last run are kept
#   REPORT_ONLY=1                       the summary of the last run again (after editing
#                                       tests/mutate/survivors.txt)
#   NO_RECT=1                           leave the rectifier out of the mutant list: no mutant
#                                       in the cells under u_engine.u_rect, u_engine.u_rect_mark
#                                       and u_engine.u_rect_check (the mcadsw_rect* modules and
#                                       the FIFOs inside them); the N mutants are spread over the
#                                       rest. Default 0 (the whole design). An environment
#                                       variable: `make mutate NO_RECT=1` passes it on too.
#                                       (A few cells that Yosys's optimisation makes after
#                                       flattening carry no instance path and stay in the list.)
#
# Flow: Yosys reads the RTL as synthesis does (-DSYNTHESIS, -Irtl for the `include of
# rtl/mcadsw_assert.svh in rtl/rect/), elaborates mcadsw_top
# (the engine, its register block and AXI4 master: every RTL module), flattens it and
# applies every mutant of the list behind a select (`mutate -ctrl mutsel W k`: mutant
# k is active when mutsel == k, 0 is the design as written; the port becomes a variable
# set from the plusarg +mcadsw_mutant=K, below). Verilator builds that one model into
# the engine harness (sim/CMakeLists.txt, MCADSW_MUTANT_VERILOG), and the harness passes
# the environment variable MCADSW_MUTANT on as that plusarg. So N mutants
# cost one model build; the design with mutsel = 0 must pass each stage of the kill suite
# before mutants run it (the engine stage first, for every mutant; the later stages,
# and the design as written through them, only when a mutant passes the engine stage).
#
# Kill suite, in this order, stopping at the first failure (GoogleTest --gtest_fail_fast):
#   1. rtl_engine_test (tests/rtl/engine_test.cpp): crops of real pairs in every mode
#      (left / right / LR, raw / sub-pixel), D from 2 to DMAX, strides, back-to-back
#      frames, reset and start while busy, aborts, every configuration error code
#      (not its death test: the design is read for synthesis, without the RTL's
#      simulation assertions);
#   2. rtl_axi_test (tests/rtl/axi_test.cpp): AXI4 bursts, tiled input, response
#      errors, abort with bursts in flight, 4 KiB;
#   3. mcadsw_sim_random --cases 40 --seed 2026 --fail-fast: random sizes, D, modes,
#      strides, latencies, interrupts, each frame against the reference.
#   4. cycles, after each stage: the frames' cycle counts it printed (engine and AXI
#      test lines, random cases) against those of the design as written (its run, below): a
#      mutant that changes only timing changed the CYCLES counter a user reads
#      (the reference has no cycle model, so the design as written is the oracle
#      for timing, as make sim's cycle comparison is).
# A mutant is killed when a stage fails, crashes (an RTL assertion, a combinational
# loop the model cannot settle) or runs out of its time: TIMEOUT seconds a stage
# (default 300), or twice the slowest stage of the design as written when that is more
# (a loaded machine: CI runs this beside the synthesis, and the engine stage alone takes
# about 140 s on an idle one). The design as written gets 4 x TIMEOUT a stage. The
# harness's own cycle limits end a hung frame long before.
# The block tests (census, weight generator, cost aggregator, WTA, post, registers)
# verilate the blocks as written, so they cannot see a mutant of the flattened engine;
# they are not in the suite.
#
# Survivors: tests/mutate/survivors.txt lists survivors by key (the `mutate` command
# without -ctrl) with a kind and the reason: equivalent (cannot change any output; not
# counted in the score) or open (could, but no test shows it yet; counted as
# survived). A survivor in neither fails the run (exit 1).
# Output: build/mutate/summary.json (total, killed, survived, equivalent, open,
# unlisted, score = killed / (total - equivalent), per module counts, the survivors), results.tsv
# (one line a mutant: number, module, outcome, the test that killed it, seconds)
# and logs/ (each mutant's kill-suite output).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
n=${N:-200}
seed=${SEED:-1}
sample=${SAMPLE:-0}
jobs=${JOBS:-$(nproc)}
stage_timeout=${TIMEOUT:-300}
no_rect=${NO_RECT:-0}
build=${BUILD_DIR:-$root/build}
out=$build/mutate
listfile=$root/tests/mutate/survivors.txt
die() { echo "mutate: $*" >&2; exit 1; }

[[ "$n" =~ ^[0-9]+$ ]] && [ "$n" -ge 1 ] && [ "$n" -le 65535 ] || die "N must be 1 to 65535, not '$n'"
[[ "$seed" =~ ^[0-9]+$ ]] || die "SEED must be a number, not '$seed'"
[[ "$sample" =~ ^[0-9]+$ ]] && [ "$sample" -le "$n" ] || die "SAMPLE must be 0 (all) to N, not '$sample'"
[[ "$jobs" =~ ^[0-9]+$ ]] && [ "$jobs" -ge 1 ] || die "JOBS must be 1 or more, not '$jobs'"
[[ "$no_rect" =~ ^[01]$ ]] || die "NO_RECT must be 0 or 1, not '$no_rect'"
[ -f "$listfile" ] || die "no list of survivors at $listfile"
mkdir -p "$out"
start_all=$(date +%s)

if [ "${REPORT_ONLY:-0}" = 1 ]; then
  [ -d "$out/results" ] && [ -f "$out/mutants.tsv" ] || die "no results in $out: run make mutate first"
  elapsed=$(cat "$out/run_seconds" 2>/dev/null || echo 0)
  no_rect=$(cat "$out/no_rect" 2>/dev/null || echo 0)    # as the last run had it
else
  # 1. The mutant design (regenerated when the RTL, N, SEED, NO_RECT or Yosys change).
  mods=$(scripts/rtl_files.sh --no-pkg rtl | tr '\n' ' ')
  pkgs=" rtl/mcadsw_pkg.sv rtl/rect/mcadsw_rect_pkg.sv "    # packages: no instances
  width=1
  while [ $(( (1 << width) - 1 )) -lt "$n" ]; do width=$((width + 1)); done
  stamp=$( { cat rtl/mcadsw_pkg.sv rtl/mcadsw_assert.svh $mods; echo "$n $seed $width $no_rect"; yosys -V; } |
          sha1sum | cut -d' ' -f1)
  design=$out/mutants_n${n}_s${seed}.v
  [ "$no_rect" = 0 ] || design=$out/mutants_n${n}_s${seed}_norect.v
  # NO_RECT=1: the mutant list is drawn from every cell but those of the rectifier's
  # instances (flattened names $flatten\u_engine.\u_rect.* and u_engine.u_rect.*, the
  # same for u_rect_mark and u_rect_check).
  mut_sel=""
  if [ "$no_rect" = 1 ]; then
    for i in u_rect u_rect_mark u_rect_check; do
      mut_sel+=" c:\$flatten\\u_engine.\\$i.* c:u_engine.$i.*"
    done
    mut_sel="select -del$mut_sel;"
  fi
  if [ ! -f "$design" ] || [ "$(cat "$out/design.stamp" 2>/dev/null)" != "$stamp" ]; then
    echo "mutate: Yosys: elaborating mcadsw_top, $n mutants (seed $seed${mut_sel:+, not in the rectifier}) behind mutsel[$((width - 1)):0]"
    rm -f "$out/instances.txt" "$out/design.stamp"
    # Instance name -> module, for the per-module counts. The type exactly m (a
    # pattern t:*m* would also count the instances of every module whose name
    # contains m: mcadsw_rect those of all mcadsw_rect_*): the module itself, or a
    # parameterised copy, $paramod\m\PARAM=... or $paramod$<hash>\m.
    inst_cmds=""
    for f in $mods; do
      [[ "$pkgs" == *" $f "* ]] && continue
      m=$(basename "$f" .sv)
      inst_cmds+="tee -q -a $out/instances.txt log -- module $m; "
      inst_cmds+="tee -q -a $out/instances.txt select -list t:$m t:\$paramod\\$m\\* t:\$paramod\$*\\$m; "
    done
    t0=$(date +%s)
    yosys -q -l "$out/yosys.log" -p "read_verilog -sv -DSYNTHESIS -Irtl rtl/mcadsw_pkg.sv $mods
      hierarchy -check -top mcadsw_top
      $inst_cmds
      prep -flatten -top mcadsw_top
      $mut_sel
      mutate -list $n -seed $seed -ctrl mutsel $width 1 -o $out/list.ys
      select -clear
      script $out/list.ys
      opt_clean
      write_verilog -noattr $design.tmp" > /dev/null || die "Yosys failed (log: $out/yosys.log)"
    # mutsel as a port would be an input of the model, and Verilator re-evaluates the
    # logic that depends on inputs every time they change (3x slower): make it a
    # variable the model sets once from the plusarg +mcadsw_mutant=K (the harness
    # passes MCADSW_MUTANT on, sim/engine_bench.cpp).
    sed -e 's/, mutsel);$/);/' \
        -e "s/^  input \[$((width - 1)):0\] mutsel;\$/  reg [$((width - 1)):0] mutsel;\n  initial if (!\$value\$plusargs(\"mcadsw_mutant=%d\", mutsel)) mutsel = 0;/" \
        -e "/^  wire \[$((width - 1)):0\] mutsel;\$/d" "$design.tmp" > "$design"
    rm -f "$design.tmp"
    [ "$(grep -c 'mcadsw_mutant=' "$design")" = 1 ] && ! grep -q 'input .*mutsel' "$design" ||
      die "could not turn the mutsel port of $design into a plusarg"
    [ "$(grep -c '^mutate ' "$out/list.ys")" = "$n" ] || die "Yosys listed $(grep -c '^mutate ' "$out/list.ys") mutants, not $n"
    if [ "$no_rect" = 1 ] && grep -qE -- '-cell (\$flatten\\)?u_engine\.\\?u_rect(_mark|_check)?\.' "$out/list.ys"; then
      die "NO_RECT=1 but Yosys listed a mutant in the rectifier ($out/list.ys)"
    fi
    echo "$stamp" > "$out/design.stamp"
    echo "mutate: design written in $(( $(date +%s) - t0 )) s ($design)"
  fi

  # 2. The model and the kill suite's programs, at -O1 as for `make gls`: the
  # generated model of the flattened design compiles in about 30 s.
  cmake -S "$root" -B "$out/cmake" -G Ninja -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DMCADSW_MUTANT_VERILOG="$design" \
        -DMCADSW_BLOCK_BENCHES=none -DMCADSW_CORE_MODEL=OFF > "$out/cmake.log" 2>&1 ||
    { tail -20 "$out/cmake.log"; die "cmake configure failed (log: $out/cmake.log)"; }
  t0=$(date +%s)
  echo "mutate: building the mutant model and the kill suite (Verilator, $out/cmake)"
  cmake --build "$out/cmake" --target rtl_engine_test_mut rtl_axi_test_mut mcadsw_sim_random_mut \
    > "$out/build.log" 2>&1 || { tail -30 "$out/build.log"; die "build failed (log: $out/build.log)"; }
  echo "mutate: built in $(( $(date +%s) - t0 )) s"
  bin=$out/cmake/bin

  # 3. The kill suite on one mutant: prints "outcome<TAB>test".
  stages_list() {
    printf '%s\n' \
      "engine|$bin/rtl_engine_test_mut --gtest_fail_fast --gtest_brief=1 --gtest_filter=-*DeathTest*" \
      "axi|$bin/rtl_axi_test_mut --gtest_fail_fast --gtest_brief=1" \
      "random|$bin/mcadsw_sim_random_mut --cases 40 --seed 2026 --fail-fast"
  }
  # The cycle-count lines of one stage's section of a kill-suite log.
  stage_cycles() {
    awk -v st="$2" '/^== / { on = ($2 == st ":") ; next }
                    on && /^(case +[0-9]+ |[0-9]+x[0-9]+ D=[0-9]+: |sim-random: )/' "$1"
  }
  # kill_suite K LOG STAGE...: mutant K through those stages of the suite, in its order
  # (LOG starts afresh with the suite's first stage, else the earlier ones are in it).
  kill_suite() {
    local k=$1 log=$2 rc
    shift 2
    local -a stages
    mapfile -t stages < <(stages_list)
    [ "$1" != "${stages[0]%%|*}" ] || : > "$log"
    for s in "${stages[@]}"; do
      local name=${s%%|*} cmd=${s#*|}
      [[ " $* " == *" $name "* ]] || continue
      echo "== $name: $cmd" >> "$log"
      rc=0
      MCADSW_MUTANT=$k timeout -k 10 "$stage_timeout" $cmd >> "$log" 2>&1 || rc=$?
      if [ "$rc" != 0 ]; then
        local what
        if [ "$rc" = 124 ] || [ "$rc" = 137 ]; then what="$name:timeout"
        elif [ "$rc" -gt 128 ]; then what="$name:signal$((rc - 128))"
        else
          what=$(grep -m1 -oE '^\[  FAILED  \] [A-Za-z0-9_./]+|^case +[0-9]+ .*FAILED' "$log" |
                 sed -E 's/^\[  FAILED  \] //; s/^case +([0-9]+) .*/case \1/' || true)
          what="$name:${what:-exit$rc}"
        fi
        printf 'killed\t%s\n' "${what// /_}"
        return
      fi
      # 4. Timing: the stage printed each frame's cycle count (the CYCLES counter
      # a user reads); counts that differ from the design as written (the same
      # stage in the baseline's log) are a changed output too.
      if [ "$k" != 0 ]; then
        local diff_line
        diff_line=$(diff <(stage_cycles "$out/baseline.log" "$name") <(stage_cycles "$log" "$name") |
                    grep -m1 '^>' || true)
        if [ -n "$diff_line" ]; then
          echo "== cycles: differ from the design as written: ${diff_line#> }" >> "$log"
          local first=${diff_line#> }
          first=${first%%:*}
          printf 'killed\tcycles:%s\n' "$(cut -c1-40 <<< "${first// /_}")"
          return
        fi
      fi
    done
    printf 'survived\t-\n'
  }

  # The design as written through some stages of the suite (as many at once as there
  # are jobs; each section appended to baseline.log), every one must pass. Lazily: the
  # engine stage first, the later ones only when a mutant passes the stages before them
  # (a sample's mutants mostly fail the engine stage; the others cost ten minutes of a
  # loaded CI machine).
  : > "$out/baseline.log"
  baseline() {
    local t0 i s rc ts slowest
    t0=$(date +%s)
    local -a base_stages
    mapfile -t base_stages < <(stages_list)
    for i in "${!base_stages[@]}"; do
      s=${base_stages[$i]}
      [[ " $* " == *" ${s%%|*} "* ]] || continue
      { echo "== ${s%%|*}: ${s#*|}"; rc=0; ts=$(date +%s)
        MCADSW_MUTANT=0 timeout -k 10 "$((4 * stage_timeout))" ${s#*|} 2>&1 || rc=$?
        echo "== seconds $(( $(date +%s) - ts ))"; echo "== exit $rc"; } > "$out/baseline_$i.log" &
      while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
    done
    wait
    for i in "${!base_stages[@]}"; do
      [ -f "$out/baseline_$i.log" ] || continue
      cat "$out/baseline_$i.log" >> "$out/baseline.log"
      [ "$(tail -n 1 "$out/baseline_$i.log")" = '== exit 0' ] ||
        die "the unmutated model fails the kill suite's ${base_stages[$i]%%|*} stage (log: $out/baseline.log): fix this first"
      rm -f "$out/baseline_$i.log"
    done
    echo "mutate: the design as written (mutsel = 0) passes the kill suite's stages $* in $(( $(date +%s) - t0 )) s"
    slowest=$(awk '$1 == "==" && $2 == "seconds" { print $3 }' "$out/baseline.log" | sort -n | tail -n 1)
    slowest=${slowest:-0}
    if [ $((2 * slowest)) -gt "$stage_timeout" ]; then
      echo "mutate: its slowest stage took $slowest s: a mutant's stage may take $((2 * slowest)) s (not $stage_timeout)"
      stage_timeout=$((2 * slowest))
    fi
  }

  # Module of each mutant: the innermost instance on its cell's path.
  awk -v OFS='\t' '
    FNR == NR { if ($1 == "--" && $2 == "module") m = $3
                else { inst = $0; sub(/.*\//, "", inst); sub(/.*\./, "", inst); mod[inst] = m }
                next }
    /^mutate / { k++; cell = ""
      for (i = 1; i < NF; i++) if ($i == "-cell") cell = $(i + 1)
      who = "mcadsw_top"; np = split(cell, seg, ".")
      for (i = 1; i <= np; i++) { s = seg[i]; sub(/^\$flatten/, "", s); sub(/^\\/, "", s)
                                   if (s in mod) who = mod[s] }
      key = $0; sub(/ -ctrl [^ ]+ [0-9]+ [0-9]+/, "", key)
      print k, who, key }' "$out/instances.txt" "$out/list.ys" > "$out/mutants.tsv"

  # 4. Which mutants: all, a list, or a seeded sample (a linear congruential
  # generator in shell arithmetic: the same picks on every machine).
  if [ -n "${MUTANTS:-}" ]; then
    picks=$MUTANTS
  elif [ "$sample" -gt 0 ]; then
    # The sample skips the mutants the list already gives as equivalent (reviewed: they
    # survive by construction, and each costs the whole kill suite, about 10 minutes on
    # CI's loaded machine, to show nothing new); it draws further ones in their place.
    equiv=$(awk -F'\t' 'FNR == NR { if ($1 ~ /^mutate / && $2 == "equivalent") eq[$1] = 1; next }
                        ($3 in eq) { printf "%s ", $1 }' "$listfile" "$out/mutants.tsv")
    avail=$(( n - $(wc -w <<< "$equiv") ))
    [ "$sample" -le "$avail" ] || die "SAMPLE $sample: only $avail of the $n mutants are not listed as equivalent"
    picks=$(state=$seed; left=$sample; declare -A seen=()
            for k in $equiv; do seen[$k]=1; done
            while [ "$left" -gt 0 ]; do
              state=$(( (state * 1103515245 + 12345) % 2147483648 ))
              k=$(( state % n + 1 ))
              [ -n "${seen[$k]:-}" ] && continue
              seen[$k]=1; echo "$k"; left=$((left - 1))
            done | sort -n | tr '\n' ' ')
    [ -z "$equiv" ] || echo "mutate: the sample leaves out $(wc -w <<< "$equiv") mutants listed as equivalent ($equiv)"
  else
    picks=$(seq 1 "$n" | tr '\n' ' ')
  fi
  npicks=$(wc -w <<< "$picks")
  echo "$no_rect" > "$out/no_rect"

  # 5. Run them.
  echo "mutate: $npicks of $n mutants, $jobs at a time, kill suite: engine tests, AXI tests, 40 random frames, cycle counts"
  if [ -n "${MUTANTS:-}" ]; then     # re-run these, keep the other results of the last run
    for k in $picks; do rm -f "$out/results/$k" "$out/logs/mutant_$k.log"; done
  else
    rm -rf "$out/logs" "$out/results"
  fi
  mkdir -p "$out/logs" "$out/results"
  export -f kill_suite stages_list stage_cycles
  export bin out
  # run_stages PICKS STAGE...: each of PICKS through those stages (results/K: number,
  # outcome, the test that killed it, seconds, the earlier stages' seconds added).
  run_stages() {
    local p=$1
    shift
    export stage_timeout stages="$*" last
    for k in $p; do echo "$k"; done | xargs -P "$jobs" -I{} bash -c '
      k={}; t0=$(date +%s); before=0
      [ ! -f "$out/results/$k" ] || before=$(cut -f4 "$out/results/$k")
      r=$(kill_suite "$k" "$out/logs/mutant_$k.log" $stages)
      printf "%s\t%s\t%s\n" "$k" "$r" "$(( $(date +%s) - t0 + before ))" > "$out/results/$k"
      [ "${r%%	*}" = survived ] && [ "$stages" != "$last" ] ||
        printf "mutate: mutant %4s  %-8s %s\n" "$k" "${r%%	*}" "${r#*	}"'
  }
  tstart=$(date +%s)
  # The engine stage for every pick; then the AXI and random stages for those that
  # passed it (the suite's order, stopping at the first failure, as one run would).
  mapfile -t suite < <(stages_list)
  first=${suite[0]%%|*}
  rest=$(for s in "${suite[@]:1}"; do printf '%s ' "${s%%|*}"; done)
  rest=${rest% }
  last=$rest
  baseline "$first"
  run_stages "$picks" "$first"
  later=$(for k in $picks; do [ "$(cut -f2 "$out/results/$k")" = survived ] && printf '%s ' "$k"; done || true)
  if [ -n "$later" ]; then
    echo "mutate: $(wc -w <<< "$later") mutants pass the $first stage: the stages $rest"
    baseline $rest
    run_stages "$later" $rest
  fi
  elapsed=$(( $(date +%s) - tstart ))
  echo "$elapsed" > "$out/run_seconds"
fi

# 6. Summary (scripts/mutate_summary.py): survivors found in the committed list are
# equivalent or open; results.tsv, summary.json; exit 1 on an unlisted survivor.
cat "$out/results"/* | sort -n > "$out/outcomes.tsv"
[ "${REPORT_ONLY:-0}" = 1 ] || echo "mutate: $(( $(date +%s) - start_all )) s in all, $elapsed s running the design as written and the mutants"
rc=0
python3 "$root/scripts/mutate_summary.py" --out "$out" --list "$listfile" --list-name "${listfile#$root/}" \
  --n "$n" --seed "$seed" --sample "$sample" --seconds "$elapsed" --jobs "$jobs" --no-rect "$no_rect" || rc=$?
echo "mutate: $out/summary.json"
exit $rc
