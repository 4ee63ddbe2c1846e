#!/usr/bin/env python3
"""costly_ids_proxy.py VGC FLOOR [SERVE ARGS...] — an exec implementation that
never answers a command naming a vertex id of FLOOR or more (a stand-in for
a node whose storage is dense: one sparse id makes millions of slots and
every call after it outlasts the call limit; issue 31 item 8). Every other
line goes to a child `VGC serve` (the reference) and its answer comes back.

The vertex ids of a command, in the text language (docs/commands.md):
vertex_set_xyz_real32/64 LAYER ID ..., vertex_set_uint32/real32/real64
LAYER ID ..., vertex_delete ID, and the four corners of
polygon_set_corner_uint32 1 POLYGON V0 V1 V2 V3. 4294967295 (0xFFFFFFFF) is
no id: "pick one" for a vertex, "unused" for a corner.

With VGC_PROXY_HANG_LOG=FILE, each command it hangs on is appended to FILE
first: how many time-outs a run paid, whatever the machine's load."""
import os
import sys
import time

from reference_child import ReferenceChild

vgc, floor = sys.argv[1], int(sys.argv[2])
child = ReferenceChild(vgc, sys.argv[3:])


def vertex_ids(words):
    if not words:
        return []
    verb = words[0]
    try:
        if verb == "vertex_delete":
            ids = [int(words[1], 0)]
        elif verb.startswith("vertex_set_"):
            ids = [int(words[2], 0)]
        elif verb == "polygon_set_corner_uint32" and int(words[1], 0) == 1:
            ids = [int(w, 0) for w in words[3:7]]
        else:
            ids = []
    except (IndexError, ValueError):
        return []
    return [i for i in ids if i != 0xFFFFFFFF]


for line in sys.stdin:
    if not line.startswith("?") and any(v >= floor for v in vertex_ids(line.split())):
        if os.environ.get("VGC_PROXY_HANG_LOG"):
            with open(os.environ["VGC_PROXY_HANG_LOG"], "a") as log:
                log.write(line)
        while True:
            time.sleep(60)
    child.relay(line)
    if line.strip() == "?quit":
        break
