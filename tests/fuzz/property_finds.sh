#!/usr/bin/env bash
# property_finds.sh PROPERTY_TARGET FAULT_PLUGIN FAULT INPUT VGC CLAUSE
# A property fuzz target, run on INPUT against the faulty plugin (fault FAULT,
# tests/conformance/faults), must stop with a finding naming CLAUSE, and the
# command file it prints must replay as an ordinary certify counterexample:
# `vgc replay FILE --impl plugin:...` exits 1 naming the same clause, and
# against the reference exits 0.
set -u
bin=$1 plugin=$2 fault=$3 input=$4 vgc=$5 clause=$6
fail() { echo "property_finds: $*" >&2; exit 1; }
out=$(VGC_FAULT="$fault" VGC_FUZZ_PLUGIN="$plugin" "$bin" "$input" 2>&1)
rc=$?
printf '%s\n' "$out" | tail -n 30
[ "$rc" -ne 0 ] || fail "no finding (exit 0) on $input"
finding=$(printf '%s\n' "$out" | grep -m1 '^vgc-fuzz: FINDING in ') || fail "exit $rc but no FINDING line"
printf '%s\n' "$finding" | grep -q -- ": $clause (" || fail "finding does not name $clause: $finding"
tmp=$(mktemp --suffix=.vgc)
trap 'rm -f "$tmp"' EXIT
printf '%s\n' "$out" | sed -n '/^----8<---- counterexample.vgc$/,/^----8<----$/p' | sed '1d;$d' >"$tmp"
[ -s "$tmp" ] || fail "no counterexample printed"
replay=$(VGC_FAULT="$fault" "$vgc" replay "$tmp" --impl "plugin:$plugin" 2>&1)
[ $? -eq 1 ] || fail "replay against the fault did not exit 1: $replay"
printf '%s\n' "$replay" | grep -q -- "$clause" || fail "replay does not name $clause: $replay"
"$vgc" replay "$tmp" --impl reference >/dev/null || fail "the counterexample does not pass against the reference"
echo "property_finds: $finding"
