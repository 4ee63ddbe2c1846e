#!/usr/bin/env bash
# cancel_test.sh VGC FAULT_PLUGIN — a cancelled certify run writes what it
# found (issue 19, item 4). The implementation is history_proxy.py in front
# of the fault plugin (VGC_FAULT=base-layer-destroyable: LAYER-BASE-2 fails
# within the first cases) that hangs after 300 commands, with a 60 s
# timeout. SIGTERM after 4 s (and SIGINT in a second run) must end vgc
# within 3 s with exit 128 + the signal, after writing a whole run
# directory whose report.json says verdict "incomplete", cancelled_by the
# signal, and still lists LAYER-BASE-2; nothing vgc started may be left.
# Then SIGTERM followed at once by SIGINT exits at once (the second
# signal's message, exit 130). A cancelled run used to leave no report.
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

start_run() {  # start_run NAME: a run in the background, $run_pid
  : >"$pids_file"
  VGC_FAULT=base-layer-destroyable HISTORY_PROXY_PIDS=$pids_file "$vgc" certify --quiet --cases 200 --timeout 60 \
    --clauses 'LAYER-*' --impl "exec:$here/history_proxy.py $vgc hang 300 --impl plugin:$plugin" \
    --reports "$tmp/$1" >"$tmp/$1.out" 2>"$tmp/$1.err" &
  run_pid=$!
  sleep 4
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
  [ "$ms" -lt 3000 ] || fail "SIG$sig: vgc took $ms ms to stop"
  report=$tmp/$sig/latest/report.json
  [ -s "$report" ] || { ls -laR "$tmp/$sig" >&2; cat "$tmp/$sig.err" >&2; fail "SIG$sig: no report written"; }
  for f in summary.md report.html junit.xml counterexamples/LAYER-BASE-2.vgc; do
    [ -s "$tmp/$sig/latest/$f" ] || fail "SIG$sig: $f missing"
  done
  grep -q '"verdict": "incomplete"' "$report" || fail "SIG$sig: verdict is not incomplete: $(grep '"verdict"' "$report")"
  grep -q "\"cancelled_by\": \"SIG$sig\"" "$report" || fail "SIG$sig: report.json does not say it was cancelled"
  grep -q 'LAYER-BASE-2' "$tmp/$sig/latest/summary.md" || fail "SIG$sig: the finding made before the cancel is lost"
  grep -q "cancelled by SIG$sig" "$tmp/$sig/latest/summary.md" || fail "SIG$sig: summary.md does not say it was cancelled"
  sleep 0.5
  for p in $(awk '{print $2, $4}' "$pids_file"); do alive "$p" && fail "SIG$sig: process $p of the implementation outlived vgc"; done
done

start_run twice
kill -TERM "$run_pid"; kill -INT "$run_pid"
wait "$run_pid"; rc=$?
[ "$rc" = 130 ] || { cat "$tmp/twice.err" >&2; fail "two signals: exit $rc, expected 130"; }
grep -q "second signal" "$tmp/twice.err" || { cat "$tmp/twice.err" >&2; fail "two signals: no word of the second signal"; }
echo "cancel: SIGTERM and SIGINT stop the run within 3 s and write an incomplete report with the finding; a second signal exits at once"
