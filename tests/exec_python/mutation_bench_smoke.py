#!/usr/bin/env python3
"""mutation_bench_smoke.py PYTHON BENCH VGC WORK — the mutation bench in one
command on one mutant (tests/exec_python/CMakeLists.txt says which): the
bench must certify it at seed 1, find it killed by a clause, and write the
row and the score."""
import glob, json, os, shutil, subprocess, sys

python, bench, vgc, work = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
listing = subprocess.run([python, bench, "--vgc", vgc, "--list"], capture_output=True, text=True, check=True).stdout
line = [l for l in listing.splitlines() if l.split()[0] == "586"]
assert line and "comparison Eq -> NotEq" in line[0], "mutant 586 is now %r: renumber the test (see CMakeLists.txt)" % line
p = subprocess.run([python, bench, "--vgc", vgc, "--only", "586", "--widen", "", "--out", work],
                   capture_output=True, text=True)
print(p.stdout[-2000:], p.stderr[-2000:])
assert p.returncode == 0, "the bench exited %d" % p.returncode
run = glob.glob(os.path.join(work, "*", "results.tsv"))
assert len(run) == 1, run
rows = [json.loads(l) for l in open(run[0])]
assert len(rows) == 1 and rows[0]["index"] == 586, rows
assert rows[0]["outcome"] == "killed" and rows[0].get("by"), "mutant 586 was not killed: %s" % rows[0]
summary = open(os.path.join(os.path.dirname(run[0]), "summary.md")).read()
assert "**100.0 %**" in summary, summary[:800]
print("mutation bench smoke: mutant 586 (%s) killed by %s" % (rows[0]["detail"], rows[0]["by"]))
