#!/usr/bin/env python3
"""slow_answers_proxy.py SECONDS CMD... — an exec implementation that is slow
without computing: it forwards each line to CMD (another exec
implementation) and waits SECONDS before passing each answer back, as a
program on a loaded machine or behind a slow link would. For
budget_cpu_test.sh."""
import subprocess, sys, time

delay = float(sys.argv[1])
child = subprocess.Popen(sys.argv[2:], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
for line in sys.stdin.buffer:
    child.stdin.write(line)
    child.stdin.flush()
    req = line.strip()
    answer = child.stdout.readline()
    out = [answer]
    # Documents (?snapshot, ?derived, ?capabilities) end with a line "end".
    if req.startswith(b"?") and req not in (b"?hello", b"?reset", b"?quit", b"?digest") and answer.strip() != b"end" \
            and not answer.startswith(b"error"):
        while True:
            more = child.stdout.readline()
            out.append(more)
            if not more or more.strip() == b"end":
                break
    time.sleep(delay)
    sys.stdout.buffer.write(b"".join(out))
    sys.stdout.buffer.flush()
    if req == b"?quit":
        break
