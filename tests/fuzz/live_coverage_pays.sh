#!/usr/bin/env bash
# live_coverage_pays.sh TARGET VGC PLUGIN CLAUSE RUNS SOURCE_DIR WORK GUIDED_MODE SEED...
# (libFuzzer build only) Does guidance by the implementation's own coverage
# pay (docs/fuzzing.md "Does it pay? The C example host")? PLUGIN is
# examples/c_host built with clang's inline 8-bit counters and vgc's
# coverage runtime, with a seeded fault only branches of the node lead to
# (COMBINE_FLUSH: the sixth write in a row to one vertex is lost; a
# branch per run length 1..5, none of them in the reference). For each SEED,
# TARGET (fuzz_differential) runs twice from the spec's cube alone, served
# over exec by `VGC serve`, with the same budget of RUNS executions
# (libFuzzer -runs, not seconds: the result does not depend on the
# machine's load):
#   guided    VGC_FUZZ_IMPL_COVERAGE=GUIDED_MODE (guide: the node's edges are
#             libFuzzer features) must find CLAUSE within RUNS;
#   unguided  VGC_FUZZ_IMPL_COVERAGE=observe (the same binary, its counters
#             counted, nothing steered) must not find it within RUNS, or
#             only later (more executions; the count of libFuzzer's last
#             progress line before the finding).
# GUIDED_MODE other than guide is for seeing the check fail (observe: the
# guided arm unguided).
set -u
target=$1 vgc=$2 plugin=$3 clause=$4 runs=$5 src=$6 work=$7 guided_mode=$8
shift 8
fail() { echo "live_coverage_pays: $*" >&2; exit 1; }
[ "$#" -gt 0 ] || fail "no seed given"
rm -rf "$work" && mkdir -p "$work"
# arm ROLE MODE SEED -> runs libFuzzer in WORK/ROLE-SEED; echoes "found N" (N: the last progress
# line's execution count before the finding, a lower bound) or "none N";
# exits 1 on anything else.
arm() {
  local mode=$2 seed=$3 d="$work/$1-$3"
  mkdir -p "$d/corpus" "$d/crashes"
  cp "$src/corpora/fuzz/fuzz_differential/seed-cube.bin" "$d/corpus/"
  VGC_FUZZ_IMPL="exec:$vgc serve --impl plugin:$plugin" VGC_FUZZ_IMPL_COVERAGE=$mode \
    "$target" -runs="$runs" -seed="$seed" -max_len=1024 -timeout=120 -detect_leaks=0 \
    -dict="$src/corpora/fuzz/fuzz_differential.dict" -artifact_prefix="$d/crashes/" "$d/corpus" >"$d/log" 2>&1
  local rc=$? last
  last=$(grep -o '^#[0-9][0-9]*' "$d/log" | tail -n 1 | tr -d '#')
  if [ "$rc" -eq 0 ]; then
    grep -q "^Done $runs runs" "$d/log" || fail "$mode, seed $seed: exit 0 without 'Done $runs runs' (see $d/log)"
    echo "none ${last:-0}"
  elif grep -q "FINDING in fuzz_differential: $clause " "$d/log"; then
    echo "found ${last:-0}"
  else
    fail "$mode, seed $seed: exit $rc without a $clause finding: $(grep -m1 -e FINDING -e ERROR "$d/log")"
  fi
}
for seed in "$@"; do
  # The two arms side by side (one core each): budgets are executions, so
  # what they share does not change the result.
  arm guided "$guided_mode" "$seed" >"$work/result-guided-$seed" &
  g_pid=$!
  arm unguided observe "$seed" >"$work/result-unguided-$seed" || exit 1
  wait "$g_pid" || exit 1
  read -r g_result g_runs <"$work/result-guided-$seed"
  read -r o_result o_runs <"$work/result-unguided-$seed"
  echo "live_coverage_pays: seed $seed: guided ($guided_mode): $g_result (#$g_runs); unguided (observe): $o_result (#$o_runs); budget $runs executions each"
  [ "$g_result" = found ] || fail "seed $seed: the guided campaign did not find $clause within $runs executions"
  [ "$o_result" = none ] || [ "$o_runs" -gt "$g_runs" ] ||
    fail "seed $seed: the unguided campaign found $clause as soon or sooner (#$o_runs; guided #$g_runs)"
done
