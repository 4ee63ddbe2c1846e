#!/usr/bin/env bash
# budget_cpu_test.sh VGC — --budget counts CPU seconds of vgc and the
# implementation it started, not the wall clock (issue 31: the same
# implementation gets the same verdict on an idle or a loaded machine;
# conformance/run_budget.h).
#  1. An implementation that is slow without computing (slow_answers_proxy.py
#     waits 10 ms before each answer of `vgc serve`, as a loaded machine
#     makes a program slow) is certified with --budget 8: the run takes more
#     than 8 s of wall clock (20 s or more) and is still conformant, exit 0.
#     With a wall-clock budget it was incomplete, exit 2 ("the budget ran
#     out").
#  2. The budget still stops a run that computes: the reference, 3000 cases
#     per property, --budget 0.2: incomplete, exit 2, and the note says the
#     CPU budget ran out.
set -u
vgc=$1
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_budget.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "budget_cpu: $*" >&2; exit 1; }

"$vgc" certify --quiet --impl "exec:python3 $here/slow_answers_proxy.py 0.01 $vgc serve" --clauses 'LAYER-*' \
  --cases 20 --budget 8 --reports "$tmp/slow" >"$tmp/slow.out" 2>&1
rc=$?
python3 - "$tmp/slow/latest/report.json" "$rc" <<'PY' || { tail -n 5 "$tmp/slow.out" >&2; fail "the slow implementation (above)"; }
import json, sys
r = json.load(open(sys.argv[1])); rc = int(sys.argv[2])
assert r["seconds"] > 8, "the run took %.1f s: not slower than the budget, nothing was shown" % r["seconds"]
assert rc == 0 and r["verdict"] == "conformant", "exit %d, verdict %s after %.1f s of wall clock: %s" % (
    rc, r["verdict"], r["seconds"], [c["note"] for c in r["clauses"] if c["status"] == "unchecked"][:2])
print("budget_cpu: a slow implementation, %.1f s of wall clock against --budget 8: conformant" % r["seconds"])
PY
[ $? -eq 0 ] || exit 1

"$vgc" certify --quiet --cases 3000 --budget 0.2 --reports "$tmp/busy" >"$tmp/busy.out" 2>&1
rc=$?
[ "$rc" -eq 2 ] || { tail -n 5 "$tmp/busy.out" >&2; fail "a run past its CPU budget exited $rc, expected 2"; }
grep -q 'CPU seconds of vgc and the implementation) ran out' "$tmp/busy/latest/summary.md" ||
  fail "the summary does not say the CPU budget ran out: $(grep -m1 -i budget "$tmp/busy/latest/summary.md")"
echo "budget_cpu: --budget 0.2 stopped a run that computes (incomplete, exit 2)"
