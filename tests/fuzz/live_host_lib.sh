# live_host_lib.sh — sourced by the tests of fuzzing a live implementation
# (live_finds.sh, live_campaign.sh): the implementation spec for a route.
#   live_spec ROUTE VGC PLUGIN   sets $spec: exec: runs `VGC serve --impl
#     plugin:PLUGIN`; verse: starts `VGC serve --verse 127.0.0.1:0 --impl
#     plugin:PLUGIN` (loopback, a free port) and records its pid in
#     $host_pids, killed on exit. VGC_FAULT (exported) picks the fault.
#   start_verse_host VGC PLUGIN ADDR LOG   one host (PLUGIN "": the
#     reference) on ADDR, its port in $host_port, its pid in $host_pid.
host_pids=""
cleanup_hosts() { for p in $host_pids; do kill "$p" 2>/dev/null; done; }
trap cleanup_hosts EXIT
start_verse_host() {  # VGC PLUGIN ADDR LOGFILE -> sets $host_port and $host_pid; PLUGIN "": the reference
  if [ -n "$2" ]; then
    "$1" serve --verse "$3" --impl "plugin:$2" >"$4" 2>&1 &
  else
    "$1" serve --verse "$3" >"$4" 2>&1 &
  fi
  host_pid=$!
  host_pids="$host_pids $host_pid"
  host_port=""
  for _ in $(seq 1 50); do
    host_port=$(sed -n 's/^vgc-verse listening [0-9.]*:\([0-9]*\).*/\1/p' "$4")
    [ -n "$host_port" ] && return 0
    sleep 0.1
  done
  echo "live_host_lib: the host did not start: $(cat "$4")" >&2
  return 1
}
live_spec() {  # ROUTE VGC PLUGIN WORK
  case "$1" in
    exec) spec="exec:$2 serve --impl plugin:$3" ;;
    verse) start_verse_host "$2" "$3" 127.0.0.1:0 "$4/host.log" || exit 1
           spec="verse:127.0.0.1:$host_port" ;;
    *) echo "live_host_lib: unknown route $1" >&2; exit 1 ;;
  esac
}
