#!/usr/bin/env python3
"""history_proxy.py VGC MODE N [SERVE ARGS...] — an exec implementation that misbehaves
after N commands since it started, whatever they were: a stand-in for a
node with a leak or a counter (issue 19). It forwards every line to a child
`VGC serve` (the reference) and relays the answers, counting the command
lines it forwarded (requests starting with '?' are not counted). Once N
commands have gone through, the next command gets, by MODE (SERVE ARGS,
e.g. --impl plugin:PATH, go to `VGC serve`):

  crash    the proxy exits 1 (its child is left to the suite to stop)
  hang     no answer, ever (the proxy sleeps; the child stays alive)
  garbage  the answer "what?" (a protocol error)
  reject   the answer "rejected AAA...": a wrong verdict on whatever
           command (a store that refuses everything once it is full);
           $HISTORY_PROXY_REASON_BYTES bytes of A (default 16)

A fresh start counts from 0 again, so a short sequence from a fresh
instance never shows it. It also writes its pid and its child's pid to
$HISTORY_PROXY_PIDS when that is set (one "proxy PID child PID" line per
start), so a test can see whether they outlive the suite. In hang mode it
creates the file $HISTORY_PROXY_HANGING, when that is set, as it starts to
hang."""
import os
import sys
import time

from reference_child import ReferenceChild

vgc, mode, limit = sys.argv[1], sys.argv[2], int(sys.argv[3])
child = ReferenceChild(vgc, sys.argv[4:])
if os.environ.get("HISTORY_PROXY_PIDS"):
    with open(os.environ["HISTORY_PROXY_PIDS"], "a") as f:
        f.write(f"proxy {os.getpid()} child {child.process.pid}\n")
count = 0
for line in sys.stdin:
    if not line.startswith("?"):
        if count >= limit:
            if mode == "crash":
                sys.exit(1)
            if mode == "hang":
                if os.environ.get("HISTORY_PROXY_HANGING"):  # a test waits for this, not for a guessed time
                    open(os.environ["HISTORY_PROXY_HANGING"], "a").close()
                while True:
                    time.sleep(60)
            if mode == "garbage":
                print("what?", flush=True)
                continue
            if mode == "reject":
                reason = "A" * int(os.environ.get("HISTORY_PROXY_REASON_BYTES", "16"))
                print("rejected " + reason, flush=True)
                continue
        count += 1
    child.relay(line)
    if line.strip() == "?quit":
        break
