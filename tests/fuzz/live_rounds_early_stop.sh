#!/usr/bin/env bash
# live_rounds_early_stop.sh VGC WORK_DIR
# A live implementation's campaign runs libFuzzer in rounds, restarted after
# each finding until --time is spent (fuzz/campaign/campaign.cpp,
# run_more_rounds). A round that stops at a finding before its first
# progress line (an input of the corpus's first pass failing: a live host's
# failure that depends on its history) did run, and the rounds go on; only a
# round that ran nothing and did not stop at a finding (it could not start)
# ends them. The stand-in for fuzz_differential: round 1 reports progress
# and stops at a finding (exit 77), round 2 stops at a finding (77) before
# any progress line, round 3 reports 500 executions and ends (exit 0).
# Before the fix the campaign stopped after round 2 ("could not start"):
# summary 7 executions, round 3 never run. Counts rounds and executions,
# never wall time.
. "$(dirname "$0")/stand_in_lib.sh" live_rounds_early_stop "$@"
cat >"$work/fuzz/fuzz_differential" <<'SCRIPT'
#!/usr/bin/env bash
last=""
for a in "$@"; do last=$a; done
[ -f "$last" ] && exit 0  # run on one input (a re-run of a saved input): nothing found
n=$(( $(cat "$(dirname "$0")/rounds" 2>/dev/null || echo 0) + 1 ))
echo "$n" >"$(dirname "$0")/rounds"
case $n in
  1) echo "#7	INITED cov: 10 ft: 20 corp: 1/9b exec/s: 1 rss: 30Mb"
     echo "==1== ERROR: libFuzzer: deadly signal"; exit 77 ;;
  2) echo "INFO: seed corpus: files: 27 min: 1b max: 90b total: 900b rss: 30Mb"
     echo "==2== ERROR: libFuzzer: deadly signal"; exit 77 ;;
  *) echo "#500	DONE   cov: 12 ft: 24 corp: 2/18b exec/s: 100 rss: 30Mb"; exit 0 ;;
esac
SCRIPT
chmod +x "$work/fuzz/fuzz_differential"
out=$("$vgc" fuzz differential --impl exec:/bin/cat --impl-coverage off --time 600 \
  --fuzz-build "$work" --source-dir "$work/src" 2>&1)
rc=$?
printf '%s\n' "$out" | tail -n 12
rounds=$(cat "$work/fuzz/rounds" 2>/dev/null || echo 0)
[ "$rounds" = 3 ] || fail "libFuzzer ran $rounds round(s), expected 3: a round that stopped at a finding before its first progress line ended the campaign (exit $rc)"
summary=$(ls "$work"/src/reports/fuzz/fuzz_differential/*/summary.json) || fail "no summary.json (exit $rc)"
python3 - "$summary" <<'PY' || exit 1
import json, sys
s = json.load(open(sys.argv[1]))
assert s["executions"] == 507, "executions %s, expected 7 + 0 + 500 over the three rounds" % s["executions"]
assert s["killed_at_deadline"] is False, "killed at the deadline"
PY
echo "live_rounds_early_stop: three rounds, the second stopped before its first progress line, 507 executions"
