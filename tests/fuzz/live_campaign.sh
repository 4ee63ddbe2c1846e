#!/usr/bin/env bash
# live_campaign.sh ROUTE VGC FUZZ_DIFFERENTIAL FAULT_PLUGIN FAULT INPUT CLAUSE STATUS CONFIRM WORK [restart]
# `vgc fuzz differential --impl exec:...|verse:...` end to end: a stand-in
# for the libFuzzer binary (the normal build has none) plays the campaign
# and saves INPUT as a crash input; `vgc fuzz` re-runs it through the real
# target against the live implementation (the faulty node, VGC_FAULT=FAULT,
# served over ROUTE), and its summary must name CLAUSE with STATUS, give a
# `vgc replay ... --impl SPEC` line that, run as printed, names the clause,
# and, for a crash or hang, say whether it was confirmed on a fresh
# instance: CONFIRM is the start of that sentence ("confirmed",
# "not confirmed", or "-" for a plain divergence). With `restart`, the
# campaign gets --restart: a command that starts the host again on its port;
# with `hostcmd`, no host is started beforehand: the campaign starts it
# itself (--host-cmd), and starts it again to confirm a crash; the replay
# line carries --host-cmd and starts one too.
set -u
route=$1 vgc=$2 target=$3 plugin=$4 fault=$5 input=$6 clause=$7 status=$8 confirm=$9 work=${10} restart=${11:-}
fail() { echo "live_campaign: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work/fuzz" "$work/src"
export VGC_FAULT=$fault
. "$(dirname "$0")/live_host_lib.sh"
if [ "$restart" = hostcmd ]; then
  host_port=$(python3 -c 'import socket; s=socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  spec="verse:127.0.0.1:$host_port"
  host_cmd="exec '$vgc' serve --verse 127.0.0.1:$host_port --impl 'plugin:$plugin'"
else
  live_spec "$route" "$vgc" "$plugin" "$work"
fi
cat >"$work/fuzz/fuzz_differential" <<SCRIPT
#!/usr/bin/env bash
for a in "\$@"; do
  case "\$a" in -artifact_prefix=*) prefix=\${a#-artifact_prefix=} ;; -fork=*|-runs=*) campaign=1 ;; esac
done
if [ -n "\${campaign:-}" ]; then
  cp "$input" "\$prefix/crash-live"
  echo "#2	DONE   cov: 10 ft: 20 corp: 1/9b exec/s: 2 rss: 30Mb"
  exit 0
fi
exec "$target" "\$@"
SCRIPT
chmod +x "$work/fuzz/fuzz_differential"
args=(fuzz differential --time 1 --impl "$spec" --timeout 2 --fuzz-build "$work" --source-dir "$work/src")
if [ "$restart" = hostcmd ]; then
  args+=(--host-cmd "$host_cmd")
elif [ -n "$restart" ]; then
  # The restart command: a new host on the same port, returning once it listens.
  cat >"$work/restart.sh" <<SCRIPT
#!/usr/bin/env bash
"$vgc" serve --verse 127.0.0.1:$host_port --impl "plugin:$plugin" >"$work/restarted.log" 2>&1 &
echo \$! >>"$work/restarted.pids"
for _ in \$(seq 1 50); do grep -q listening "$work/restarted.log" && exit 0; sleep 0.1; done
exit 1
SCRIPT
  chmod +x "$work/restart.sh"
  args+=(--restart "$work/restart.sh")
  trap 'cleanup_hosts; [ -f "$work/restarted.pids" ] && kill $(cat "$work/restarted.pids") 2>/dev/null' EXIT
fi
out=$("$vgc" "${args[@]}" 2>&1)
rc=$?
printf '%s\n' "$out" | tail -n 12
[ "$rc" -eq 1 ] || fail "expected exit 1 (a finding), got $rc"
summary=$(ls "$work"/src/reports/fuzz/fuzz_differential/*/summary.json) || fail "no summary.json"
replay=$(python3 - "$summary" "$clause" "$status" "$confirm" "$spec" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); clause, status, confirm, spec = sys.argv[2:6]
assert s["implementation"] == spec, "implementation: %s" % s["implementation"]
c = s["crashes"]
assert len(c) == 1, "expected one finding, got %d" % len(c)
c = c[0]
assert c["clause"] == clause, "clause %r, signature %s" % (c["clause"], c["signature"])
assert (", %s)" % status) in c["signature"], "status: %s" % c["signature"]
assert ("--impl '%s'" % spec) in c["replay"], "replay line: %s" % c["replay"]
if "VGC_FUZZ_HOST_CMD=" in c["replay_fuzzer"]:
    assert "--host-cmd " in c["replay"], "replay line without --host-cmd: %s" % c["replay"]
    assert confirm == "-" or "--host-cmd" in c["confirmation"], "confirmation: %r" % c["confirmation"]
assert "VGC_FUZZ_IMPL=" in c["replay_fuzzer"], c["replay_fuzzer"]
if confirm == "-":
    assert c["confirmation"] == "", c["confirmation"]
    assert c["replayed_clause"] == clause, "replayed: %r" % c["replayed_clause"]
else:
    assert c["confirmation"].startswith(confirm + ":"), "confirmation: %r" % c["confirmation"]
print(c["replay"])
PY
) || fail "summary: see above"
grep -q -- "$clause" "$(dirname "$summary")/summary.md" || fail "summary.md does not name $clause"
[ "$confirm" = "-" ] || grep -q -- "- $confirm:" "$(dirname "$summary")/summary.md" || fail "summary.md does not say '$confirm'"
if [ "$route" = exec ] || [ -n "$restart" ]; then
  # The replay line, run as printed (it names this vgc by its absolute
  # path; a bare `vgc` or `./vgc` is this vgc too): a fresh instance shows
  # the clause again.
  [ "$restart" = restart ] && "$work/restart.sh"
  case "$replay" in
    ./vgc\ *|vgc\ *) line="\"$vgc\" ${replay#* }" ;;
    *) line=$replay ;;
  esac
  r=$(eval "$line" 2>&1)
  [ $? -eq 1 ] || fail "the replay line did not exit 1: $line: $r"
  printf '%s\n' "$r" | grep -q -- "$clause" || fail "the replay line does not name $clause: $r"
fi
echo "live_campaign: $route: $clause ($status) found, summarized and replayable${restart:+, restarted}"
