#!/usr/bin/env bash
# live_campaign_finds.sh ROUTE VGC FUZZ_BUILD FAULT_PLUGIN FAULT CLAUSE SOURCE_DIR WORK
# (libFuzzer build only) The done-when check of fuzzing a live
# implementation: a real `vgc fuzz differential --impl exec:...|verse:...`
# campaign of at most 60 s, seed 1, starting from the spec's cube alone
# (it holds no trigger of the fault), against the faulty node
# (VGC_FAULT=FAULT) served over ROUTE on loopback, must find the fault
# named by CLAUSE; its summary says that the implementation's own coverage
# is not seen (vgc serve is not built with vgc's coverage runtime).
set -u
route=$1 vgc=$2 fbuild=$3 plugin=$4 fault=$5 clause=$6 src=$7 work=$8
fail() { echo "live_campaign_finds: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work/src/corpora/fuzz/fuzz_differential"
cp "$src/corpora/fuzz/fuzz_differential/seed-cube.bin" "$work/src/corpora/fuzz/fuzz_differential/"
cp "$src/corpora/fuzz/fuzz_differential.dict" "$work/src/corpora/fuzz/"
export VGC_FAULT=$fault
. "$(dirname "$0")/live_host_lib.sh"
live_spec "$route" "$vgc" "$plugin" "$work"
"$vgc" fuzz differential --impl "$spec" --time 60 --stop-at-first --seed 1 --fuzz-build "$fbuild" \
  --source-dir "$work/src" >"$work/out" 2>&1
rc=$?
tail -n 20 "$work/out"
[ "$rc" -eq 1 ] || fail "expected exit 1 (a finding), got $rc"
summary=$(ls "$work"/src/reports/fuzz/fuzz_differential/*/summary.json) || fail "no summary.json"
python3 - "$summary" "$clause" <<'PY' || fail "summary: see above"
import json, sys
s = json.load(open(sys.argv[1])); clause = sys.argv[2]
found = [c["clause"] for c in s["crashes"]]
assert clause in found, "clauses found: %s" % found
t = s["time_to_first_finding_s"]
assert t is not None and t <= 60, "time to first finding: %s" % t
# vgc serve is not built with the coverage runtime: the campaign says so (exec:),
# or that the wire route does not take it (verse:), and runs as before.
ic = s["implementation_coverage"]
assert ic is not None and not ic["seen"] and ic["counters_reached"] == 0, "implementation coverage: %s" % ic
assert ic["mode"] == ("guide" if s["implementation"].startswith("exec:") else "wire"), ic
md = open(sys.argv[1].replace("summary.json", "summary.md")).read()
assert "| implementation coverage | not seen: " in md, "summary.md does not say the coverage is not seen"
print("live_campaign_finds: %s found after %.1f s, %d executions, %.0f exec/s" % (clause, t, s["executions"], s["exec_per_s_mean"]))
PY
