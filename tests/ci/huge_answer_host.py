#!/usr/bin/env python3
"""huge_answer_host.py VGC N BYTES — an exec implementation whose answers grow
huge after N commands since it started (issue 31: resource exhaustion looks
like this): it forwards every line to a child `VGC serve` (the reference)
and relays the answers, counting the command lines it forwarded (requests
starting with '?' are not counted). Once N commands have gone through, every
later command is answered `rejected ` followed by BYTES bytes of "A", one
line, whatever the command. A fresh start counts from 0 again.

vgc must keep what it copies of such an answer bounded (bounded_text.h):
tests/ci/bounded_copies_test.sh checks the run directory's size and vgc's
memory."""
import sys

from reference_child import ReferenceChild

vgc, limit, size = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
child = ReferenceChild(vgc)
huge = "rejected " + "A" * size + "\n"
count = 0
out = sys.stdout
for line in sys.stdin:
    if not line.startswith("?"):
        if count >= limit:
            out.write(huge)
            out.flush()
            continue
        count += 1
    child.relay(line, out)
    if line.strip() == "?quit":
        break
