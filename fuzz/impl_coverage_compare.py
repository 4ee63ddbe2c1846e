#!/usr/bin/env python3
"""impl_coverage_compare.py [--files F,F,...] A_DIR... -- B_DIR... — which of
an implementation's functions one set of runs reached more of than another,
from their coverage records (RUN_DIR/implementation_coverage/*.txt, as
written by `vgc fuzz differential`, `vgc fuzz wire --host-cmd` and
fuzz/host_coverage_of.py).

Spec: docs/fuzzing.md "Against the r6 host, guided by its own coverage"
(the ceiling: the union of every arm against one arm).

The records of all A_DIRs are merged into one set of reached counters (a
counter reached by any of them is reached), the same for the B_DIRs; the
counters are grouped by function as fuzz/impl_coverage_by_file.py does (the
function whose entry counter is the last at or before a counter) and each
function is named with llvm-symbolizer (name, file, line). Prints, for the
files given (base names; default: every file), the total counters and those
reached by A, by B, by both and by A only, then one line per function where
A and B differ: `A-only B-only reached-by-A reached-by-B counters name file:line`,
most A-only first. The records must come from one build of the
implementation (same counters, same PC table).
"""
import os
import signal
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from impl_coverage_by_file import merge_records, read_record  # noqa: E402
import glob  # noqa: E402


def union(dirs):
    recs = []
    for d in dirs:
        recs += [read_record(p) for p in sorted(glob.glob(os.path.join(d, "implementation_coverage", "*.txt")))]
    recs = [r for r in recs if r["counters"]]
    if not recs:
        return None, None
    return merge_records(recs)


def main():
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # `| head` ends it quietly
    args = sys.argv[1:]
    files = None
    if args[:1] == ["--files"]:
        files = set(args[1].split(","))
        args = args[2:]
    if "--" not in args:
        print(__doc__, file=sys.stderr)
        return 2
    k = args.index("--")
    a, base = union(args[:k])
    b, base_b = union(args[k + 1:])
    if a is None or b is None or not base["functions"]:
        print("impl_coverage_compare: no records (or no function entries) on one side", file=sys.stderr)
        return 2
    n = min(len(a), len(b))
    functions = sorted(base["functions"])
    names = {}
    for m, path in enumerate(base["modules"]):
        offs = [off for (_, mm, off) in functions if mm == m]
        text = "\n".join("0x%x" % o for o in offs) + "\n"
        out = subprocess.run(["llvm-symbolizer", "--obj=" + path, "--functions=linkage"], input=text,
                             capture_output=True, text=True).stdout
        blocks = [x for x in out.split("\n\n") if x.strip()]
        for off, block in zip(offs, blocks):
            lines = block.strip().split("\n")
            name = lines[0]
            loc = lines[1] if len(lines) > 1 else "?"
            f, _, rest = loc.partition(":")
            names[(m, off)] = (name, os.path.basename(f), rest.split(":")[0])
    tot = [0, 0, 0, 0, 0]
    rows = []
    for k, (idx, m, off) in enumerate(functions):
        end = functions[k + 1][0] if k + 1 < len(functions) and functions[k + 1][1] == m else n
        name, f, line = names.get((m, off), ("?", "?", "?"))
        if files is not None and f not in files:
            continue
        ra = sum(a[idx:end])
        rb = sum(b[idx:end])
        aonly = sum(1 for i in range(idx, end) if a[i] and not b[i])
        bonly = sum(1 for i in range(idx, end) if b[i] and not a[i])
        tot = [tot[0] + end - idx, tot[1] + ra, tot[2] + rb, tot[3] + aonly, tot[4] + bonly]
        if aonly or bonly:
            rows.append((aonly, bonly, ra, rb, end - idx, name, "%s:%s" % (f, line)))
    print("counters %d  reached by A %d  by B %d  A only %d  B only %d  A/B %.2f" %
          (tot[0], tot[1], tot[2], tot[3], tot[4], tot[1] / tot[2] if tot[2] else 0))
    for r in sorted(rows, key=lambda r: (-r[0], r[1], r[6])):
        print("%4d %4d %4d %4d %4d  %s  %s" % r)
    return 0


if __name__ == "__main__":
    sys.exit(main())
