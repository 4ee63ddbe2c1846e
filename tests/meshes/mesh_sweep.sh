#!/usr/bin/env bash
# mesh_sweep.sh [--levels N] [--timeout S] VGC MESH... — certify every mesh
# with the reference in process and through exec:'VGC serve', one line per
# mesh: name, vertices, faces, each route's verdict and wall seconds
# (docs/certify.md "Sweeping a corpus"). Meshes with faces of 5+ corners
# are read with --triangulate. Exit 0 when every mesh is conformant on both
# routes, 1 otherwise (the lines say which).
set -uo pipefail
levels=2 timeout=5
while [ $# -gt 0 ]; do
  case $1 in
    --levels) levels=$2; shift 2 ;;
    --timeout) timeout=$2; shift 2 ;;
    *) break ;;
  esac
done
[ $# -ge 2 ] || { echo "usage: $0 [--levels N] [--timeout S] VGC MESH..." >&2; exit 2; }
vgc=$1; shift
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_mesh_sweep.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
printf '%-28s %8s %8s  %-15s %7s  %-15s %7s\n' mesh vertices faces in-process s exec s
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
  a=$(route "$m" reference) || bad=$((bad + 1))
  b=$(route "$m" "exec:$vgc serve") || bad=$((bad + 1))
  read -r va ta <<<"$a"; read -r vb tb <<<"$b"
  printf '%-28s %8s %8s  %-15s %7s  %-15s %7s\n' "$(basename "$m")" "$nv" "$((nt + nq))" "$va" "$ta" "$vb" "$tb"
done
[ "$bad" = 0 ] || { echo "mesh_sweep: $bad route(s) not conformant; the last one's output:" >&2; cat "$tmp/last_failure" >&2; exit 1; }
