#!/usr/bin/env bash
# bounded_copies_test.sh VGC — what vgc copies of an implementation's
# answers into its outputs is bounded (issue 31, item 5; bounded_text.h).
# huge_answer_host.py answers `rejected <BYTES of A>` (50 MiB by default,
# BYTES=N to change it) to every command after its 300th since it started.
# The run must end with a verdict (exit 1 or 2, no crash), its run
# directory must stay under 10 MB and its stdout under 1 MB, vgc's own peak
# resident memory (VmHWM, sampled) under 400 MB, and the cut must say how
# big the answer was ("52,428,800 bytes, first 4 KiB shown"). A baseline
# whose reason is 5 MB long is copied into report.json cut the same way.
# (Before: 500 MB on stdout and in each report file, 50 MB per
# counterexample file, 3.4 GB resident.)
set -uo pipefail
[ $# -ge 1 ] || { echo "usage: $0 VGC" >&2; exit 2; }
vgc=$1
bytes=${BYTES:-52428800}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_bounded.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 2
fail() { echo "bounded_copies: $*" >&2; exit 1; }

python3 -c "import sys; sys.stdout.write('LAYER-BASE-2 ' + 'R' * 5000000 + '\n')" >baseline.txt
"$vgc" certify --quiet --cases 40 --clauses 'LAYER-*' --baseline baseline.txt \
  --impl "exec:$here/huge_answer_host.py $vgc 300 $bytes" --reports R >out 2>err &
pid=$!
hwm=0
while kill -0 "$pid" 2>/dev/null; do
  h=$(awk '/^VmHWM:/ {print $2}' "/proc/$pid/status" 2>/dev/null)
  [ -n "$h" ] && [ "$h" -gt "$hwm" ] && hwm=$h
  sleep 0.1
done
wait "$pid"; rc=$?
[ $rc = 1 ] || [ $rc = 2 ] || { tail -c 2000 err >&2; fail "exit $rc, expected a verdict (1 or 2)"; }
run=$(readlink -f R/latest)
[ -f "$run/report.json" ] || { tail -c 2000 err >&2; fail "no report written"; }
size=$(du -sb "$run" | cut -f1)
stdout_size=$(stat -c %s out)
echo "bounded_copies: exit $rc, run directory $size bytes, stdout $stdout_size bytes, vgc's peak RSS $((hwm / 1024)) MB"
[ "$size" -lt 10000000 ] || { du -ab "$run" | sort -n | tail -n 5 >&2; fail "the run directory has $size bytes (10 MB at most)"; }
[ "$stdout_size" -lt 1000000 ] || fail "stdout has $stdout_size bytes (1 MB at most)"
[ "$hwm" -gt 0 ] && [ "$hwm" -lt 409600 ] || fail "vgc's peak resident memory was $hwm kB (400 MB at most)"
shown=$(python3 -c "print(f'{int(\"$bytes\"):,}')")  # 52,428,800
grep -q "$shown bytes, first 4 KiB shown" "$run/report.json" ||
  fail "report.json does not say how big the cut answer was ('$shown bytes, first 4 KiB shown')"
grep -q "5,000,000 bytes, first 4 KiB shown" "$run/report.json" ||
  fail "report.json does not hold the baseline's reason cut, with its size"
echo "bounded_copies: a ${bytes}-byte answer and a 5 MB baseline reason are copied cut, with their sizes"
