#!/usr/bin/env bash
# cancel_test.sh VGC FAULT_PLUGIN — a cancelled certify run writes what it
# found (issue 19, item 4). The implementation is history_proxy.py in front
# of the fault plugin (VGC_FAULT=base-layer-destroyable: LAYER-BASE-2 fails
# within the first cases) that hangs after 300 commands, with a 60 s
# timeout. SIGTERM once it hangs (and SIGINT in a second run) must end vgc
# within 3 s with exit 128 + the signal, after writing a whole run
# directory whose report.json says verdict "incomplete", cancelled_by the
# signal, and still lists LAYER-BASE-2; nothing vgc started may be left.
# Then SIGTERM followed at once by SIGINT exits at once (the second
# signal's message, exit 130). A cancelled run used to leave no report.
# Then (issue 31, item 6) report.json's exit_code is the process's and the
# stdout lines are not lost; a whole certification through exec:'vgc
# serve' is cancelled at ten moments, one while its implementation is still
# starting, one during a Verse login to a host that does not answer: each
# stops within 2 s and writes its report.
set -uo pipefail
[ $# -ge 2 ] || { echo "usage: $0 VGC FAULT_PLUGIN" >&2; exit 2; }
vgc=$1 plugin=$2
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_cancel.XXXXXX")
pids_file=$tmp/pids
cleanup() {
  [ -f "$pids_file" ] && for p in $(awk '{print $2, $4}' "$pids_file"); do kill -9 "$p" 2>/dev/null; done
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() { echo "cancel: $*" >&2; exit 1; }
alive() { kill -0 "$1" 2>/dev/null && [ "$(ps -o stat= -p "$1" | cut -c1)" != Z ]; }
# within MS: a limit of MS milliseconds on an idle machine, stretched by the
# load per core when it is over 1 (on 2 cores at load 25 a process gets a
# twelfth of a core: stopping and writing the report took 3.5 s there,
# against 0.4-1.1 s at the other moments of the same run). What is bounded
# is vgc's own work after the signal, not the machine's schedule.
within() {
  awk -v ms="$1" -v n="$(nproc)" '{ f = $1 / n; if (f < 1) f = 1; printf "%d", ms * f }' /proc/loadavg
}

start_run() {  # start_run NAME: a run in the background, $run_pid
  : >"$pids_file"
  rm -f "$tmp/hanging"
  VGC_FAULT=base-layer-destroyable HISTORY_PROXY_PIDS=$pids_file HISTORY_PROXY_HANGING=$tmp/hanging \
    "$vgc" certify --quiet --cases 200 --timeout 60 \
    --clauses 'LAYER-*' --impl "exec:$here/history_proxy.py $vgc hang 300 --impl plugin:$plugin" \
    --reports "$tmp/$1" >"$tmp/$1.out" 2>"$tmp/$1.err" &
  run_pid=$!
  # Until the proxy hangs (300 commands in: LAYER-BASE-2 was found long
  # before), however long that takes on a loaded machine.
  for _ in $(seq 1200); do [ -e "$tmp/hanging" ] && break; alive "$run_pid" || break; sleep 0.1; done
  [ -e "$tmp/hanging" ] || { cat "$tmp/$1.out" "$tmp/$1.err" >&2; fail "$1: the implementation did not reach its hang in 120 s"; }
  alive "$run_pid" || { cat "$tmp/$1.out" "$tmp/$1.err" >&2; fail "$1: vgc ended before it was cancelled"; }
}

for sig in TERM INT; do
  start_run "$sig"
  t0=$(date +%s%N)
  kill -"$sig" "$run_pid"
  wait "$run_pid"; rc=$?
  ms=$(( ($(date +%s%N) - t0) / 1000000 ))
  want=$(( 128 + $(kill -l "$sig") ))
  [ "$rc" = "$want" ] || { cat "$tmp/$sig.out" "$tmp/$sig.err" >&2; fail "SIG$sig: exit $rc, expected $want"; }
  limit=$(within 3000)
  [ "$ms" -lt "$limit" ] || fail "SIG$sig: vgc took $ms ms to stop (limit $limit ms at load $(cut -d' ' -f1 /proc/loadavg))"
  report=$tmp/$sig/latest/report.json
  [ -s "$report" ] || { ls -laR "$tmp/$sig" >&2; cat "$tmp/$sig.err" >&2; fail "SIG$sig: no report written"; }
  for f in summary.md report.html junit.xml counterexamples/LAYER-BASE-2.vgc; do
    [ -s "$tmp/$sig/latest/$f" ] || fail "SIG$sig: $f missing"
  done
  grep -q '"verdict": "incomplete"' "$report" || fail "SIG$sig: verdict is not incomplete: $(grep '"verdict"' "$report")"
  grep -q "\"cancelled_by\": \"SIG$sig\"" "$report" || fail "SIG$sig: report.json does not say it was cancelled"
  grep -q 'LAYER-BASE-2' "$tmp/$sig/latest/summary.md" || fail "SIG$sig: the finding made before the cancel is lost"
  grep -q "cancelled by SIG$sig" "$tmp/$sig/latest/summary.md" || fail "SIG$sig: summary.md does not say it was cancelled"
  grep -q "\"exit_code\": $want" "$report" || fail "SIG$sig: report.json's exit_code is not the process's $want: $(grep '"exit_code"' "$report")"
  grep -q "^cancelled by SIG$sig" "$tmp/$sig.out" || fail "SIG$sig: stdout lost the line that says it was cancelled"
  grep -q "^report: " "$tmp/$sig.out" || fail "SIG$sig: stdout lost the report line"
  sleep 0.5
  for p in $(awk '{print $2, $4}' "$pids_file"); do alive "$p" && fail "SIG$sig: process $p of the implementation outlived vgc"; done
done

start_run twice
kill -TERM "$run_pid"; kill -INT "$run_pid"
wait "$run_pid"; rc=$?
[ "$rc" = 130 ] || { cat "$tmp/twice.err" >&2; fail "two signals: exit $rc, expected 130"; }
grep -q "second signal" "$tmp/twice.err" || { cat "$tmp/twice.err" >&2; fail "two signals: no word of the second signal"; }

# expect_cancelled NAME RC MS: a run cancelled by SIGTERM ended with 143
# within 2 s, with a whole report whose exit_code is the process's and in
# which no capability the implementation claims reads not-claimed (it is
# unchecked when the cancel came before its check; issue 31 item 6).
expect_cancelled() {
  local name=$1 rc=$2 ms=$3 report=$tmp/$1/latest/report.json
  [ "$rc" = 143 ] || { tail -n 5 "$tmp/$name.err" >&2; fail "$name: exit $rc, expected 143"; }
  local limit
  limit=$(within 2000)
  [ "$ms" -lt "$limit" ] || fail "$name: vgc took $ms ms to stop (limit $limit ms at load $(cut -d' ' -f1 /proc/loadavg))"
  [ -s "$report" ] || { ls -la "$tmp/$name" >&2; tail -n 5 "$tmp/$name.err" >&2; fail "$name: no report written"; }
  python3 - "$report" "$claims" <<'PY' || fail "$name: report.json is wrong (above)"
import json, sys
r = json.load(open(sys.argv[1]))
claims_every_capability = bool(sys.argv[2].split())
assert r["exit_code"] == 143, "exit_code %s" % r["exit_code"]
assert r["cancelled_by"] == "SIGTERM", r.get("cancelled_by")
assert r["verdict"] == "incomplete", r["verdict"]
wrong = [c["id"] for c in r["clauses"] if c["status"] == "not-claimed"]
assert not (claims_every_capability and wrong), "claimed capabilities read not-claimed: %s" % wrong
PY
}
# The capabilities `vgc serve` claims (the reference claims every one).
claims=$(printf '?capabilities\n?quit\n' | "$vgc" serve | head -n 1 | cut -d' ' -f2-)
[ -n "$claims" ] || fail "vgc serve claims no capability: the not-claimed check below would check nothing"

# A whole certification through exec:'vgc serve', cancelled by `timeout`
# at moments spread over the run (storage.scale runs from about 1 s in).
# `timeout` sends its SIGTERM to vgc and then to its own process group, so
# vgc gets it twice, microseconds apart: that is one cancel, not a second
# signal (it used to end about 1 run in 3 here, and 1 in 33 in the issue,
# with exit 143 and no report). Every run the signal reached before its end
# must stop within 2 s with its report.
cancelled=0
for delay in 0.3 0.8 1.3 1.9 2.6 3.4 4.3 5.3 6.5 8.0; do  # one decimal each (the ms sum below)
  name=full-$delay
  t0=$(date +%s%N)
  timeout --preserve-status -s TERM "$delay" "$vgc" certify --quiet --impl "exec:$vgc serve" --reports "$tmp/$name" \
    >"$tmp/$name.out" 2>"$tmp/$name.err"
  rc=$?
  ms=$(( ($(date +%s%N) - t0) / 1000000 - ${delay%.*} * 1000 - ${delay#*.} * 100 ))
  if [ "$rc" = 0 ] && ! grep -q cancelled_by "$tmp/$name/latest/report.json"; then
    echo "cancel: $name: the run had ended (conformant) before the signal"
    continue
  fi
  expect_cancelled "$name" "$rc" "$ms"
  cancelled=$((cancelled + 1))
  echo "cancel: $name: stopped $ms ms after the signal, report written"
done
[ "$cancelled" -ge 5 ] || fail "only $cancelled of the runs were cancelled before they ended: too little was checked"

# Cancelled while the implementation is still starting (it never answers
# ?hello; the start limit is 60 s): the report is written all the same,
# every clause unchecked.
name=starting
"$vgc" certify --quiet --clauses 'LAYER-*' --impl "exec:touch '$tmp/started'; sleep 30" --reports "$tmp/$name" \
  >"$tmp/$name.out" 2>"$tmp/$name.err" &
run_pid=$!
for _ in $(seq 600); do [ -e "$tmp/started" ] && break; sleep 0.1; done  # vgc is waiting for its ?hello
[ -e "$tmp/started" ] || fail "starting: the implementation was not started within 60 s"
t0=$(date +%s%N)
kill -TERM "$run_pid"
wait "$run_pid"; rc=$?
ms=$(( ($(date +%s%N) - t0) / 1000000 ))
claims=
expect_cancelled "$name" "$rc" "$ms"
python3 - "$tmp/$name/latest/report.json" <<'PY' || fail "starting: report.json is wrong (above)"
import json, sys
r = json.load(open(sys.argv[1]))
statuses = {c["status"] for c in r["clauses"]}
assert statuses == {"unchecked"}, statuses
PY
# Over the Verse wire, cancelled during the login to a host that does not
# answer (stopped): the login's limit is --start-timeout (60 s), and the
# wait must end at the cancel, not at the limit.
"$vgc" serve --verse 127.0.0.1:0 >"$tmp/host.out" 2>"$tmp/host.err" &
host_pid=$!
for _ in $(seq 300); do grep -q '^vgc-verse listening' "$tmp/host.out" && break; sleep 0.1; done
port=$(sed -n 's/^vgc-verse listening .*:\([0-9]*\)$/\1/p' "$tmp/host.out")
[ -n "$port" ] || { kill "$host_pid"; fail "verse: the host did not start"; }
kill -STOP "$host_pid"
name=verse-login
"$vgc" certify --quiet --clauses 'LAYER-*' --impl "verse:127.0.0.1:$port" --reports "$tmp/$name" \
  >"$tmp/$name.out" 2>"$tmp/$name.err" &
run_pid=$!
# Once vgc has its UDP socket (its login has begun; its handlers are in place before).
for _ in $(seq 600); do ls -l "/proc/$run_pid/fd" 2>/dev/null | grep -q 'socket:' && break; sleep 0.1; done
sleep 0.5
t0=$(date +%s%N)
kill -TERM "$run_pid"
wait "$run_pid"; rc=$?
ms=$(( ($(date +%s%N) - t0) / 1000000 ))
kill -CONT "$host_pid"; kill "$host_pid"; wait "$host_pid" 2>/dev/null
claims=
expect_cancelled "$name" "$rc" "$ms"
echo "cancel: verse-login: stopped $ms ms after the signal, report written"

echo "cancel: SIGTERM and SIGINT stop the run within 3 s and write an incomplete report with the finding; a second signal exits at once; $cancelled runs through exec:'vgc serve' cancelled by timeout at moments from 0.3 s to 8 s a run cancelled while its implementation started and one cancelled during a Verse login each stopped within 2 s with a whole report (exit_code 143, claimed capabilities not not-claimed)"
