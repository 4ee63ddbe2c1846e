#!/usr/bin/env bash
# smoke.sh BINARY CORPORA_ROOT TARGET RUNS SEED WORK_DIR
# The deterministic fuzz smoke of `./vgc test` (docs/fuzzing.md "Smoke"):
# the libFuzzer binary BINARY (built by fuzz_clusterfuzzlite_build) runs
# exactly RUNS executions with -seed=SEED, starting from TARGET's committed
# corpus and fixed crashes (CORPORA_ROOT/TARGET, CORPORA_ROOT/TARGET-crashes)
# with its dictionary and the max_len of its ClusterFuzzLite options.
# A count and a seed, not a time: the same binary makes the same inputs in
# the same order on any machine, so a failure here reproduces with the
# command it prints. New inputs go to WORK_DIR/new (emptied first), never
# into the committed corpus. Fails on any finding, and when libFuzzer did not
# run all RUNS executions.
set -u
binary=$1 root=$2 target=$3 runs=$4 seed=$5 work=$6
fail() { echo "smoke $target: $*" >&2; exit 1; }
[ -x "$binary" ] || fail "no libFuzzer binary $binary (fuzz_clusterfuzzlite_build builds it)"
rm -rf "$work" && mkdir -p "$work/new"
case "$target" in
  fuzz_mesh_*) max_len=256 ;;  # as .clusterfuzzlite/build.sh's options
  *) max_len=1024 ;;
esac
args=(-runs="$runs" -seed="$seed" -max_len="$max_len" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1
      -artifact_prefix="$work/")
[ -f "$root/$target.dict" ] && args+=(-dict="$root/$target.dict")
dirs=("$work/new" "$root/$target")
[ -d "$root/$target-crashes" ] && dirs+=("$root/$target-crashes")
cmd="$binary ${args[*]} ${dirs[*]}"
echo "smoke $target: $cmd"
start=$(date +%s%N)
ASAN_OPTIONS=detect_leaks=0 "$binary" "${args[@]}" "${dirs[@]}" >"$work/fuzzer.log" 2>&1
rc=$?
ms=$(( ($(date +%s%N) - start) / 1000000 ))
if [ "$rc" -ne 0 ]; then
  grep -E "^(vgc-fuzz|fuzz_|==[0-9]+==ERROR|SUMMARY|artifact_prefix|Test unit written)" "$work/fuzzer.log" | head -20 >&2
  tail -5 "$work/fuzzer.log" >&2
  for f in "$work"/crash-* "$work"/timeout-* "$work"/oom-* "$work"/leak-*; do
    [ -f "$f" ] && echo "smoke $target: input $f (base64 $(base64 -w0 "$f")); replay: $binary $f" >&2
  done
  fail "libFuzzer exit $rc after $(grep -c '' "$work/fuzzer.log") log lines (seed $seed, $runs runs)"
fi
done_line=$(grep -E "^Done [0-9]+ runs" "$work/fuzzer.log" | tail -1)
executed=$(grep -E "^stat::number_of_executed_units: " "$work/fuzzer.log" | awk '{print $2}')
cov=$(grep -oE "cov: [0-9]+" "$work/fuzzer.log" | tail -1)
[ -n "$done_line" ] || fail "no 'Done N runs' line: libFuzzer did not finish its runs"
[ "${executed:-0}" -ge "$runs" ] || fail "$executed executions, expected $runs"
times >"$work/times"  # in this shell: its children's user and system time
cpu=$(tail -1 "$work/times")
echo "smoke $target: $done_line; $cov; $(ls "$work/new" | wc -l) new inputs; ${ms} ms wall; CPU (user system) $cpu"
