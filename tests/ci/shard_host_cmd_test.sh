#!/usr/bin/env bash
# shard_host_cmd_test.sh VGC — `vgc certify --shard I/N` with `--host-cmd`:
# every shard starts its own host on the port of --impl, so shards side by
# side on one machine need a port each. The second shard finds the port in
# use (here held by a plain UDP socket): exit 2, the port message, and the
# line that says shards need a port each (cli/cmd_certify.cpp; docs/certify.md
# "Splitting a run: shards"). Seen failing with that line taken out of
# cmd_certify.cpp. Takes the launcher's 10 s wait for the port, no more.
set -uo pipefail
[ $# -ge 1 ] || { echo "usage: $0 VGC" >&2; exit 2; }
vgc=$1
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_shard_host_cmd.XXXXXX")
holder=""
trap '[ -n "$holder" ] && kill "$holder" 2>/dev/null; rm -rf "$tmp"' EXIT
fail() { echo "shard_host_cmd: $*" >&2; exit 1; }
python3 -c '
import socket, sys, time
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.bind(("127.0.0.1", 0))
print(s.getsockname()[1], flush=True)
time.sleep(120)' >"$tmp/port" &
holder=$!
for _ in $(seq 100); do [ -s "$tmp/port" ] && break; sleep 0.1; done
port=$(cat "$tmp/port")
[ -n "$port" ] || fail "the port holder did not start"
"$vgc" certify --impl "verse:127.0.0.1:$port" --host-cmd "exec sleep 60" --shard 2/3 \
  --reports "$tmp/R" >"$tmp/out" 2>&1
rc=$?
cat "$tmp/out"
[ $rc = 2 ] || fail "exit $rc, expected 2 (the host's port is in use)"
grep -q "UDP port $port of 127.0.0.1 is in use by another program" "$tmp/out" || fail "no port message"
grep -q "with --shard 2/3 and --host-cmd every shard starts its own host on the port of --impl" "$tmp/out" \
  || fail "the exit 2 does not say that shards with --host-cmd need a port each"
grep -q "each need a port of their own" "$tmp/out" || fail "the exit 2 does not say that shards need a port each"
echo "shard_host_cmd: exit 2, the port in use, shards need a port each"
