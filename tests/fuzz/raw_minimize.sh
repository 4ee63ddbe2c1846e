#!/usr/bin/env bash
# raw_minimize.sh VGC CLANG WORK_DIR — a finding of a raw-bytes target (one
# that names no clause: a sanitizer crash in fuzz_text, fuzz_stream,
# fuzz_verse_packet, fuzz_mesh_*) has its input minimized with libFuzzer's
# -minimize_crash before it is written (issue 19, item 9). A real libFuzzer
# target built here (data/crash_on_pattern.c: ASan heap-buffer-overflow on
# "BUG!" anywhere in the input) stands in for fuzz_text; its campaign saves
# 24 2,000-byte inputs with the pattern buried at different places. `vgc
# fuzz text` must report one finding whose written counterexample is much
# smaller than the input, still holds the pattern, still crashes the target
# the same way, and whose summary says how much it was minimized. Before
# this, the 2,000-byte input was written as it was. Every start of the
# target is slowed down, as on a loaded machine: the result must not change.
. "$(dirname "$0")/stand_in_lib.sh" raw_minimize "$1" "$3"
clang=$2
real="$work/crash_on_pattern"
"$clang" -g -O1 -fsanitize=fuzzer,address "$(dirname "$0")/data/crash_on_pattern.c" -o "$real" ||
  fail "cannot build the faulty libFuzzer target with $clang"
python3 - "$work" <<'PY'
import random, sys
r = random.Random(19)
for k in range(24):
    name, at = "crash-%02d" % k, 60 + 80 * k
    body = bytearray(r.choice(b"abcdefghijklmnopqrstuvwxyz \n") for _ in range(2000))
    body[at:at + 4] = b"BUG!"
    open(sys.argv[1] + "/" + name, "wb").write(bytes(body))
PY
cat >"$work/fuzz/fuzz_text" <<SCRIPT
#!/usr/bin/env bash
for a in "\$@"; do
  case "\$a" in -artifact_prefix=*) prefix=\${a#-artifact_prefix=} ;; -fork=*) campaign=1 ;; esac
done
if [ -n "\${campaign:-}" ]; then
  cp "$work"/crash-[0-9][0-9] "\$prefix"
  echo "#2	DONE   cov: 10 ft: 20 corp: 1/9b exec/s: 2 rss: 30Mb"
  exit 0
fi
sleep 0.5  # a loaded machine: every start of the target is slow
exec "$real" "\$@"
SCRIPT
chmod +x "$work/fuzz/fuzz_text"
out=$("$vgc" fuzz text --time 1 --fuzz-build "$work" --source-dir "$work/src" 2>&1)
rc=$?
[ "$rc" -eq 1 ] || { printf '%s\n' "$out" | tail -20; fail "expected exit 1 (a finding), got $rc"; }
summary=$(ls "$work"/src/reports/fuzz/fuzz_text/*/summary.json) || fail "no summary.json"
cex=$(ls "$work"/src/reports/fuzz/fuzz_text/*/counterexamples/crash-1.txt) || fail "no counterexample"
python3 - "$summary" "$cex" <<'PY' || exit 1
import json, os, sys
s = json.load(open(sys.argv[1]))
c = s["crashes"]
assert len(c) == 1, "expected one finding, got %d: %s" % (len(c), [x["signature"] for x in c])
c = c[0]
# Signing re-runs each of the 24 inputs: 12 s of wall clock here, which
# the old wall-clock budget (10 s) cut short; the budget is CPU time now.
assert s["crash_inputs_signed"] == 24, "signed %s of 24 inputs (stopped by %r)" % (s["crash_inputs_signed"], s.get("signing_stopped_by"))
assert c["inputs"] == 24, "expected all 24 inputs in it, got %s" % c["inputs"]
assert "heap-buffer-overflow" in c["signature"], c["signature"]
size = os.path.getsize(sys.argv[2])
# Each start of the target takes half a second here, as on a loaded
# machine: the minimization is bounded by steps and mutations, not by wall
# time, so it still ends where libFuzzer can shrink no further, the 4 bytes
# of the pattern (it used to stop where a share of the signing budget's
# wall clock ran out, larger under load).
body = open(sys.argv[2], "rb").read()
assert body == b"BUG!", "the written counterexample has %d bytes, not the 4 of the pattern: %r" % (size, body[:80])
m = c.get("minimized")
assert m, "summary.json does not say the input was minimized: %s" % c
assert m["from_bytes"] == 2000 and m["to_bytes"] == size, m
assert os.path.getsize(m["input"]) == size, m
assert "no smaller input fails" in c["minimize_note"], c["minimize_note"]
assert "minimized from 2000 to" in open(os.path.join(os.path.dirname(sys.argv[1]), "summary.md")).read()
PY
# The written input still crashes the real target the same way.
again=$("$real" "$cex" 2>&1) && fail "the minimized counterexample no longer crashes"
printf '%s\n' "$again" | grep -q 'AddressSanitizer: heap-buffer-overflow' ||
  { printf '%s\n' "$again" | tail -5; fail "the minimized counterexample crashes differently"; }
echo "raw_minimize: one finding of 24 inputs, all signed, its 2000-byte input minimized to $(stat -c %s "$cex") bytes"
