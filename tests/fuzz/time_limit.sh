#!/usr/bin/env bash
# time_limit.sh VGC WORK_DIR
# `vgc fuzz --time` is a wall-clock limit: a stand-in for the libFuzzer
# binary that never stops (as fork mode did with many crashing inputs) is
# killed after --time (plus 5 s), with every process of its group, and the
# summary is still written, saying so. (The test's own CTest timeout is the
# bound: no timing assertion here.)
. "$(dirname "$0")/stand_in_lib.sh" time_limit "$@"
cat >"$work/fuzz/fuzz_stream" <<'SCRIPT'
#!/usr/bin/env bash
# A job that ignores -max_total_time, with a child of its own (a fork-mode job).
echo "#1	INITED cov: 10 ft: 20 corp: 1/9b exec/s: 1 rss: 30Mb"
sleep 300 &
echo $! >"$(dirname "$0")/child.pid"
sleep 300
SCRIPT
chmod +x "$work/fuzz/fuzz_stream"
out=$("$vgc" fuzz stream --time 2 --fuzz-build "$work" --source-dir "$work/src" 2>&1)
rc=$?
printf '%s\n' "$out" | tail -n 12
summary=$(ls "$work"/src/reports/fuzz/fuzz_stream/*/summary.json) || fail "no summary.json (exit $rc)"
python3 - "$summary" <<'PY' || exit 1
import json, sys
s = json.load(open(sys.argv[1]))
assert s["killed_at_deadline"] is True, "killed_at_deadline: %s" % s["killed_at_deadline"]
assert s["executions"] == 1, s["executions"]
PY
child=$(cat "$work/fuzz/child.pid")
sleep 1
# Gone, or a zombie: once killed, an orphan waits for PID 1 to reap it, and
# in a container PID 1 may take its time (kill -0 succeeds on a zombie).
state=$(sed 's/^.*) //' "/proc/$child/stat" 2>/dev/null | cut -c1)
case "$state" in
  "" | Z | X) ;;
  *) kill "$child"; fail "the stand-in's child $child survived (state $state)" ;;
esac
echo "time_limit: killed at the deadline, summary written, no process left"
