#!/usr/bin/env python3
"""A well-behaved exec implementation that stresses the suite's plumbing:
it writes 1 MiB to stderr before each answer (the suite must drain stderr
or both deadlock), ends its lines in "\r\n", accepts every command, and its
documents are those of a fresh node.
tests/adapter/exec_faults_test.cpp: every call is Ok."""
import sys

noise = ("x" * 1023 + "\n") * 1024
for line in sys.stdin:
    line = line.rstrip("\r\n")
    sys.stderr.write(noise)
    sys.stderr.flush()
    if line == "?hello":
        out = "vgc-exec 1 polite-noise"
    elif line == "?quit":
        break
    elif line == "?snapshot":
        out = "vgc-snapshot 1\r\nend"
    elif line == "?derived":
        out = "vgc-derived 1\r\nend"
    else:
        out = "ok"
    sys.stdout.write(out + "\r\n")
    sys.stdout.flush()
