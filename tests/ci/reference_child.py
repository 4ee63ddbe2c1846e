"""reference_child.py — the part every misbehaving test implementation in
tests/ci shares (history_proxy.py, costly_ids_proxy.py,
huge_answer_host.py): a child `VGC serve` (the reference, or SERVE ARGS
such as --impl plugin:PATH) to which lines are relayed, its answers copied
back, a document (?snapshot, ?derived, a capability request) to its "end"
line and ?digest as one line (docs/adapters.md)."""
import subprocess
import sys


class ReferenceChild:
    def __init__(self, vgc, serve_args=()):
        self.process = subprocess.Popen([vgc, "serve"] + list(serve_args), stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, text=True, bufsize=1)

    def relay(self, line, out=sys.stdout):
        """Sends `line` to the child and copies its whole answer to `out`;
        exits 3 when the child's output ends."""
        self.process.stdin.write(line)
        self.process.stdin.flush()
        answer = self._read()
        out.write(answer)
        single = line.strip() in ("?hello", "?reset", "?quit", "?digest") or not line.startswith("?")
        while not single and not answer.startswith("error") and answer.strip() != "end":
            answer = self._read()
            out.write(answer)
        out.flush()

    def _read(self):
        answer = self.process.stdout.readline()
        if not answer:
            sys.exit(3)
        return answer
