#!/usr/bin/env bash
# live_baseline.sh FUZZ_DIFFERENTIAL VGC FAULT_PLUGIN INPUT WORK
# A known deviation of a live implementation (VGC_FUZZ_BASELINE, set by
# `vgc fuzz --baseline`) does not stop the target: the known-bad input of
# polygon-delete-ignored is a finding (POLY-DELETE-1) without the baseline
# and passes with POLY-DELETE-1 in it; a crash is a finding whatever the
# baseline says.
set -u
bin=$1 vgc=$2 plugin=$3 input=$4 work=$5
fail() { echo "live_baseline: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"
printf '# known\nPOLY-DELETE-1 kept on purpose in this test\nBONE-FOREST-1 also\n' >"$work/baseline.txt"
spec="exec:$vgc serve --impl plugin:$plugin"
VGC_FAULT=polygon-delete-ignored VGC_FUZZ_IMPL="$spec" "$bin" "$input" >"$work/without.log" 2>&1 &&
  fail "no finding without the baseline"
grep -q "FINDING in fuzz_differential: POLY-DELETE-1" "$work/without.log" || fail "without the baseline: $(tail -3 "$work/without.log")"
VGC_FAULT=polygon-delete-ignored VGC_FUZZ_IMPL="$spec" VGC_FUZZ_BASELINE="$work/baseline.txt" "$bin" "$input" \
  >"$work/with.log" 2>&1 || fail "with POLY-DELETE-1 in the baseline: $(grep FINDING "$work/with.log")"
VGC_FAULT=crash-on-self-parent VGC_FUZZ_IMPL="$spec" VGC_FUZZ_BASELINE="$work/baseline.txt" "$bin" \
  "$(dirname "$0")/data/bone_self_parent.bin" >"$work/crash.log" 2>&1 && fail "a crash in a baseline clause was passed over"
grep -q "BONE-FOREST-1 (IMPLEMENTATION-DEFINED, crash)" "$work/crash.log" || fail "crash: $(grep FINDING "$work/crash.log")"
echo "live_baseline: a baseline clause passed over, a crash still found"
