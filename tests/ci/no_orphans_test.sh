#!/usr/bin/env bash
# no_orphans_test.sh VGC — nothing vgc starts outlives it, however it ends
# (issue 19, item 3). `vgc certify --impl exec:'history_proxy.py VGC hang 50'`
# is killed with SIGKILL while the implementation hangs; within a few
# seconds the proxy (python, started by /bin/sh) and its child `vgc serve`
# must be gone too. They used to be left running under PID 1. Then the
# same with an implementation that first starts two sleepers out of its
# process group and session: one `setsid sleep` whose parent stays alive,
# one double-forked (its parent exits at once, so it is an orphan while
# vgc runs); both must be gone after kill -9 of vgc, and after a run that
# ends normally. With only a process-group kill they were left running.
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

# An implementation that leaves its session: two sleepers, then the proxy.
cat >"$tmp/setsid_impl.sh" <<'SH'
#!/bin/sh
setsid sleep 300 </dev/null >/dev/null 2>&1 &
echo "setsid $!" >>"$HISTORY_PROXY_PIDS"
sh -c 'setsid sleep 301 </dev/null >/dev/null 2>&1 & echo "double $!" >>"$HISTORY_PROXY_PIDS"'
exec "$@"
SH
chmod +x "$tmp/setsid_impl.sh"

gone_within_5s() {  # every pid of the pids file ends within 5 s
  left=
  for _ in $(seq 50); do
    left=
    for p in $(awk '{print $2, $4}' "$pids_file"); do alive "$p" && left="$left $p"; done
    [ -z "$left" ] && return 0
    sleep 0.1
  done
  ps -o pid,ppid,pgid,sid,stat,args -p "${left# }" >&2
  return 1
}

# A run that ends normally leaves no sleeper either.
: >"$pids_file"
HISTORY_PROXY_PIDS=$pids_file timeout 60 "$vgc" certify --quiet --cases 5 --clauses 'LAYER-BASE-*' \
  --impl "exec:$tmp/setsid_impl.sh $vgc serve" --reports "$tmp/R" >"$tmp/out" 2>&1
grep -q '^setsid ' "$pids_file" || { cat "$tmp/out" >&2; fail "the setsid implementation never started"; }
gone_within_5s || fail "after a normal run, still running:$left"

for how in KILL TERM SETSID-KILL; do
  : >"$pids_file"
  impl="exec:$here/history_proxy.py $vgc hang 50"
  [ "$how" = SETSID-KILL ] && impl="exec:$tmp/setsid_impl.sh $here/history_proxy.py $vgc hang 50"
  HISTORY_PROXY_PIDS=$pids_file "$vgc" certify --quiet --cases 200 --timeout 60 --clauses 'LAYER-*' \
    --impl "$impl" --reports "$tmp/R" >"$tmp/out" 2>&1 &
  vgc_pid=$!
  # Wait until the proxy has started and the run has had time to reach its hang.
  for _ in $(seq 100); do [ -s "$pids_file" ] && break; sleep 0.1; done
  [ -s "$pids_file" ] || { cat "$tmp/out" >&2; fail "the implementation never started"; }
  sleep 2
  alive "$vgc_pid" || { cat "$tmp/out" >&2; fail "vgc ended before the hang (expected it to wait 60 s)"; }
  kill -"${how#SETSID-}" "$vgc_pid"
  wait "$vgc_pid" 2>/dev/null
  gone_within_5s || fail "after kill -$how of vgc, still running:$left"
done
echo "no_orphans: after kill -KILL and kill -TERM of vgc, and after a normal run, its implementation, the" \
  "implementation's child and sleepers it started with setsid (one double-forked) are gone"
