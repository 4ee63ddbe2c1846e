#!/bin/bash
# record.sh — records the r6 interop transcripts replayed by
# tests/verse/r6_replay_test.cpp (docs/verse_wire.md section 12).
#
#   tests/verse/r6_fixtures/record.sh R6_DIR [VGC_BINARY]
#
# R6_DIR is an already-built r6 tree (the public ffforks/verse sources built
# per their own Makefile: it holds libverse.a, verse.h and the `verse`
# server). This script builds nothing of r6: it compiles OUR recorder
# (tests/verse/r6_interop/*.cpp) and links it with R6_DIR/libverse.a, runs
# R6_DIR/verse and `vgc serve --verse` on free loopback ports, each for one
# scripted session, and writes
#   r6_host.txt   r6's client library against r6's host
#   vgc_host.txt  r6's client library against vgc serve --verse
# next to this script. Every server it starts is killed; every wait is bounded.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../../.." && pwd)
r6=${1:?usage: record.sh R6_DIR [VGC_BINARY]}
r6=$(cd "$r6" && pwd)
vgc=${2:-$src/build/cli/vgc}
for f in "$r6/libverse.a" "$r6/verse.h" "$r6/verse" "$vgc"; do
  [ -e "$f" ] || { echo "record.sh: $f not found" >&2; exit 2; }
done
work=$(mktemp -d)
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; rm -rf "$work"; }
trap cleanup EXIT

wraps=v_fs_add_func,v_fs_unpack,v_fs_unpack_beginning,callback_send_packet_ack,callback_send_packet_nak,v_n_receive_data,v_n_send_data
${CXX:-g++} -std=c++17 -O2 -I"$r6" "$src/tests/verse/r6_interop/r6_client.cpp" "$src/tests/verse/r6_interop/r6_tap.cpp" \
  -o "$work/vgc_r6_client" "-Wl,--wrap=${wraps//,/,--wrap=}" "$r6/libverse.a" -lm

free_port() { python3 -c 'import socket; s=socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }

# r6's host (it needs its host_id.rsa, so it runs in its own directory)
port=$(free_port)
(cd "$r6" && exec ./verse -port="$port") > "$work/verse.log" 2>&1 &
pids+=($!)
sleep 0.5
timeout 60 "$work/vgc_r6_client" record "127.0.0.1:$port" "$work/r6_host.txt" > "$work/r6.log" 2>&1 \
  || { echo "record.sh: session against r6's host failed:" >&2; cat "$work/r6.log" >&2; exit 1; }
kill "${pids[-1]}"

# vgc's host
port=$(free_port)
"$vgc" serve --verse "127.0.0.1:$port" > "$work/vgc.out" 2> "$work/vgc.log" &
pids+=($!)
sleep 0.5
timeout 60 "$work/vgc_r6_client" record "127.0.0.1:$port" "$work/vgc_host.txt" > "$work/vgc_client.log" 2>&1 \
  || { echo "record.sh: session against vgc serve --verse failed:" >&2; cat "$work/vgc_client.log" "$work/vgc.log" >&2; exit 1; }
kill "${pids[-1]}"

# the host line names a port that changes from run to run
sed -i 's/^host 127\.0\.0\.1:[0-9]*$/host r6 (R6_DIR\/verse)/' "$work/r6_host.txt"
sed -i 's/^host 127\.0\.0\.1:[0-9]*$/host vgc serve --verse/' "$work/vgc_host.txt"
cp "$work/r6_host.txt" "$work/vgc_host.txt" "$here/"
echo "record.sh: wrote $here/r6_host.txt and $here/vgc_host.txt"
