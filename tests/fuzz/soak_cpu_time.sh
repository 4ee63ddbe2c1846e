#!/usr/bin/env bash
# soak_cpu_time.sh VGC WORK_DIR
# `vgc fuzz --all --cpu-time` (docs/fuzzing.md "Soak"): a target's budget is
# CPU seconds, not wall-clock. The stand-in for fuzz_stream is a fork-mode
# libFuzzer that never stops by itself: its parent only waits, and its job
# (a child process) computes most of the time and sleeps the rest.
# The soak must stop it once the job has used the budget (1 CPU s, about
# 1.5 s of wall clock on an idle machine), counting the job's CPU while it
# runs, before the wall-clock cap (--wall-cap 30: 30 s, so that a loaded
# test machine does not reach it); without --cpu-time the same --time is
# a wall-clock limit.
. "$(dirname "$0")/stand_in_lib.sh" soak_cpu_time "$@"
mkdir -p "$work/src/corpora/fuzz/fuzz_stream"
echo "seed" >"$work/src/corpora/fuzz/fuzz_stream/seed-1"
cat >"$work/fuzz/fuzz_stream" <<'SCRIPT'
#!/usr/bin/env bash
for a in "$@"; do [ "$a" = -merge=1 ] && { echo "MERGE-OUTER: done"; exit 0; }; done
echo "#1: cov: 3 ft: 3 corp: 1 exec/s 1 oom/timeout/crash: 0/0/0 time: 0s job: 1 dft_time: 0"
(
  while :; do
    for ((i = 0; i < 100000; i++)); do :; done
    sleep 0.05
  done
) &
wait
SCRIPT
chmod +x "$work/fuzz/fuzz_stream"

soak() {
  "$vgc" fuzz --all --targets stream --time 1 --jobs 1 --fuzz-build "$work" --source-dir "$work/src" \
    --work-corpus "$work/wc" "$@" >"$work/soak.out" 2>"$work/soak.err"
}
check() {  # check MODE: the newest soak.json
  python3 - "$1" "$(ls -d "$work"/src/reports/fuzz/soak/* | sort | tail -1)/soak.json" <<'PY'
import json, sys
mode, path = sys.argv[1], sys.argv[2]
s = json.load(open(path))
r = s["rows"][0]
if mode == "cpu":
    assert s["cpu_time"] is True, s
    assert r["cpu_budget_spent"] and not r["killed_at_deadline"], r
    # The budget was spent by the job (the parent only waits): its CPU was read while it ran.
    assert 0.9 <= r["cpu_s"] < 2.5, r["cpu_s"]
    # Part of its time asleep: more wall than CPU; stopped by its budget, not the 30 s cap.
    assert r["cpu_s"] < r["wall_s"] < 30, (r["cpu_s"], r["wall_s"])
    md = open(path.replace("soak.json", "soak.md")).read()
    assert "CPU budget s" in md and "--cpu-time --wall-cap 30" in md, md
else:
    assert s["cpu_time"] is False and not r["cpu_budget_spent"], r
    assert r["wall_s"] < 1 + 15, r["wall_s"]
PY
}
soak --cpu-time --wall-cap 30 || { cat "$work/soak.err"; fail "--cpu-time soak: exit $?"; }
check cpu || { cat "$work/soak.err" "$work/soak.out"; fail "--cpu-time: see above"; }
soak || { cat "$work/soak.err"; fail "wall-clock soak: exit $?"; }
check wall || fail "wall-clock soak: see above"
# Only a soak takes a CPU budget, and a wall cap only with it.
"$vgc" fuzz --all --targets stream --time 1 --wall-cap 3 --fuzz-build "$work" --source-dir "$work/src" 2>"$work/cap.err" && fail "--wall-cap without --cpu-time was accepted"
grep -q -- "--wall-cap takes" "$work/cap.err" || fail "no clear error for --wall-cap without --cpu-time: $(cat "$work/cap.err")"
"$vgc" fuzz stream --cpu-time --time 1 --fuzz-build "$work" --source-dir "$work/src" 2>"$work/one.err" && fail "--cpu-time without --all was accepted"
grep -q -- "are for a soak" "$work/one.err" || fail "no clear error for --cpu-time without --all: $(cat "$work/one.err")"
echo "soak_cpu_time: a target stopped at 1 CPU s of its running job's time, wall-clock mode unchanged"
