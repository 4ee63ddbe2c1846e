#!/usr/bin/env python3
"""slow_or_huge.py MODE [N] — a minimal exec program (an empty node) that is
slow to start or says too much, by MODE:

  slow_hello N   sleeps N seconds before it answers ?hello (a loaded CI
                 runner starting a Python program or a JVM), then is fine
  huge N         answers every command `rejected ` + N bytes of "A", says
                 it is N bytes of "B" in ?hello, and puts a line of N bytes
                 of "C" in its snapshot

tests/adapter/exec_limits_test.cpp: the start has its own limit
(--start-timeout), and what vgc keeps of a huge answer is cut, with its
size said (bounded_text.h)."""
import sys
import time

mode = sys.argv[1]
arg = sys.argv[2] if len(sys.argv) > 2 else "0"
n = int(arg) if mode == "huge" else 0
out = sys.stdout
for line in sys.stdin:
    line = line.rstrip("\n")
    if line == "?hello":
        if mode == "slow_hello":
            time.sleep(float(arg))
        out.write("vgc-exec 1 " + ("B" * n if mode == "huge" else "slow-or-huge") + "\n")
    elif line == "?reset":
        out.write("ok\n")
    elif line == "?snapshot":
        out.write("vgc-snapshot 1\n" + ("C" * n + "\n" if mode == "huge" else "") + "end\n")
    elif line == "?derived":
        out.write("vgc-derived 1\nend\n")
    elif line == "?quit":
        break
    elif line.startswith("?"):
        out.write("error unknown request " + line + "\n")
    else:
        out.write("rejected " + "A" * n + "\n" if mode == "huge" else "ok\n")
    out.flush()
