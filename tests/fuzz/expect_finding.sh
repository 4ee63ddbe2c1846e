#!/usr/bin/env bash
# expect_finding.sh FUZZ_BINARY PLUGIN INPUT VGC EXPECTED
# Runs the differential target on INPUT against PLUGIN and passes when it
# stops with a finding whose message matches the extended regex EXPECTED and
# whose printed counterexample runs under `VGC apply`; when the finding names
# a clause ("CLAUSE (LEVEL, status): ..."), `VGC replay FILE --impl
# plugin:PLUGIN` must exit 1 naming the same clause, and pass against the
# reference.
set -u
bin=$1 plugin=$2 input=$3 vgc=$4 expected=$5
fail() { echo "expect_finding: $*" >&2; exit 1; }
out=$(VGC_FUZZ_PLUGIN="$plugin" "$bin" "$input" 2>&1)
rc=$?
printf '%s\n' "$out" | tail -n 40
[ "$rc" -ne 0 ] || fail "no finding (exit 0) on $input"
finding=$(printf '%s\n' "$out" | grep -m1 '^vgc-fuzz: FINDING in fuzz_differential: ') ||
  fail "exit $rc but no FINDING line"
printf '%s\n' "$finding" | grep -Eq -- "$expected" || fail "finding does not match /$expected/: $finding"
tmp=$(mktemp --suffix=.vgc)
trap 'rm -f "$tmp"' EXIT
printf '%s\n' "$out" | sed -n '/^----8<---- counterexample.vgc$/,/^----8<----$/p' | sed '1d;$d' >"$tmp"
[ -s "$tmp" ] || fail "no counterexample printed"
"$vgc" apply "$tmp" >/dev/null || fail "the counterexample does not run under vgc apply"
clause=$(printf '%s\n' "$finding" | sed -nE 's/^vgc-fuzz: FINDING in fuzz_differential: ([A-Z][A-Z0-9-]*-[0-9]+) \(.*/\1/p')
if [ -n "$clause" ]; then
  replay=$("$vgc" replay "$tmp" --impl "plugin:$plugin" 2>&1)
  [ $? -eq 1 ] || fail "vgc replay against the plugin did not exit 1: $replay"
  printf '%s\n' "$replay" | grep -q -- "$clause" || fail "vgc replay does not name $clause: $replay"
  "$vgc" replay "$tmp" --impl reference >/dev/null || fail "the counterexample does not pass against the reference"
fi
echo "expect_finding: found as expected: $finding"
