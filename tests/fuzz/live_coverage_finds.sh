#!/usr/bin/env bash
# live_coverage_finds.sh VGC FUZZ_BUILD PLUGIN CLAUSE CAP SOURCE_DIR WORK MODE SEED...
# (libFuzzer build only) Fuzzing guided by the implementation's own
# coverage (docs/fuzzing.md "Coverage of the implementation"): PLUGIN is
# examples/c_host built with clang's inline 8-bit counters and vgc's
# coverage runtime, with its seeded fault SLOT_TAG_WRAP (the element created
# in a slot reused a fourth time is never listed: behind branches the
# reference has no counterpart of). For each SEED, `vgc fuzz differential
# --impl "exec:VGC serve --impl plugin:PLUGIN" --impl-coverage MODE` from
# the spec's cube alone, at most CAP s, must find CLAUSE, and its summary
# must say the node's coverage was seen (counters reached, functions
# entered). MODE guide is the done-when check (3 of 3 seeds within 300 s;
# not met, docs/fuzzing.md "Does it pay?"); observe runs the same campaign
# unguided, for the comparison.
set -u
vgc=$1 fbuild=$2 plugin=$3 clause=$4 cap=$5 src=$6 work=$7 mode=$8
shift 8
fail() { echo "live_coverage_finds: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work/src/corpora/fuzz/fuzz_differential"
cp "$src/corpora/fuzz/fuzz_differential/seed-cube.bin" "$work/src/corpora/fuzz/fuzz_differential/"
cp "$src/corpora/fuzz/fuzz_differential.dict" "$work/src/corpora/fuzz/"
for seed in "$@"; do
  rm -rf "$work/src/reports"
  "$vgc" fuzz differential --impl "exec:$vgc serve --impl plugin:$plugin" --impl-coverage "$mode" --time "$cap" \
    --stop-at-first --seed "$seed" --fuzz-build "$fbuild" --source-dir "$work/src" >"$work/out-$seed" 2>&1
  rc=$?
  tail -n 12 "$work/out-$seed"
  [ "$rc" -eq 1 ] || fail "seed $seed: expected exit 1 (a finding), got $rc"
  summary=$(ls "$work"/src/reports/fuzz/fuzz_differential/*/summary.json) || fail "seed $seed: no summary.json"
  python3 - "$summary" "$clause" "$cap" "$mode" "$seed" <<'PY' || fail "seed $seed: summary: see above"
import json, sys
s = json.load(open(sys.argv[1])); clause, cap, mode, seed = sys.argv[2], float(sys.argv[3]), sys.argv[4], sys.argv[5]
found = [c["clause"] for c in s["crashes"]]
assert clause in found, "clauses found: %s" % found
t = s["time_to_first_finding_s"]
assert t is not None and t <= cap, "time to first finding: %s" % t
ic = s["implementation_coverage"]
assert ic and ic["mode"] == mode and ic["seen"], "implementation coverage: %s" % ic
assert 0 < ic["counters_reached"] <= ic["counters"], ic
assert 0 < ic["functions_entered"] <= ic["function_entries"], ic
print("live_coverage_finds: seed %s, %s: %s found after %.1f s, %d executions, %.0f exec/s, %d of %d counters, "
      "%d of %d functions" % (seed, mode, clause, t, s["executions"], s["exec_per_s_mean"], ic["counters_reached"],
                              ic["counters"], ic["functions_entered"], ic["function_entries"]))
PY
done
