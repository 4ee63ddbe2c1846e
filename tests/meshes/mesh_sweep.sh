#!/usr/bin/env bash
# mesh_sweep.sh [--levels N] [--timeout S] [--routes LIST] [--verse-max-faces F] VGC MESH...
# — certify every mesh on each route of LIST (comma-separated, default
# in-process,exec): `in-process` the reference in process, `exec` through
# exec:'VGC serve', `verse` over the Verse wire against one `VGC serve
# --verse` started for the sweep (meshes of at most F faces, default 20000;
# larger ones show "-"). One line per mesh: name, vertices, faces, each
# route's verdict and wall seconds (docs/certify.md "Sweeping a corpus").
# Meshes with faces of 5+ corners are read with --triangulate. Exit 0 when
# every mesh is conformant on every route it ran, 1 otherwise (the lines
# say which), 2 for bad arguments or a Verse host that does not start.
set -uo pipefail
levels=2 timeout=5 routes=in-process,exec verse_max=20000
while [ $# -gt 0 ]; do
  case $1 in
    --levels) levels=$2; shift 2 ;;
    --timeout) timeout=$2; shift 2 ;;
    --routes) routes=$2; shift 2 ;;
    --verse-max-faces) verse_max=$2; shift 2 ;;
    *) break ;;
  esac
done
usage="usage: $0 [--levels N] [--timeout S] [--routes in-process,exec,verse] [--verse-max-faces F] VGC MESH..."
[ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }
IFS=, read -r -a route_list <<<"$routes"
for r in "${route_list[@]}"; do
  case $r in in-process|exec|verse) ;; *) echo "$0: unknown route '$r'; $usage" >&2; exit 2 ;; esac
done
vgc=$1; shift
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_mesh_sweep.XXXXXX")
host_pid=
cleanup() { [ -n "$host_pid" ] && kill "$host_pid" 2>/dev/null; rm -rf "$tmp"; }
trap cleanup EXIT
verse_impl=
if [[ ",$routes," == *,verse,* ]]; then
  "$vgc" serve --verse 127.0.0.1:0 >"$tmp/host.out" 2>"$tmp/host.err" &
  host_pid=$!
  for _ in $(seq 100); do
    grep -q '^vgc-verse listening' "$tmp/host.out" 2>/dev/null && break
    sleep 0.1
  done
  port=$(sed -n 's/^vgc-verse listening .*:\([0-9]*\)$/\1/p' "$tmp/host.out")
  [ -n "$port" ] || { echo "$0: vgc serve --verse did not start: $(cat "$tmp/host.err")" >&2; exit 2; }
  verse_impl="verse:127.0.0.1:$port"
fi
header=$(printf '%-28s %8s %8s' mesh vertices faces)
for r in "${route_list[@]}"; do header+=$(printf '  %-15s %7s' "$r" s); done
echo "$header"
bad=0
route() {  # route MESH IMPL: "<verdict> <seconds>"
  local t0 t1 rc verdict
  t0=$(date +%s.%N)
  "$vgc" certify --mesh "$1" --triangulate --levels "$levels" --timeout "$timeout" --impl "$2" \
    --reports "$tmp/reports" >"$tmp/out" 2>&1
  rc=$?
  t1=$(date +%s.%N)
  verdict=$(sed -n 's/^.*: \(conformant\|not conformant\|incomplete\) on .*/\1/p' "$tmp/out" | tail -1)
  [ -n "$verdict" ] || verdict="error(rc=$rc)"
  printf '%s %.1f' "${verdict// /-}" "$(awk "BEGIN { print $t1 - $t0 }")"
  [ "$rc" = 0 ] || cp "$tmp/out" "$tmp/last_failure"
  return "$rc"
}
for m in "$@"; do
  counts=$("$vgc" import --triangulate "$m" 2>/dev/null | head -1 |
    sed -n 's/.*: \([0-9]*\) vertices, \([0-9]*\) triangles, \([0-9]*\) quads/\1 \2 \3/p')
  if [ -z "$counts" ]; then  # not a polygon mesh vgc reads (a point cloud): said, not certified
    printf '%-28s %8s %8s  refused: %s\n' "$(basename "$m")" - - \
      "$("$vgc" import --triangulate "$m" 2>&1 >/dev/null | sed 's/^[^ ]* error: //' | cut -c1-70)"
    continue
  fi
  read -r nv nt nq <<<"$counts"
  faces=$((nt + nq))
  line=$(printf '%-28s %8s %8s' "$(basename "$m")" "$nv" "$faces")
  for r in "${route_list[@]}"; do
    case $r in
      in-process) impl=reference ;;
      exec) impl="exec:$vgc serve" ;;
      verse) impl=$verse_impl ;;
    esac
    if [ "$r" = verse ] && [ "$faces" -gt "$verse_max" ]; then
      line+=$(printf '  %-15s %7s' - -)
      continue
    fi
    out=$(route "$m" "$impl") || bad=$((bad + 1))
    read -r v t <<<"$out"
    line+=$(printf '  %-15s %7s' "$v" "$t")
  done
  echo "$line"
done
[ "$bad" = 0 ] || { echo "mesh_sweep: $bad route(s) not conformant; the last one's output:" >&2; cat "$tmp/last_failure" >&2; exit 1; }
