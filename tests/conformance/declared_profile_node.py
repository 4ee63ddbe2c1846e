#!/usr/bin/env python3
# declared_profile_node.py — a small exec program (docs/adapters.md section
# 1) that stores the node as the reference does and computes nothing
# derived: it forwards every line to `vgc serve` except ?derived, which it
# answers with an empty derived document (no bone poses, no effective
# creases), and ?capabilities, which it answers itself, claiming no
# capability and declaring the profile words given on its command line.
#
#   declared_profile_node.py VGC_BINARY [WORD ...]
#     e.g. declared_profile_node.py build/cli/vgc profile:no-derived
#
# Spec: the derived-only clauses BONE-PARENT-1 and BONE-DOWNSTREAM-1 (bone
# world poses), and the profile words of declared_profile.h. Without
# profile:no-derived it fails them (its poses are missing); with it they are
# not-applicable, and ?derived must never be asked: if it is, the program
# exits with status 3 (a crash vgc reports).
import subprocess
import sys


def main():
    vgc, words = sys.argv[1], sys.argv[2:]
    no_derived = "profile:no-derived" in words
    serve = subprocess.Popen([vgc, "serve"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1)
    out = sys.stdout

    def forward(line, document):
        serve.stdin.write(line + "\n")
        serve.stdin.flush()
        while True:
            answer = serve.stdout.readline()
            if not answer:
                sys.exit(4)
            out.write(answer)
            if not document or answer == "end\n" or answer.startswith("error"):
                break
        out.flush()

    for raw in sys.stdin:
        line = raw.rstrip("\n")
        if line == "?capabilities":
            out.write(" ".join(["capabilities"] + words) + "\nend\n")
            out.flush()
        elif line == "?derived":
            if no_derived:
                sys.stderr.write("declared_profile_node: asked ?derived after declaring profile:no-derived\n")
                sys.exit(3)
            out.write("vgc-derived 1\nend\n")
            out.flush()
        elif line == "?quit":
            break
        else:
            forward(line, line == "?snapshot")
    serve.stdin.write("?quit\n")
    serve.stdin.flush()
    serve.wait()


if __name__ == "__main__":
    main()
