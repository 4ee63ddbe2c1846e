#!/usr/bin/env python3
"""impl_coverage_by_file.py RUN_DIR [FILE...] — the implementation's counters
reached per source file, from the coverage records of a `vgc fuzz` run
(RUN_DIR/implementation_coverage/*.txt: fuzz/targets/coverage_record.h; the
records of `vgc fuzz differential` and of `vgc fuzz wire --host-cmd`).

Spec: docs/fuzzing.md "Against the r6 host, guided by its own coverage".

Every record of the run is merged (a counter reached by any process of the
run is reached). A counter belongs to the function whose entry counter is
the last at or before it in its module (SanitizerCoverage numbers a
function's counters together, its entry first); each function entry's PC
(the record's `function` lines: module, offset from the module's load
address) is named by llvm-symbolizer (Debian's `llvm`) with its source
file. So the implementation must have been built with `pc-table` (and -g
for file names). Prints one line per source file, `file counters reached`,
sorted by file; with FILE arguments (base names, e.g. vs_node_geometry.c),
those files only and a line `total` of them. Exit 2 when the run has no
record or no function entries.
"""
import glob
import os
import subprocess
import sys


def read_record(path):
    rec = {"modules": [], "functions": [], "reached": "", "counters": 0}
    with open(path) as f:
        for line in f:
            key, _, rest = line.rstrip("\n").partition(" ")
            if key == "counters":
                rec["counters"] = int(rest)
            elif key == "module":
                rec["modules"].append(rest.split(" (")[0])
            elif key == "reached":
                rec["reached"] = rest
            elif key == "function":
                i, m, off = rest.split()
                rec["functions"].append((int(i), int(m), int(off, 16)))
    return rec


def bits(hexmap, n):
    """Bit i of the map (hex, counter i's bit; coverage_record.cpp's order)."""
    out = [False] * n
    for k, ch in enumerate(hexmap):
        v = int(ch, 16)
        for b in range(4):
            i = k * 4 + b
            if i < n and v & (1 << b):
                out[i] = True
    return out


def merge_records(records):
    """The counters any of `records` reached, and the record with the most
    function entries (whose PC table names them)."""
    n = max(r["counters"] for r in records)
    reached = [False] * n
    for r in records:
        for i, b in enumerate(bits(r["reached"], r["counters"])):
            reached[i] = reached[i] or b
    return reached, max(records, key=lambda r: len(r["functions"]))


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    run, wanted = sys.argv[1], [os.path.basename(a) for a in sys.argv[2:]]
    records = [read_record(p) for p in sorted(glob.glob(os.path.join(run, "implementation_coverage", "*.txt")))]
    records = [r for r in records if r["counters"] and r["functions"]]
    if not records:
        print("impl_coverage_by_file: no record with function entries under %s/implementation_coverage" % run,
              file=sys.stderr)
        return 2
    reached, base = merge_records(records)
    n = len(reached)
    modules, functions = base["modules"], sorted(base["functions"])
    # Name each entry's file: one llvm-symbolizer per module.
    files = {}
    for m, path in enumerate(modules):
        offs = [off for (_, mm, off) in functions if mm == m]
        if not offs:
            continue
        text = "\n".join("0x%x" % o for o in offs) + "\n"
        out = subprocess.run(["llvm-symbolizer", "--obj=" + path, "--functions=none"], input=text,
                             capture_output=True, text=True).stdout
        lines = [l for l in out.split("\n\n") if l.strip()]
        for off, block in zip(offs, lines):
            loc = block.strip().split("\n")[0]
            files[(m, off)] = os.path.basename(loc.split(":")[0]) if loc and not loc.startswith("??") else "?"
    per_file = {}
    for k, (idx, m, off) in enumerate(functions):
        end = functions[k + 1][0] if k + 1 < len(functions) and functions[k + 1][1] == m else n
        f = files.get((m, off), "?")
        c, r = per_file.get(f, (0, 0))
        per_file[f] = (c + (end - idx), r + sum(reached[idx:end]))
    names = wanted or sorted(per_file)
    tc = tr = 0
    for f in names:
        c, r = per_file.get(f, (0, 0))
        tc, tr = tc + c, tr + r
        print("%s %d %d" % (f, c, r))
    if wanted:
        print("total %d %d" % (tc, tr))
    return 0


if __name__ == "__main__":
    sys.exit(main())
