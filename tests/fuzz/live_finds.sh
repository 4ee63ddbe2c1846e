#!/usr/bin/env bash
# live_finds.sh ROUTE FUZZ_DIFFERENTIAL VGC FAULT_PLUGIN FAULT INPUT EXPECTED WORK
# fuzz_differential against a live implementation (VGC_FUZZ_IMPL,
# fuzz/targets/live_implementation.h): ROUTE exec (`vgc serve` of the faulty node
# over the exec protocol) or verse (`vgc serve --verse` of it on loopback),
# the node's seeded fault VGC_FAULT=FAULT. On the known-bad INPUT the target
# must stop with a FINDING matching the extended regex EXPECTED, naming a
# clause; its printed counterexample must replay with `vgc replay FILE --impl
# SPEC` (a fresh implementation: a new process, a new session) to the same
# clause and status, and pass against the reference.
set -u
route=$1 bin=$2 vgc=$3 plugin=$4 fault=$5 input=$6 expected=$7 work=$8
fail() { echo "live_finds: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"
export VGC_FAULT=$fault
. "$(dirname "$0")/live_host_lib.sh"
live_spec "$route" "$vgc" "$plugin" "$work"
out=$(VGC_FUZZ_IMPL="$spec" VGC_FUZZ_TIMEOUT=2 timeout 60 "$bin" "$input" 2>&1)
rc=$?
printf '%s\n' "$out" | tail -n 20
[ "$rc" -ne 0 ] || fail "no finding (exit 0) on $input against $spec"
printf '%s\n' "$out" | grep -q "reference vs .*$( [ "$route" = verse ] && echo 'Verse host' || echo 'faulty')" ||
  fail "the target did not drive the $route implementation"
finding=$(printf '%s\n' "$out" | grep -m1 '^vgc-fuzz: FINDING in fuzz_differential: ') || fail "exit $rc but no FINDING line"
# The finding's message may go on over lines (an exec program's last stderr lines).
block=$(printf '%s\n' "$out" | sed -n '/^vgc-fuzz: FINDING in/,/^vgc-fuzz: the /p' | tr '\n' ' ')
printf '%s\n' "$block" | grep -Eq -- "$expected" || fail "finding does not match /$expected/: $block"
clause=$(printf '%s\n' "$finding" | sed -nE 's/^vgc-fuzz: FINDING in fuzz_differential: ([A-Z][A-Z0-9-]*-[0-9]+) \(.*/\1/p')
status=$(printf '%s\n' "$finding" | sed -nE 's/^[^(]*\([A-Z-]+, ([a-z-]+)\).*/\1/p')
[ -n "$clause" ] && [ -n "$status" ] || fail "the finding names no clause and status: $finding"
cex="$work/counterexample.vgc"
printf '%s\n' "$out" | sed -n '/^----8<---- counterexample.vgc$/,/^----8<----$/p' | sed '1d;$d' >"$cex"
[ -s "$cex" ] || fail "no counterexample printed"
if [ "$route" = verse ] && [ "$status" != fail ]; then
  live_spec verse "$vgc" "$plugin" "$work"  # the host is gone: a fresh one
fi
replay=$("$vgc" replay "$cex" --impl "$spec" --timeout 2 2>&1)
[ $? -eq 1 ] || fail "vgc replay --impl $spec did not exit 1: $replay"
printf '%s\n' "$replay" | grep -Eq -- "^$status( \(|.*) $clause " ||
  fail "vgc replay does not show $status $clause: $replay"
"$vgc" replay "$cex" --impl reference >/dev/null || fail "the counterexample does not pass against the reference"
echo "live_finds: $route: found and replayed on a fresh instance: $finding"
