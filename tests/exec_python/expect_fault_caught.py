#!/usr/bin/env python3
"""Runs `vgc certify` on vgc_node.py with one seeded fault switched on
(VGC_PY_FAULT) and asserts that certification fails (exit 1) and that the
summary reports that clause as failing (its row in the clause table reads
`| CLAUSE | LEVEL | fail |`; a mere mention is not enough, since a
conformant summary lists every clause too).

Usage: expect_fault_caught.py VGC NODE_PY REPORTS_DIR FAULT CLAUSE
Exit 0 when both hold, 1 otherwise (with the reason on stderr).
"""
import os
import re
import subprocess
import sys


def main(argv):
    if len(argv) != 6:
        sys.stderr.write(__doc__)
        return 2
    vgc, node, reports, fault, clause = argv[1:]
    env = dict(os.environ, VGC_PY_FAULT=fault)
    # --strict: the fault's clause (POLY-DISTINCT-1) is IMPLEMENTATION-DEFINED,
    # a profile difference that gates only when asked to.
    cmd = [vgc, "certify", "--strict", "--timeout", "30", "--impl", "exec:%s %s" % (sys.executable, node),
           "--quiet", "--cases", "100", "--reports", reports]
    rc = subprocess.run(cmd, env=env).returncode
    if rc != 1:
        sys.stderr.write("expected certify to exit 1 (not-conformant) with fault %s, got %d\n" % (fault, rc))
        return 1
    summary = os.path.join(reports, "latest", "summary.md")
    try:
        with open(summary, encoding="utf-8", errors="replace") as f:
            text = f.read()
    except OSError as e:
        sys.stderr.write("cannot read %s: %s\n" % (summary, e))
        return 1
    row = re.compile(r"^\| %s \| [^|]+ \| fail \| \d+ \|$" % re.escape(clause), re.M)
    if not row.search(text):
        sys.stderr.write("%s does not report %s as failing (fault %s)\n" % (summary, clause, fault))
        return 1
    print("fault %s caught: certify exit 1, summary reports %s failing" % (fault, clause))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
