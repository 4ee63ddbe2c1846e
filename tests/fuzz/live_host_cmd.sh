#!/usr/bin/env bash
# live_host_cmd.sh CHECK VGC FUZZ_BUILD TARGET PLUGIN SOURCE_DIR WORK
# (libFuzzer build only) A Verse host that vgc starts itself, `--impl
# verse:HOST:PORT --host-cmd CMD` (docs/fuzzing.md "A Verse host vgc starts:
# --host-cmd"). The host is `VGC serve --verse 127.0.0.1:PORT --impl
# plugin:PLUGIN`, PLUGIN being examples/c_host built with clang's inline
# 8-bit counters, PC table and vgc's coverage runtime (as for
# live_coverage_guides.sh, there over exec). CHECK is
#   coverage    1. the committed corpus read once by TARGET (fuzz_differential,
#                  -runs=0) over the wire with VGC_FUZZ_HOST_CMD, the node's
#                  coverage guiding and only observed: the target says the
#                  host's coverage is seen, the reference's coverage (cov) is
#                  the same, the features (ft) more when guiding;
#               2. a 20 s campaign with --host-cmd and --coverage-report: its
#                  summary says the host's counters were reached and its
#                  functions entered (ch_node_apply among them), host.log has
#                  the host's output, and no host is left after it;
#               3. the same campaign against a host already running and no
#                  --host-cmd says the coverage is not seen (as before).
#   wire        `vgc fuzz wire --host-cmd` of 60 inputs, guided and observed:
#               the host's counters seen in both, inputs queued and made from
#               the queue only when guided; no host left after either.
#   orphans     `vgc fuzz differential --host-cmd` killed with SIGKILL, then
#               SIGTERM, while the host it started runs; `vgc certify
#               --host-cmd` killed with SIGKILL: within 5 s no host is left.
set -u
check=$1 vgc=$2 fbuild=$3 target=$4 plugin=$5 src=$6 work=$7
fail() { echo "live_host_cmd ($check): $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work/corpus" "$work/src/corpora/fuzz/fuzz_differential"
pids_file=$work/host_pids
: >"$pids_file"
cleanup() {  # whatever the outcome, this test leaves nothing running
  for p in $(cat "$pids_file" 2>/dev/null) ${other_host:-}; do kill -9 "$p" 2>/dev/null; done
}
trap cleanup EXIT
# A free UDP port on loopback (the kernel's pick, released at once).
port=$(python3 -c 'import socket; s=socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
spec="verse:127.0.0.1:$port"
# The host writes its pid (sh's, which exec keeps) before it becomes the host.
host_cmd="echo \$\$ >>'$pids_file'; exec '$vgc' serve --verse 127.0.0.1:$port --impl 'plugin:$plugin'"
alive() { kill -0 "$1" 2>/dev/null && [ "$(sed 's/^.*) //' "/proc/$1/stat" 2>/dev/null | cut -c1)" != Z ]; }
hosts_left() {  # the hosts of the pids file still running
  left=
  for p in $(cat "$pids_file"); do alive "$p" && left="$left $p"; done
  [ -n "$left" ]
}
gone_within_5s() {
  for _ in $(seq 50); do hosts_left || return 0; sleep 0.1; done
  ps -o pid,ppid,pgid,sid,stat,args -p "${left# }" >&2
  return 1
}

case "$check" in
coverage)
  cp "$src/corpora/fuzz/fuzz_differential/"* "$work/corpus/"
  inited() {  # MODE -> "cov ft" of libFuzzer's INITED line
    VGC_FUZZ_IMPL=$spec VGC_FUZZ_HOST_CMD=$host_cmd VGC_FUZZ_IMPL_COVERAGE=$1 \
      "$target" -runs=0 -detect_leaks=0 -max_len=1024 "$work/corpus" >"$work/inited-$1.log" 2>&1 ||
      fail "$1: $target -runs=0 failed: $(tail -n 5 "$work/inited-$1.log")"
    sed -n 's/^#[0-9]*[[:space:]]*INITED cov: \([0-9]*\) ft: \([0-9]*\).*/\1 \2/p' "$work/inited-$1.log" | tail -n 1
  }
  read -r cov_g ft_g <<<"$(inited guide)"
  read -r cov_o ft_o <<<"$(inited observe)"
  echo "live_host_cmd: corpus of $(ls "$work/corpus" | wc -l) inputs over the wire: guide cov $cov_g ft $ft_g;" \
    "observe cov $cov_o ft $ft_o"
  [ -n "$ft_g" ] && [ -n "$ft_o" ] || fail "no INITED line (see $work/inited-*.log)"
  grep -q "the implementation's coverage is seen: [0-9]* counters" "$work/inited-guide.log" ||
    fail "the target did not say the host's coverage is seen: $(grep -m1 "coverage" "$work/inited-guide.log")"
  # Over the wire vgc's own coverage varies a little from run to run (the
  # adapter's resend and late-packet paths depend on timing): within 1 %.
  d=$((cov_g > cov_o ? cov_g - cov_o : cov_o - cov_g))
  [ $((d * 100)) -le "$cov_o" ] || fail "the reference's coverage differs by more than 1 %: $cov_g vs $cov_o"
  grep -q "module .*libc_host_coverage.so ([0-9]* counters" "$work/inited-guide.log" ||
    fail "the host's module is not named: $(grep -m2 "module" "$work/inited-guide.log")"
  [ "$(grep -c "module .*libc_host_coverage.so" "$work/inited-guide.log")" -eq 1 ] ||
    fail "the plugin's counters were mapped more than once: $(grep "module" "$work/inited-guide.log")"
  [ "$ft_g" -gt "$ft_o" ] || fail "guiding added no feature: ft $ft_g vs $ft_o"
  gone_within_5s || fail "after the target ended, a host is still running:$left"

  cp "$src/corpora/fuzz/fuzz_differential/seed-cube.bin" "$work/src/corpora/fuzz/fuzz_differential/"
  : >"$pids_file"
  "$vgc" fuzz differential --impl "$spec" --host-cmd "$host_cmd" --time 20 --seed 1 --fuzz-build "$fbuild" \
    --coverage-report --source-dir "$work/src" >"$work/campaign.out" 2>&1
  rc=$?
  [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || { tail -n 20 "$work/campaign.out"; fail "the campaign exited $rc"; }
  [ -s "$pids_file" ] || fail "the campaign started no host"
  gone_within_5s || fail "after the campaign ended, a host is still running:$left"
  summary=$(ls "$work"/src/reports/fuzz/fuzz_differential/*/summary.json) || fail "no summary.json"
  grep -q "vgc-verse listening 127.0.0.1:$port" "$(dirname "$summary")/host.log" ||
    fail "host.log does not have the host's output: $(head -c 300 "$(dirname "$summary")/host.log")"
  python3 - "$summary" <<'PY' || fail "summary: see above"
import json, sys
s = json.load(open(sys.argv[1]))
ic = s["implementation_coverage"]
assert ic and ic["mode"] == "guide" and ic["seen"], ic
assert 0 < ic["counters_reached"] <= ic["counters"], ic
assert 0 < ic["functions_entered"] <= ic["function_entries"], ic
report = ic["coverage_report"]
assert report, "no coverage report: %s" % ic.get("coverage_report_note")
entered = open(report).read().split("## Entered")[1]
assert "- `ch_node_apply`" in entered, "ch_node_apply is not among the entered functions: %s" % entered[:400]
md = open(sys.argv[1].replace("summary.json", "summary.md")).read()
line = [l for l in md.splitlines() if l.startswith("| implementation coverage |")]
assert line and "counters reached" in line[0] and "functions entered" in line[0], line
print("live_host_cmd: %s" % line[0])
PY

  # A host already running, no --host-cmd: the coverage is not seen, as before.
  "$vgc" serve --verse "127.0.0.1:$port" --impl "plugin:$plugin" >"$work/other_host.log" 2>&1 &
  other_host=$!
  for _ in $(seq 50); do grep -q "listening" "$work/other_host.log" && break; sleep 0.1; done
  rm -rf "$work/src/reports"
  "$vgc" fuzz differential --impl "$spec" --time 5 --seed 1 --fuzz-build "$fbuild" --source-dir "$work/src" \
    >"$work/campaign-running.out" 2>&1
  rc=$?
  [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || { tail -n 20 "$work/campaign-running.out"; fail "the campaign exited $rc"; }
  summary=$(ls "$work"/src/reports/fuzz/fuzz_differential/*/summary.json) || fail "no summary.json (running host)"
  python3 - "$summary" <<'PY' || fail "summary (running host): see above"
import json, sys
s = json.load(open(sys.argv[1]))
ic = s["implementation_coverage"]
assert ic and ic["mode"] == "wire" and not ic["seen"] and ic["counters_reached"] == 0, ic
md = open(sys.argv[1].replace("summary.json", "summary.md")).read()
assert "| implementation coverage | not seen: " in md and "--host-cmd" in md, "summary.md does not say it is not seen"
print("live_host_cmd: a host vgc did not start: not seen")
PY
  ;;
orphans)
  cp "$src/corpora/fuzz/fuzz_differential/seed-cube.bin" "$work/src/corpora/fuzz/fuzz_differential/"
  started() {  # WHAT LOG: waits until a host has written its pid and listens
    for _ in $(seq 600); do
      [ -s "$pids_file" ] && hosts_left && return 0
      sleep 0.1
    done
    tail -n 20 "$2" >&2
    fail "$1: no host was started"
  }
  for how in KILL TERM; do
    : >"$pids_file"
    "$vgc" fuzz differential --impl "$spec" --host-cmd "$host_cmd" --time 120 --seed 1 --fuzz-build "$fbuild" \
      --source-dir "$work/src" >"$work/fuzz-$how.out" 2>&1 &
    vgc_pid=$!
    started "vgc fuzz" "$work/fuzz-$how.out"
    sleep 2  # libFuzzer runs inputs against it
    alive "$vgc_pid" || { tail -n 20 "$work/fuzz-$how.out" >&2; fail "vgc fuzz ended before it was killed"; }
    kill -"$how" "$vgc_pid"
    wait "$vgc_pid" 2>/dev/null
    gone_within_5s || fail "after kill -$how of vgc fuzz, a host is still running:$left"
  done
  : >"$pids_file"
  "$vgc" certify --impl "$spec" --host-cmd "$host_cmd" --reports "$work/certify" >"$work/certify.out" 2>&1 &
  vgc_pid=$!
  started "vgc certify" "$work/certify.out"
  alive "$vgc_pid" || { tail -n 20 "$work/certify.out" >&2; fail "vgc certify ended before it was killed"; }
  kill -KILL "$vgc_pid"
  wait "$vgc_pid" 2>/dev/null
  gone_within_5s || fail "after kill -KILL of vgc certify, a host is still running:$left"
  echo "live_host_cmd: after kill -KILL and -TERM of vgc fuzz and kill -KILL of vgc certify, no host is left"
  ;;
wire)
  # vgc fuzz wire with the host's coverage: guided, the inputs that reached
  # new code of the host are queued and later inputs made from them;
  # observed, the counters are counted and every input drawn afresh.
  for mode in guide observe; do
    : >"$pids_file"
    rm -rf "$work/src/reports"
    "$vgc" fuzz wire --impl "$spec" --host-cmd "$host_cmd" --impl-coverage "$mode" --max-inputs 60 --time 600 \
      --seed 1 --source-dir "$work/src" >"$work/wire-$mode.out" 2>&1
    rc=$?
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || { tail -n 20 "$work/wire-$mode.out"; fail "vgc fuzz wire ($mode) exited $rc"; }
    [ -s "$pids_file" ] || fail "vgc fuzz wire ($mode) started no host"
    gone_within_5s || fail "after vgc fuzz wire ($mode) ended, a host is still running:$left"
    summary=$(ls "$work"/src/reports/fuzz/wire/*/summary.json) || fail "no summary.json ($mode)"
    python3 - "$summary" "$mode" <<'PY' || fail "wire summary ($mode): see above"
import json, sys
s = json.load(open(sys.argv[1])); mode = sys.argv[2]
ic = s["implementation_coverage"]
assert ic["mode"] == mode and ic["seen"], ic
assert 0 < ic["counters_reached"] <= ic["counters"] and ic["functions_entered"] > 0, ic
if mode == "guide":
    assert ic["queued"] > 0 and ic["inputs_from_queue"] > 0, "guided, nothing queued or made from the queue: %s" % ic
else:
    assert ic["queued"] == 0 and ic["inputs_from_queue"] == 0, "observed, yet inputs queued: %s" % ic
md = open(sys.argv[1].replace("summary.json", "summary.md")).read()
line = [l for l in md.splitlines() if l.startswith("| host coverage |")]
assert line and "counters reached" in line[0], line
print("live_host_cmd: wire %s: %s" % (mode, line[0]))
PY
  done
  ;;
*) fail "unknown check (coverage, orphans or wire)" ;;
esac
