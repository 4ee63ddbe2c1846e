#!/usr/bin/env bash
# fuzz/bench.sh SAN_BUILD NOSAN_BUILD [SECONDS [TARGET...]]  — exec/s of every
# fuzz target (or the TARGETs named) on one core (taskset -c 0), with
# sanitizers (SAN_BUILD: -DVGC_FUZZ=ON) and without (NOSAN_BUILD:
# -DVGC_FUZZ=ON -DVGC_FUZZ_SANITIZERS=none; "-" skips it).
# Each target runs three times per build (libFuzzer seeds 1, 2 and 3), each
# for SECONDS (default 30; -max_total_time) starting from a fresh copy of
# the target's seed corpus, with its dictionary. Reports, per target and
# build, the median of the three runs of: the executions (libFuzzer's final
# stats), libFuzzer's own exec/s (wall clock) and the executions per
# CPU-second (user + sys time of the process), which is the fair figure on
# a shared machine; then the three exec/cpu-s figures themselves, so the
# spread shows. VGC_BENCH_RUNS=N runs N times instead (N odd).
# Not a test: numbers depend on the machine. docs/fuzzing.md records them.
set -u
san=$1 nosan=$2 seconds=${3:-30}
shift 3 2>/dev/null || shift $#
runs_per=${VGC_BENCH_RUNS:-3}
root="$(cd "$(dirname "$0")/.." && pwd)"
# Every target the build lists (fuzz/fuzz_targets.txt), else the first three.
targets="fuzz_stream fuzz_text fuzz_differential"
[ -f "$san/fuzz/fuzz_targets.txt" ] && targets=$(cat "$san/fuzz/fuzz_targets.txt")
[ $# -gt 0 ] && targets="$*"
printf 'load before: %s\n' "$(uptime)" >&2
printf 'targets: %s\n' "$targets" >&2
# The median of the numbers on stdin ("?" when there are none).
median() { sort -n | awk '{ v[NR] = $1 } END { if (NR == 0) print "?"; else print v[int((NR + 1) / 2)] }'; }
# One run: prints "EXECUTIONS WALL_EXEC_S EXEC_PER_CPU_S" ("?" for what it could not read).
one_run() {
  local t=$1 b=$2 seed=$3 work out wall cpu runs rate
  work=$(mktemp -d)
  cp "$root/corpora/fuzz/$t"/* "$work/" 2>/dev/null
  local opts=(-seed="$seed" -max_total_time="$seconds" -print_final_stats=1)
  [ -f "$root/corpora/fuzz/$t.dict" ] && opts+=(-dict="$root/corpora/fuzz/$t.dict")
  case "$t" in fuzz_mesh_*) opts+=(-max_len=256) ;; *) opts+=(-max_len=1024) ;; esac
  out=$( { /usr/bin/time -f "CPU %U %S" taskset -c 0 "$b/fuzz/$t" "${opts[@]}" "$work" ; } 2>&1 )
  rm -rf "$work"
  wall=$(printf '%s\n' "$out" | grep -o 'exec/s: [0-9]*' | tail -1 | cut -d' ' -f2)
  cpu=$(printf '%s\n' "$out" | awk '/^CPU /{print $2 + $3}')
  runs=$(printf '%s\n' "$out" | awk '/stat::number_of_executed_units:/{print $2}' | tail -1)
  rate=$(awk -v r="${runs:-0}" -v c="${cpu:-0}" 'BEGIN{ if (c > 0 && r > 0) printf "%.0f", r / c; else print "?" }')
  printf '%s %s %s\n' "${runs:-?}" "${wall:-?}" "$rate"
}
printf '%-24s %-10s %10s %12s %14s   %s\n' target build runs "exec/s(wall)" "exec/cpu-s" "(each run's exec/cpu-s)"
for t in $targets; do
  for b in "$san" "$nosan"; do
    [ "$b" = "-" ] && continue
    label=$([ "$b" = "$san" ] && echo asan+ubsan || echo none)
    results=""
    for seed in $(seq 1 "$runs_per"); do results+="$(one_run "$t" "$b" "$seed")"$'\n'; done
    col() { printf '%s' "$results" | awk -v k="$1" 'NF == 3 && $k != "?" { print $k }' | median; }
    each=$(printf '%s' "$results" | awk '{ printf "%s%s", (NR > 1 ? " " : ""), $3 }')
    printf '%-24s %-10s %10s %12s %14s   (%s)\n' "$t" "$label" "$(col 1)" "$(col 2)" "$(col 3)" "$each"
  done
done
printf 'load after: %s\n' "$(uptime)" >&2
