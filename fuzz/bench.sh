#!/usr/bin/env bash
# fuzz/bench.sh SAN_BUILD NOSAN_BUILD [SECONDS [TARGET...]]  — exec/s of every
# fuzz target (or the TARGETs named) on one core (taskset -c 0), with
# sanitizers (SAN_BUILD: -DVGC_FUZZ=ON) and without (NOSAN_BUILD:
# -DVGC_FUZZ=ON -DVGC_FUZZ_SANITIZERS=none; "-" skips it).
# Each run: libFuzzer, seed 1, for SECONDS (default 30; -max_total_time)
# starting from a fresh copy of the target's seed corpus, with its
# dictionary. Reports the executions (libFuzzer's final stats), libFuzzer's
# own exec/s (wall clock) and executions per CPU-second (user + sys time of
# the process), which is the fair figure on a shared machine.
# Not a test: numbers depend on the machine. docs/fuzzing.md records them.
set -u
san=$1 nosan=$2 seconds=${3:-30}
shift 3 2>/dev/null || shift $#
root="$(cd "$(dirname "$0")/.." && pwd)"
printf '%-24s %-10s %10s %12s %14s\n' target build runs "exec/s(wall)" "exec/cpu-s"
# Every target the build lists (fuzz/fuzz_targets.txt), else the first three.
targets="fuzz_stream fuzz_text fuzz_differential"
[ -f "$san/fuzz/fuzz_targets.txt" ] && targets=$(cat "$san/fuzz/fuzz_targets.txt")
[ $# -gt 0 ] && targets="$*"
printf 'load before: %s\n' "$(uptime)" >&2
printf 'targets: %s\n' "$targets" >&2
for t in $targets; do
  for b in "$san" "$nosan"; do
    [ "$b" = "-" ] && continue
    label=$([ "$b" = "$san" ] && echo asan+ubsan || echo none)
    work=$(mktemp -d)
    cp "$root/corpora/fuzz/$t"/* "$work/" 2>/dev/null
    opts=(-seed=1 -max_total_time="$seconds" -print_final_stats=1)
    [ -f "$root/corpora/fuzz/$t.dict" ] && opts+=(-dict="$root/corpora/fuzz/$t.dict")
    case "$t" in fuzz_mesh_*) opts+=(-max_len=256) ;; *) opts+=(-max_len=1024) ;; esac
    out=$( { /usr/bin/time -f "CPU %U %S" taskset -c 0 "$b/fuzz/$t" "${opts[@]}" "$work" ; } 2>&1 )
    wall=$(printf '%s\n' "$out" | grep -o 'exec/s: [0-9]*' | tail -1 | cut -d' ' -f2)
    cpu=$(printf '%s\n' "$out" | awk '/^CPU /{print $2 + $3}')
    runs=$(printf '%s\n' "$out" | awk '/stat::number_of_executed_units:/{print $2}' | tail -1)
    rate=$(awk -v r="${runs:-0}" -v c="$cpu" 'BEGIN{ if (c > 0) printf "%.0f", r / c; else print "?" }')
    printf '%-24s %-10s %10s %12s %14s\n' "$t" "$label" "${runs:-?}" "${wall:-?}" "$rate"
    rm -rf "$work"
  done
done
printf 'load after: %s\n' "$(uptime)" >&2
