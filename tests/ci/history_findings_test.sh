#!/usr/bin/env bash
# history_findings_test.sh VGC FAULT_PLUGIN — a crash is reported against a
# clause only when its counterexample crashes a fresh instance (issue 19,
# item 1). history_proxy.py in front of the reference crashes after every
# 20 commands since it started, whatever they are: certify must report one
# crash, on STABLE-1, "depends on the implementation's history", whose
# counterexample crashes a fresh instance when replayed; no other clause
# may carry a finding. (It used to blame the clause of whatever command was
# running, several times, with counterexamples that replayed clean.) A
# crash that does reproduce (the fault plugin's crash-on-self-parent, behind
# the same proxy with no limit) is still reported on its own clause.
#
# history_findings_test.sh VGC FAULT_PLUGIN hang|garbage — the same for an
# implementation that stops answering (timeout) or answers garbage
# (protocol error, ACCEPT-1) after 20 commands since it started: one
# finding, on STABLE-1 or ACCEPT-1, "depends on the implementation's
# history", whose counterexample shows the same failure on a fresh instance.
#
# history_findings_test.sh VGC FAULT_PLUGIN reject — a wrong answer is
# confirmed like a crash (issue 31 item 2): after 100 commands since it
# started the implementation answers `rejected` to every command. One
# finding, STABLE-1 fail, "depends on the implementation's history"
# (wrong-answer), whose counterexample gets a wrong answer from a fresh
# instance; none on the clause of whatever command was running (it used to
# be 9 MUST fails on unrelated clauses that replayed as agreeing).
set -uo pipefail
[ $# -ge 2 ] || { echo "usage: $0 VGC FAULT_PLUGIN [hang|garbage]" >&2; exit 2; }
vgc=$1 plugin=$2 mode=${3:-crash}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_history.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 2
fail() { echo "history_findings ($mode): $*" >&2; exit 1; }

if [ "$mode" != crash ]; then
  case "$mode" in
    # 3 s per answer: the hang is forever, so any limit finds it; a second
    # was near what a loaded runner can take for a legitimate answer, and
    # starting the proxy has its own limit (--start-timeout, default 60 s).
    hang) clause=STABLE-1 status=timeout shows=timeout timeout=(--timeout 3) ;;
    garbage) clause=ACCEPT-1 status=fail shows=protocol-error timeout=() ;;
    reject) clause=STABLE-1 status=fail shows="^fail " timeout=() ;;
    *) echo "usage: $0 VGC FAULT_PLUGIN [hang|garbage|reject]" >&2; exit 2 ;;
  esac
  limit=20 cases=20
  [ "$mode" = reject ] && limit=100 cases=40
  # Every 21st command since a start hangs for the whole --timeout, all run
  # long: 5 cases a clause still end a case of another clause (the one the
  # finding must not be blamed on) and take 45 s instead of 115 s idle.
  [ "$mode" = hang ] && cases=5
  impl="exec:$here/history_proxy.py $vgc $mode $limit"
  "$vgc" certify --quiet --cases $cases --clauses 'LAYER-*' "${timeout[@]}" --impl "$impl" --reports R >out 2>err
  rc=$?
  [ $rc = 1 ] || { cat out err >&2; fail "exit $rc, expected 1 (a $clause $status)"; }
  python3 - R/latest/report.json "$clause" "$status" <<'PY' || { cat out >&2; fail "report.json is wrong (above)"; }
import json, sys
r = json.load(open(sys.argv[1]))
clause, status = sys.argv[2], sys.argv[3]
found = {c["id"]: c for c in r["clauses"] if c.get("counterexample")}
assert list(found) == [clause], "clauses with a finding: %s (expected only %s)" % (sorted(found), clause)
f = found[clause]
assert f["status"] == status, f["status"]
assert f["message"].startswith("depends on the implementation's history"), f["message"]
if status == "fail" and clause == "STABLE-1":
    assert "wrong-answer" in f["message"], f["message"]
PY
  cex=R/latest/counterexamples/$clause.vgc
  [ -s "$cex" ] || fail "no counterexample file for $clause"
  "$vgc" replay "$cex" "${timeout[@]}" --impl "$impl" >replay.out 2>&1
  grep -q "$shows" replay.out || { cat replay.out >&2; fail "the $clause counterexample does not show a $shows on a fresh instance"; }
  echo "history_findings ($mode): a history-dependent $shows is one $clause finding with a reproducer"
  exit 0
fi

impl="exec:$here/history_proxy.py $vgc crash 20"
"$vgc" certify --quiet --cases 20 --clauses 'LAYER-*' --impl "$impl" --reports R >out 2>err
rc=$?
[ $rc = 1 ] || { cat out err >&2; fail "exit $rc, expected 1 (a STABLE-1 crash)"; }
python3 - R/latest/report.json <<'PY' || { cat out >&2; fail "report.json is wrong (above)"; }
import json, sys
r = json.load(open(sys.argv[1]))
found = {c["id"]: c for c in r["clauses"] if c.get("counterexample")}
assert list(found) == ["STABLE-1"], "clauses with a finding: %s (expected only STABLE-1)" % sorted(found)
f = found["STABLE-1"]
assert f["status"] == "crash", f["status"]
msg = f["message"]
assert msg.startswith("depends on the implementation's history"), msg
PY
cex=R/latest/counterexamples/STABLE-1.vgc
[ -s "$cex" ] || fail "no counterexample file for STABLE-1"
"$vgc" replay "$cex" --impl "$impl" >replay.out 2>&1
grep -q "crash" replay.out || { cat replay.out >&2; fail "the STABLE-1 counterexample does not crash a fresh instance"; }

# A crash that reproduces stands on its own clause, as before.
VGC_FAULT=crash-on-self-parent "$vgc" certify --quiet --cases 50 --clauses 'BONE-*' \
  --impl "exec:$here/history_proxy.py $vgc crash 1000000 --impl plugin:$plugin" --reports S >out2 2>err2
grep -q "crash *BONE-FOREST-1" out2 || { cat out2 err2 >&2; fail "the reproducible crash is not reported on BONE-FOREST-1"; }
! grep -q "depends on the implementation's history" out2 || { cat out2 >&2; fail "a reproducible crash was called history-dependent"; }
echo "history_findings: a history-dependent crash is one STABLE-1 finding with a reproducer; a reproducible one stands on its clause"
