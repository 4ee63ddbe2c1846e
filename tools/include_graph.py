#!/usr/bin/env python3
"""include_graph.py [SOURCE_DIR] — the project's include graph, checked.

The layers are one-way (README "Layout"): runtime (the coverage runtime
linked into implementations, C, standard library only) -> reference/node -> reference/geometry
-> verse -> conformance -> oracles -> fuzz/targets and bench (side by side)
-> fuzz/campaign -> fuzz/wire -> cli (fuzz/'s three rooms, one-way). A product file may include a project header of its own layer or of a
lower one, never of a higher one; and no two files may include each other,
directly or through others (a cycle). Tests, examples and plugins sit above
everything and are not checked.

Prints each violation as FILE:LINE: and the reason, then a one-line
summary; exit 1 when there is any, 0 otherwise. Only `#include "..."`
lines count; a header is found next to the including file, then in every
product folder (as the CMake include paths do).
"""
import os
import re
import sys
from pathlib import Path

LAYERS = [
    ("runtime",),
    ("reference/node",),
    ("reference/geometry",),
    ("verse",),
    ("conformance", "conformance/adapter", "conformance/report", "conformance/gen"),
    ("oracles",),
    ("fuzz/targets", "bench"),
    ("fuzz/campaign",),
    ("fuzz/wire",),
    ("cli",),
]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def folder_layer(folder):
    for i, folders in enumerate(LAYERS):
        if folder in folders:
            return i
    return None


def product_files(root):
    out = []
    for folders in LAYERS:
        for folder in folders:
            d = root / folder
            if d.is_dir():
                out += sorted(p for p in d.iterdir() if p.suffix in (".h", ".cpp", ".c", ".inc") and p.is_file())
    return out


def resolve(root, including, name, by_name):
    here = including.parent / name
    if here.is_file():
        return here.resolve()
    candidates = by_name.get(name, [])
    return candidates[0] if len(candidates) == 1 else (candidates[0] if candidates else None)


def main():
    root = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent).resolve()
    files = product_files(root)
    by_name = {}
    for f in files:
        rel = f.relative_to(root)
        by_name.setdefault(f.name, []).append(f.resolve())
        by_name.setdefault(str(rel.relative_to(rel.parts[0])) if len(rel.parts) > 1 else f.name, []).append(f.resolve())
    edges = {}
    problems = []
    for f in files:
        src_layer = folder_layer(str(f.parent.relative_to(root)))
        for number, line in enumerate(f.read_text(errors="replace").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            target = resolve(root, f, m.group(1), by_name)
            if target is None:
                continue  # generated or a system header in quotes
            to_layer = folder_layer(str(target.parent.relative_to(root)))
            edges.setdefault(f.resolve(), set()).add(target)
            if to_layer is not None and src_layer is not None and to_layer > src_layer:
                problems.append(f"{f.relative_to(root)}:{number}: includes {target.relative_to(root)}, "
                                f"a higher layer ({LAYERS[to_layer][0]} is above {LAYERS[src_layer][0]})")
    # Cycles among headers (a .cpp is never included).
    state = {}
    stack = []

    def visit(node):
        state[node] = 1
        stack.append(node)
        for nxt in sorted(edges.get(node, ())):
            if state.get(nxt) == 1:
                cycle = stack[stack.index(nxt):] + [nxt]
                problems.append("include cycle: " + " -> ".join(str(c.relative_to(root)) for c in cycle))
            elif nxt not in state:
                visit(nxt)
        stack.pop()
        state[node] = 2

    for node in sorted(edges):
        if node not in state:
            visit(node)
    for p in problems:
        print(p)
    print(f"include graph: {len(files)} product files, {sum(len(v) for v in edges.values())} project includes, "
          f"{len(problems)} violation(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
