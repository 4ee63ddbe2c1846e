#!/usr/bin/env python3
"""subdivision_skew_proxy.py VGC — an exec implementation whose Catmull-Clark
subdivision is wrong: it forwards every line to a child `VGC serve` (the
reference) and relays the answers, except that in the answer to
`?subdivide N` the x of every 7th refined vertex is moved by 0.25. A
stand-in for a node whose subdivision code is broken on real meshes
(tests/ci/certify_mesh_test.sh).

With VGC_PROXY_SLOW=SECONDS it skews nothing: it answers `?subdivide 2`
SECONDS late (a host too slow for vgc's --timeout, whose answer is right).

With VGC_PROXY_DIGEST_HANG=1 it claims ?digest (the reference's
?capabilities) but never answers it: `certify --mesh` asks no ?digest, so
`vgc replay` of its counterexample must not either (issue 31 item 5)."""
import os
import subprocess
import sys
import time

slow = float(os.environ.get("VGC_PROXY_SLOW", "0"))
digest_hang = os.environ.get("VGC_PROXY_DIGEST_HANG") == "1"

child = subprocess.Popen([sys.argv[1], "serve"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1)
for line in sys.stdin:
    if digest_hang and line.strip() == "?digest":
        time.sleep(3600)
    child.stdin.write(line)
    child.stdin.flush()
    request = line.strip()
    skew = request.startswith("?subdivide ") and not slow
    if slow and request == "?subdivide 2":
        time.sleep(slow)
    single = request in ("?hello", "?reset", "?quit") or not request.startswith("?")
    answer = child.stdout.readline()
    if not answer:
        sys.exit(3)
    out = [answer]
    k = 0
    while not single and not answer.startswith("error") and answer.strip() != "end":
        answer = child.stdout.readline()
        if not answer:
            sys.exit(3)
        if skew and answer.startswith("vertex "):
            k += 1
            if k % 7 == 0:
                w = answer.split()
                w[1] = repr(float(w[1]) + 0.25)
                answer = " ".join(w) + "\n"
        out.append(answer)
    sys.stdout.write("".join(out))
    sys.stdout.flush()
    if request == "?quit":
        break
