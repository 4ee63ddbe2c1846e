#!/usr/bin/env bash
# no_orphans.sh VGC WORK_DIR — nothing `vgc fuzz` starts outlives it,
# however it ends (issue 29 item 5; the fuzz side of
# tests/ci/no_orphans_test.sh, which holds `vgc certify` to the same). A
# stand-in for the libFuzzer binary starts a fork-mode-like job in its
# process group and a sleeper in a session of its own (setsid), then runs
# on; `vgc fuzz stream` is killed with SIGKILL, then with SIGTERM, while it
# runs. Within 5 s the stand-in, its job and the setsid sleeper must be
# gone. (With the campaign's own fork+setpgid they were all left running
# under PID 1: nothing killed the group once vgc was gone.) Then a
# campaign that ends at its --time leaves nothing either.
. "$(dirname "$0")/stand_in_lib.sh" no_orphans "$@"
pids_file=$work/pids
cleanup() {
  # Whatever the outcome, this test leaves nothing running either.
  [ -f "$pids_file" ] && for p in $(awk '{print $2}' "$pids_file"); do kill -9 "$p" 2>/dev/null; done
}
trap cleanup EXIT
cat >"$work/fuzz/fuzz_stream" <<'SCRIPT'
#!/usr/bin/env bash
pids=$(dirname "$0")/../pids
echo "stand-in $$" >>"$pids"
sleep 300 &
echo "job $!" >>"$pids"
setsid sleep 301 </dev/null >/dev/null 2>&1 &
echo "setsid $!" >>"$pids"
echo "#1	INITED cov: 10 ft: 20 corp: 1/9b exec/s: 1 rss: 30Mb"
sleep 302
SCRIPT
chmod +x "$work/fuzz/fuzz_stream"

alive() { kill -0 "$1" 2>/dev/null && [ "$(sed 's/^.*) //' "/proc/$1/stat" 2>/dev/null | cut -c1)" != Z ]; }
gone_within_5s() {  # every pid of the pids file ends within 5 s
  for _ in $(seq 50); do
    left=
    for p in $(awk '{print $2}' "$pids_file"); do alive "$p" && left="$left $p"; done
    [ -z "$left" ] && return 0
    sleep 0.1
  done
  ps -o pid,ppid,pgid,sid,stat,args -p "${left# }" >&2
  return 1
}

for how in KILL TERM; do
  : >"$pids_file"
  "$vgc" fuzz stream --time 120 --fuzz-build "$work" --source-dir "$work/src" >"$work/out" 2>&1 &
  vgc_pid=$!
  for _ in $(seq 300); do [ "$(wc -l <"$pids_file")" -ge 3 ] && break; sleep 0.1; done
  [ "$(wc -l <"$pids_file")" -ge 3 ] || { cat "$work/out" >&2; fail "the stand-in never started its children"; }
  alive "$vgc_pid" || { cat "$work/out" >&2; fail "vgc ended before it was killed"; }
  kill -"$how" "$vgc_pid"
  wait "$vgc_pid" 2>/dev/null
  gone_within_5s || fail "after kill -$how of vgc fuzz, still running:$left"
done

# A campaign that ends at its deadline (--time, plus 5 s) leaves nothing.
: >"$pids_file"
"$vgc" fuzz stream --time 1 --fuzz-build "$work" --source-dir "$work/src" >"$work/out" 2>&1
grep -q '^setsid ' "$pids_file" || { cat "$work/out" >&2; fail "the stand-in never started its sleeper"; }
gone_within_5s || fail "after a campaign that ended at its deadline, still running:$left"
echo "no_orphans: after kill -KILL and kill -TERM of vgc fuzz, and after a campaign that ended, the stand-in," \
  "its job and its setsid sleeper are gone"
