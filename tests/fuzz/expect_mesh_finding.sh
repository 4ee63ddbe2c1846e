#!/usr/bin/env bash
# expect_mesh_finding.sh FUZZ_BINARY FAULT INPUT EXPECTED
# Runs a mesh fuzz target (replay build) on INPUT with the seeded reference
# fault VGC_FUZZ_MESH_FAULT=FAULT and passes when it stops with a finding
# whose message matches the extended regex EXPECTED and which prints the
# mesh; then runs the same input without the fault and requires no finding.
set -u
bin=$1 fault=$2 input=$3 expected=$4
fail() { echo "expect_mesh_finding: $*" >&2; exit 1; }
target=$(basename "$bin")
out=$(VGC_FUZZ_MESH_FAULT="$fault" "$bin" "$input" 2>&1)
rc=$?
printf '%s\n' "$out" | tail -n 40
[ "$rc" -ne 0 ] || fail "no finding (exit 0) on $input with fault $fault"
finding=$(printf '%s\n' "$out" | grep -m1 "^vgc-fuzz: FINDING in $target: ") || fail "exit $rc but no FINDING line"
printf '%s\n' "$finding" | grep -Eq -- "$expected" || fail "finding does not match /$expected/: $finding"
printf '%s\n' "$out" | sed -n '/^----8<---- mesh.txt$/,/^----8<----$/p' | grep -q '^f 0:' || fail "no mesh printed"
VGC_FUZZ_MESH_FAULT= "$bin" "$input" >/dev/null 2>&1 || fail "the input gives a finding without the fault too"
echo "expect_mesh_finding: found as expected: $finding"
