#!/usr/bin/env bash
# wire_fuzz.sh VGC FAULT_PLUGIN WORK
# `vgc fuzz wire` (fuzz/wire/wire_fuzz.h) against `vgc serve --verse` on
# loopback, bounded by --max-inputs:
#  1. the reference host: every input answered, the node as the model says:
#     no finding (the model of what a host acts on is right);
#  2. the faulty node long-names-truncated (creates a layer whose name is
#     too long): found as LAYER-NAME-1, confirmed on a fresh node; the
#     transcript replays with `vgc replay --wire` (exit 1 naming the clause)
#     and passes against the reference host;
#  3. a host killed during the campaign: a timeout finding, not confirmed
#     (no --restart), the campaign stops and says why;
#     `vgc replay --wire` against the dead port names its --start-timeout;
#  4. the same with --restart (a new host on the port): the campaign goes on
#     to --max-inputs after the finding.
set -u
vgc=$1 plugin=$2 work=$3
fail() { echo "wire_fuzz: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"
. "$(dirname "$0")/live_host_lib.sh"
summary_of() { ls -t "$1"/reports/fuzz/wire/*/summary.json 2>/dev/null | head -1; }

# 1. The reference host.
start_verse_host "$vgc" "" 127.0.0.1:0 "$work/ref.log" || fail "the reference host did not start"
ref_port=$host_port
"$vgc" fuzz wire --impl "verse:127.0.0.1:$ref_port" --time 60 --max-inputs 300 --source-dir "$work/ref" >"$work/ref.out" 2>&1
rc=$?
[ "$rc" -eq 0 ] || fail "against the reference host: exit $rc: $(tail -5 "$work/ref.out")"
python3 - "$(summary_of "$work/ref")" <<'PY' || fail "reference summary"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["inputs"] == 300 and not s["findings"] and not s["stopped_because"], s
assert len(s["inputs_by_kind"]) >= 9, s["inputs_by_kind"]
PY

# 2. A seeded fault.
export VGC_FAULT=long-names-truncated
start_verse_host "$vgc" "$plugin" 127.0.0.1:0 "$work/fault.log" || exit 1
"$vgc" fuzz wire --impl "verse:127.0.0.1:$host_port" --time 60 --max-inputs 100 --stop-at-first \
  --source-dir "$work/fault" >"$work/fault.out" 2>&1
rc=$?
[ "$rc" -eq 1 ] || fail "against long-names-truncated: expected exit 1, got $rc: $(tail -5 "$work/fault.out")"
transcript=$(python3 - "$(summary_of "$work/fault")" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
f = s["findings"]
assert len(f) == 1 and f[0]["clause"] == "LAYER-NAME-1" and f[0]["status"] == "fail", f
assert f[0]["confirmation"].startswith("confirmed:"), f[0]["confirmation"]
print(f[0]["transcript"])
PY
) || fail "fault summary"
r=$("$vgc" replay --wire "$transcript" --impl "verse:127.0.0.1:$host_port" 2>&1)
[ $? -eq 1 ] || fail "vgc replay --wire against the faulty host did not exit 1: $r"
printf '%s\n' "$r" | grep -q "^fail LAYER-NAME-1 (MUST)" || fail "vgc replay --wire does not name LAYER-NAME-1: $r"
"$vgc" replay --wire "$transcript" --impl "verse:127.0.0.1:$ref_port" >/dev/null ||
  fail "the transcript does not pass against the reference host"
unset VGC_FAULT

# 3. A host that dies during the campaign, no --restart.
start_verse_host "$vgc" "" 127.0.0.1:0 "$work/dies.log" || fail "the host did not start"
dies=$host_pid port=$host_port
"$vgc" fuzz wire --impl "verse:127.0.0.1:$port" --time 30 --timeout 1 --source-dir "$work/dies" >"$work/dies.out" 2>&1 &
campaign=$!
sleep 1.5
kill "$dies"
wait "$campaign"
rc=$?
[ "$rc" -eq 1 ] || fail "a host killed mid-campaign: expected exit 1, got $rc: $(tail -5 "$work/dies.out")"
python3 - "$(summary_of "$work/dies")" <<'PY' || fail "dies summary"
import json, sys
s = json.load(open(sys.argv[1]))
f = s["findings"]
assert len(f) == 1 and f[0]["status"] in ("timeout", "crash") and f[0]["clause"] == "STABLE-1", f
assert f[0]["confirmation"].startswith("not confirmed:") and "--restart" in f[0]["confirmation"], f[0]["confirmation"]
assert "--restart" in s["stopped_because"], s["stopped_because"]
assert s["wall_s"] < 25, s["wall_s"]
PY

# 3b. `vgc replay --wire` bounds its login by --start-timeout, as replay of a
# command file does (issue 31): against the dead port it says that limit.
r=$("$vgc" replay --wire "$transcript" --impl "verse:127.0.0.1:$port" --timeout 1 --start-timeout 2 2>&1)
rc=$?
[ "$rc" -eq 2 ] || fail "replay --wire against a dead host: expected exit 2, got $rc: $r"
printf '%s\n' "$r" | grep -q -- "within 2 s (--start-timeout)" || fail "replay --wire against a dead host does not name its 2 s --start-timeout: $r"

# 3c. A malformed transcript is exit 2 naming its line and column, before
# any host is asked, and no raw control byte is echoed (it once aborted on
# a byte pair that is not hex, and read `ids 3x` as 3).
bad_transcript() {  # NAME CONTENT EXPECTED-TEXT
  printf "$2" >"$work/$1.wire"
  r=$("$vgc" replay --wire "$work/$1.wire" --impl "verse:127.0.0.1:$port" --start-timeout 2 2>&1)
  rc=$?
  [ "$rc" -eq 2 ] || fail "replay --wire of $1: expected exit 2, got $rc: $r"
  printf '%s\n' "$r" | grep -qF -- "$3" || fail "replay --wire of $1 does not say '$3': $r"
  ! printf '%s' "$r" | LC_ALL=C grep -q '[[:cntrl:]]' || fail "replay --wire of $1 echoes a control byte: $r"
}
bad_transcript not_hex 'input truncated: x\nids 3\npacket 0 05zz\n' "line 3, column 12: 'z' is not a hex digit"
bad_transcript half_byte 'input truncated: x\nids 3\npacket 0 051\n' "line 3, column 12: half a byte"
bad_transcript control 'input truncated: x\nids 3\ndatagram 00\001G\n' "line 3, column 12: '\\x01' is not a hex digit"
bad_transcript ids 'input truncated: x\nids 3x\n' "line 2, column 5: expected ids N"
bad_transcript offset 'input truncated: x\nids 3\npacket 99999999999999999999 05\n' "line 3, column 8: expected packet OFFSET BODY"

# 4. The same with --restart: a new host on the same port; the campaign goes on.
start_verse_host "$vgc" "" 127.0.0.1:0 "$work/dies2.log" || fail "the host did not start"
dies=$host_pid port=$host_port
cat >"$work/restart.sh" <<SCRIPT
#!/usr/bin/env bash
"$vgc" serve --verse 127.0.0.1:$port >"$work/restarted.log" 2>&1 &
echo \$! >>"$work/restarted.pids"
for _ in \$(seq 1 50); do grep -q listening "$work/restarted.log" && exit 0; sleep 0.1; done
exit 1
SCRIPT
chmod +x "$work/restart.sh"
trap 'cleanup_hosts; [ -f "$work/restarted.pids" ] && kill $(cat "$work/restarted.pids") 2>/dev/null' EXIT
"$vgc" fuzz wire --impl "verse:127.0.0.1:$port" --time 60 --max-inputs 400 --timeout 1 --restart "$work/restart.sh" \
  --source-dir "$work/restart" >"$work/restart.out" 2>&1 &
campaign=$!
sleep 1.5
kill "$dies"
wait "$campaign"
rc=$?
[ "$rc" -eq 1 ] || fail "with --restart: expected exit 1, got $rc: $(tail -5 "$work/restart.out")"
python3 - "$(summary_of "$work/restart")" <<'PY' || fail "restart summary"
import json, sys
s = json.load(open(sys.argv[1]))
f = s["findings"]
assert len(f) >= 1 and f[0]["status"] in ("timeout", "crash"), f
# The host was killed from outside, not by the input: a fresh host does not fail on it.
assert f[0]["confirmation"].startswith("not confirmed: the input alone does not fail a fresh host"), f[0]["confirmation"]
assert s["inputs"] == 400 and not s["stopped_because"], (s["inputs"], s["stopped_because"])
PY
echo "wire_fuzz: reference clean over 300 inputs; LAYER-NAME-1 found, confirmed and replayed; a dead host reported (stopped without --restart, went on with it)"
