#!/usr/bin/env bash
# no_orphans_test.sh VGC — nothing vgc starts outlives it, however it ends
# (issue 19, item 3). `vgc certify --impl exec:'history_proxy.py VGC hang 50'`
# is killed with SIGKILL while the implementation hangs; within a few
# seconds the proxy (python, started by /bin/sh) and its child `vgc serve`
# must be gone too. They used to be left running under PID 1.
set -uo pipefail
[ $# -ge 1 ] || { echo "usage: $0 VGC" >&2; exit 2; }
vgc=$1
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_no_orphans.XXXXXX")
pids_file=$tmp/pids
cleanup() {
  # Whatever the outcome, this test leaves nothing running either.
  if [ -f "$pids_file" ]; then
    for p in $(awk '{print $2, $4}' "$pids_file"); do kill -9 "$p" 2>/dev/null; done
  fi
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() { echo "no_orphans: $*" >&2; exit 1; }

alive() { kill -0 "$1" 2>/dev/null && [ "$(ps -o stat= -p "$1" | cut -c1)" != Z ]; }

for how in KILL TERM; do
  : >"$pids_file"
  HISTORY_PROXY_PIDS=$pids_file "$vgc" certify --quiet --cases 200 --timeout 60 --clauses 'LAYER-*' \
    --impl "exec:$here/history_proxy.py $vgc hang 50" --reports "$tmp/R" >"$tmp/out" 2>&1 &
  vgc_pid=$!
  # Wait until the proxy has started and the run has had time to reach its hang.
  for _ in $(seq 100); do [ -s "$pids_file" ] && break; sleep 0.1; done
  [ -s "$pids_file" ] || { cat "$tmp/out" >&2; fail "the implementation never started"; }
  sleep 2
  alive "$vgc_pid" || { cat "$tmp/out" >&2; fail "vgc ended before the hang (expected it to wait 60 s)"; }
  kill -"$how" "$vgc_pid"
  wait "$vgc_pid" 2>/dev/null
  left=
  for _ in $(seq 50); do
    left=
    for p in $(awk '{print $2, $4}' "$pids_file"); do alive "$p" && left="$left $p"; done
    [ -z "$left" ] && break
    sleep 0.1
  done
  [ -z "$left" ] || { ps -o pid,ppid,pgid,stat,args -p "${left# }" >&2; fail "after kill -$how of vgc, still running:$left"; }
done
echo "no_orphans: after kill -KILL and kill -TERM of vgc, its implementation and the implementation's child are gone"
