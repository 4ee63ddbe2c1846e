#!/usr/bin/env bash
# concurrent_certify_test.sh VGC — certify runs started in the same second
# each get a run directory of their own, whole, and reports/latest always
# points at a whole run (issue 19, item 2).
#
# Four concurrent runs of the same seed (two of LAYER-BASE-1, two of
# LAYER-BASE-2) into one --reports directory must all exit 0 and print four
# distinct report paths, each holding its own run's report.json; then three
# sequential runs of the same seed within a second must leave three run
# directories. They used to share "<second>-seed1": two of the four exited 2
# with wrong "free space" advice and two printed one path.
set -uo pipefail
[ $# -ge 1 ] || { echo "usage: $0 VGC" >&2; exit 2; }
vgc=$1
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_concurrent_certify.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "concurrent_certify: $*" >&2; exit 1; }

cd "$tmp" || exit 2
pids=()
for i in 1 2 3 4; do
  clause=LAYER-BASE-$(( (i + 1) / 2 ))
  "$vgc" certify --quiet --cases 20 --clauses "$clause" --reports R >"out$i" 2>"err$i" &
  pids+=($!)
done
for i in 1 2 3 4; do
  wait "${pids[$((i - 1))]}"; rc=$?
  [ $rc = 0 ] || { cat "out$i" "err$i" >&2; fail "run $i exited $rc, expected 0"; }
done
paths=()
for i in 1 2 3 4; do
  p=$(sed -n 's/^report: \(.*\)\/summary.md$/\1/p' "out$i")
  [ -n "$p" ] || { cat "out$i" >&2; fail "run $i printed no report path"; }
  for f in report.json summary.md report.html junit.xml; do
    [ -s "$p/$f" ] || fail "run $i: $p/$f missing or empty"
  done
  clause=LAYER-BASE-$(( (i + 1) / 2 ))
  grep -q "\"$clause\"" "$p/report.json" || fail "run $i: $p/report.json is not its run's report (no $clause)"
  other=LAYER-BASE-$(( 3 - (i + 1) / 2 ))
  ! grep -q "\"$other\"" "$p/report.json" || fail "run $i: $p/report.json holds $other: another run's report"
  paths+=("$p")
done
n=$(printf '%s\n' "${paths[@]}" | sort -u | wc -l)
[ "$n" = 4 ] || { printf '%s\n' "${paths[@]}" >&2; fail "$n distinct run directories for 4 runs"; }
[ -s R/latest/report.json ] || fail "R/latest does not point at a whole run"
leftover=$(find R -name '*.partial*' | head -1)
[ -z "$leftover" ] || fail "left behind $leftover"

for i in 5 6 7; do
  "$vgc" certify --quiet --cases 5 --clauses LAYER-BASE-1 --reports S >"out$i" 2>"err$i" || { cat "err$i" >&2; fail "sequential run $i failed"; }
done
n=$(ls -d S/reference/*/ | wc -l)
[ "$n" = 3 ] || { ls -la S/reference >&2; fail "$n run directories after three sequential runs, expected 3"; }
echo "concurrent_certify: four concurrent runs, four whole run directories; three sequential runs, three"
