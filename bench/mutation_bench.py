#!/usr/bin/env python3
"""mutation_bench.py — how much of someone else's code vgc's generators reach,
measured by mutation (issue 27, item 6).

Spec: none of the Verse spec; docs/certify.md "What the suite catches: the
mutation bench".

Rule coverage (rule_uses in report.json) counts what the generators reach in
the reference; it does not say what they would catch in an implementation
the suite did not write. This bench takes such an implementation, written
from the documentation alone (tests/exec_python/vgc_node.py by default),
makes first-order mutants of it, and certifies each one:

  * comparisons flipped (< <=, > >=, == !=, in / not in, is / is not),
  * integer constants moved by one (n-1 and n+1; 0 and 1 included),
  * conditions negated (if, elif, while, a conditional expression, assert),
  * `and` / `or` swapped,
  * statements dropped (one statement of a block replaced by `pass`; a
    docstring, a def, a class or an import is never dropped).

Each mutant is certified at seed 1 (`vgc certify --seed 1`, the suite's
defaults otherwise, with `--timeout 3` and `--budget 180`: a finding made
before the budget runs out kills it, so a killed mutant's run need not
finish; a survivor's run must, or it is counted "incomplete"): a finding
(exit 1) kills it, exit 0 lets it survive. A mutant
that cannot start (it no longer answers ?hello) is killed trivially and
counted apart ("stillborn"). Every survivor is then certified again more
widely (seeds 2..5, 4x the cases, twice the size): one that is killed there
is not equivalent, and the clause and counterexample of that run say what
the generators should draw at seed 1 to catch it; one that survives that
too is "not distinguished" and printed with its source line for a person
to explain (an equivalent mutant, or a reach the generators lack).

Score = killed at seed 1 / (mutants - stillborn - explained equivalents).
Explained equivalents are listed in EQUIVALENT below, each with why: the
bench never decides equivalence on its own.

The mutants are numbered in the order of a walk of the source's syntax tree,
so the same source gives the same mutants; `--sample N` takes N of them, an
even spread over that order (every k-th), so the same N gives the same
sample. Output: a directory with one line per mutant in results.tsv, the
survivors' reports, and summary.md (the score, the survivors, the trend
line for docs/certify.md).

Usage:
  python3 bench/mutation_bench.py --vgc build/cli/vgc [--sample 120] [--jobs 2]
      [--source tests/exec_python/vgc_node.py] [--out reports/mutation]
      [--list] [--only K,K,...]
"""

import argparse
import ast
import concurrent.futures
import copy
import datetime
import json
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# Mutants shown equivalent by reading them (index in the full list, for the
# default source, -> why). Each entry is an argument a person checked; the
# bench does not guess. Re-check them when the source changes (the bench
# prints a mutant's line; an entry whose line no longer matches is ignored
# and said so).
EQUIVALENT = {}

FLIP = {
    ast.Lt: ast.LtE, ast.LtE: ast.Lt, ast.Gt: ast.GtE, ast.GtE: ast.Gt,
    ast.Eq: ast.NotEq, ast.NotEq: ast.Eq, ast.In: ast.NotIn, ast.NotIn: ast.In,
    ast.Is: ast.IsNot, ast.IsNot: ast.Is,
}


class Site:
    """One place a first-order mutation can be made."""

    def __init__(self, kind, node, line, detail, apply):
        self.kind, self.node, self.line, self.detail, self.apply = kind, node, line, detail, apply


def is_docstring(stmt, body):
    return (body and stmt is body[0] and isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant)
            and isinstance(stmt.value.value, str))


def skipped_node(node):
    """The seeded-fault block and the `if __name__ == "__main__"` guard are
    the harness, not the node: they are not mutated."""
    if isinstance(node, ast.If) and isinstance(node.test, ast.Compare):
        left = node.test.left
        if isinstance(left, ast.Name) and left.id == "__name__":
            return True
        if isinstance(left, ast.Name) and left.id == "FAULT":
            return True
    if isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id in ("FAULTS", "FAULT")
                                           for t in node.targets):
        return True
    return False


def collect_sites(tree):
    """Every mutation site, in a fixed walk order."""
    sites = []

    def visit(node, parent_body=None):
        if skipped_node(node):
            return
        if isinstance(node, ast.Compare):
            for i, op in enumerate(node.ops):
                if type(op) in FLIP:
                    def apply(n=node, i=i):
                        n.ops[i] = FLIP[type(n.ops[i])]()
                    sites.append(Site("comparison", node, node.lineno,
                                      "%s -> %s" % (type(op).__name__, FLIP[type(op)].__name__), apply))
        if isinstance(node, ast.Constant) and type(node.value) is int and not isinstance(node.value, bool):
            for delta in (-1, 1):
                def apply(n=node, d=delta):
                    n.value = n.value + d
                sites.append(Site("constant", node, node.lineno, "%d -> %d" % (node.value, node.value + delta), apply))
        if isinstance(node, (ast.If, ast.While, ast.IfExp, ast.Assert)):
            def apply(n=node):
                n.test = ast.UnaryOp(op=ast.Not(), operand=n.test)
            sites.append(Site("negation", node, node.lineno, "not (%s)" % ast.unparse(node.test)[:60], apply))
        if isinstance(node, ast.BoolOp):
            def apply(n=node):
                n.op = ast.Or() if isinstance(n.op, ast.And) else ast.And()
            sites.append(Site("boolean", node, node.lineno,
                              "and -> or" if isinstance(node.op, ast.And) else "or -> and", apply))
        for field in ("body", "orelse", "finalbody"):
            body = getattr(node, field, None)
            if not isinstance(body, list):
                continue
            for stmt in body:
                if not isinstance(stmt, ast.stmt) or skipped_node(stmt) or is_docstring(stmt, body):
                    continue
                if isinstance(stmt, (ast.FunctionDef, ast.ClassDef, ast.Import, ast.ImportFrom, ast.Pass,
                                     ast.Global, ast.Nonlocal)):
                    continue
                def apply(b=body, s=stmt):
                    b[b.index(s)] = ast.copy_location(ast.Pass(), s)
                sites.append(Site("drop", stmt, stmt.lineno, "drop `%s`" % ast.unparse(stmt).split("\n")[0][:60],
                                  apply))
        for child in ast.iter_child_nodes(node):
            visit(child)

    visit(tree)
    return sites


def make_mutant(source, index):
    """The source with mutation `index` applied, and its site."""
    tree = ast.parse(source)
    sites = collect_sites(tree)
    site = sites[index]
    site.apply()
    ast.fix_missing_locations(tree)
    return ast.unparse(tree) + "\n", site


def certify(vgc, program, seed, cases, max_size, reports, timeout_s, budget_s):
    """Runs vgc certify; (exit code, report.json or None, seconds, the console's last lines)."""
    cmd = [vgc, "certify", "--impl", "exec:%s %s" % (sys.executable, program), "--seed", str(seed), "--quiet",
           "--timeout", str(timeout_s), "--budget", str(budget_s), "--reports", reports]
    if cases:
        cmd += ["--cases", str(cases)]
    if max_size:
        cmd += ["--max-size", str(max_size)]
    t0 = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, errors="replace", timeout=3600)
        rc, out = p.returncode, (p.stdout + p.stderr)
    except subprocess.TimeoutExpired:
        rc, out = -1, "vgc certify did not end within an hour"
    seconds = time.monotonic() - t0
    report = None
    latest = os.path.join(reports, "latest", "report.json")
    if os.path.exists(latest):
        try:
            report = json.load(open(latest))
        except ValueError:
            report = None
    return rc, report, seconds, out.strip().splitlines()[-3:]


def failing_clauses(report):
    if not report:
        return []
    bad = ("fail", "crash", "timeout", "protocol-error")
    return [c for c in report.get("clauses", []) if c.get("status") in bad]


def judge_mutant(args, index, source, workdir):
    """Certifies mutant `index` at seed 1, then a survivor more widely."""
    text, site = make_mutant(source, index)
    d = os.path.join(workdir, "m%04d" % index)
    os.makedirs(d, exist_ok=True)
    program = os.path.join(d, "node.py")
    open(program, "w").write(text)
    rc, report, secs, tail = certify(args.vgc, program, 1, None, None, os.path.join(d, "seed1"), args.timeout,
                                     args.budget)
    row = {"index": index, "kind": site.kind, "line": site.line, "detail": site.detail, "seconds": round(secs, 1)}
    # A program that no longer starts (no `vgc-exec 1 NAME` answer to
    # ?hello) leaves no report: vgc could not begin the run.
    started = report is not None and not any("cannot start" in line or "vgc-exec 1" in line for line in tail)
    if rc == 1 or (rc == 2 and failing_clauses(report)):  # a finding kills it, cut short by the budget or not
        first = failing_clauses(report)
        row.update(outcome="killed", by=first[0]["id"] if first else "?")
    elif rc == 0:
        row.update(outcome="survived")
    elif not started:
        row.update(outcome="stillborn", by=" ".join(tail)[-200:])
    else:
        row.update(outcome="incomplete", by=" ".join(tail)[-200:])
    if row["outcome"] != "survived" or not args.widen:
        if row["outcome"] in ("killed", "stillborn") and not args.keep:
            shutil.rmtree(d, ignore_errors=True)
        return row
    for seed in args.widen:
        rc2, report2, secs2, _ = certify(args.vgc, program, seed, 800, 100, os.path.join(d, "seed%d" % seed),
                                         args.timeout, 4 * args.budget)
        row["seconds"] = round(row["seconds"] + secs2, 1)
        if rc2 == 1:
            first = failing_clauses(report2)
            c = first[0] if first else {}
            row.update(wider="killed", wider_seed=seed, by=c.get("id", "?"),
                       counterexample=" ; ".join(c.get("counterexample_commands", []))[:400])
            return row
    row.update(wider="survived")
    return row


def summarize(rows, sites, source_lines, out, started, args):
    n = len(rows)
    count = lambda **kv: sum(1 for r in rows if all(r.get(k) == v for k, v in kv.items()))
    killed, stillborn = count(outcome="killed"), count(outcome="stillborn")
    survived, incomplete = count(outcome="survived"), count(outcome="incomplete")
    equivalent = [r for r in rows if r["outcome"] == "survived" and r["index"] in EQUIVALENT]
    denominator = n - stillborn - len(equivalent)
    score = 100.0 * killed / denominator if denominator else 0.0
    by_kind = {}
    for r in rows:
        k = by_kind.setdefault(r["kind"], [0, 0])
        k[1] += 1
        k[0] += r["outcome"] == "killed"
    md = ["# vgc mutation bench", "",
          "Source: `%s` (%d mutation sites). Mutants certified: %d%s. vgc: `%s`. Started %s, %d s." % (
              os.path.relpath(args.source, ROOT), len(sites), n,
              " (every %d-th: `--sample %d`)" % (max(1, len(sites) // n), n) if n < len(sites) else "",
              args.vgc, started, int(time.time() - args.t0)), "",
          "| mutants | killed at seed 1 | survived | stillborn | incomplete | explained equivalent | score |",
          "|---|---|---|---|---|---|---|",
          "| %d | %d | %d | %d | %d | %d | **%.1f %%** |" % (n, killed, survived, stillborn, incomplete,
                                                              len(equivalent), score), "",
          "Score = killed at seed 1 / (mutants - stillborn - explained equivalent). By kind:", ""]
    for kind, (k, t) in sorted(by_kind.items()):
        md.append("- %s: %d of %d killed" % (kind, k, t))
    md += ["", "## Survivors", ""]
    for r in rows:
        if r["outcome"] != "survived" and r["outcome"] != "incomplete":
            continue
        line = source_lines[r["line"] - 1].strip() if 0 < r["line"] <= len(source_lines) else ""
        md.append("- mutant %d, line %d (%s: %s): `%s`" % (r["index"], r["line"], r["kind"], r["detail"], line[:100]))
        if r["outcome"] == "incomplete":
            md.append("  - incomplete at seed 1: %s" % r.get("by", ""))
        elif r.get("wider") == "killed":
            md.append("  - not equivalent: killed at seed %d (4x cases, size 100) by %s; what seed 1 should draw: `%s`"
                      % (r["wider_seed"], r["by"], r.get("counterexample", "")))
        elif r["index"] in EQUIVALENT:
            md.append("  - equivalent: %s" % EQUIVALENT[r["index"]])
        else:
            md.append("  - not distinguished by the wider runs either: to explain (equivalent, or a reach the "
                      "generators lack)")
    md += ["", "Trend line for docs/certify.md:", "",
           "    %s  %s  %d mutants  score %.1f %%  (%d killed, %d survived, %d stillborn, %d incomplete)" % (
               started[:10], os.path.relpath(args.source, ROOT), n, score, killed, survived, stillborn, incomplete)]
    open(os.path.join(out, "summary.md"), "w").write("\n".join(md) + "\n")
    return score, "\n".join(md)


def main():
    ap = argparse.ArgumentParser(description="vgc's mutation bench (docs/certify.md)")
    ap.add_argument("--vgc", required=True, help="the vgc binary")
    ap.add_argument("--source", default=os.path.join(ROOT, "tests", "exec_python", "vgc_node.py"))
    ap.add_argument("--out", default=os.path.join("reports", "mutation"))
    ap.add_argument("--sample", type=int, default=0, help="certify N mutants spread evenly over all (0: all)")
    ap.add_argument("--sample-offset", type=int, default=0,
                    help="with --sample: start the even spread this many mutants later (a second, disjoint sample)")
    ap.add_argument("--only", default="", help="comma-separated mutant numbers")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=3, help="certify --timeout for each mutant")
    ap.add_argument("--budget", type=float, default=180,
                    help="certify --budget for each mutant at seed 1 (a killed mutant's run need not finish: its "
                         "first finding kills it; a survivor's run must, or it is counted incomplete)")
    ap.add_argument("--widen", default="2,3,4,5", help="seeds of the wider runs of a survivor ('' for none)")
    ap.add_argument("--keep", action="store_true", help="keep the killed mutants' reports")
    ap.add_argument("--list", action="store_true", help="list the mutants and exit")
    args = ap.parse_args()
    args.t0 = time.time()
    if not (args.timeout > 0 and args.budget > 0):
        ap.error("--timeout and --budget must be positive")
    for name, value in (("--sample", args.sample), ("--jobs", args.jobs)):
        if value < 0 or (name == "--jobs" and value == 0):
            ap.error("%s: %d is out of range" % (name, value))
    try:
        args.widen = [int(s) for s in args.widen.split(",") if s.strip()]
    except ValueError:
        ap.error("--widen: %r is not a comma-separated list of seeds" % args.widen)
    if not os.access(args.vgc, os.X_OK):
        ap.error("--vgc: %s is not an executable" % args.vgc)
    args.vgc = os.path.abspath(args.vgc)
    args.source = os.path.abspath(args.source)
    source = open(args.source).read()
    sites = collect_sites(ast.parse(source))
    if args.list:
        for i, s in enumerate(sites):
            print("%4d  line %4d  %-10s %s" % (i, s.line, s.kind, s.detail))
        return 0
    if args.only:
        try:
            chosen = sorted({int(k) for k in args.only.split(",")})
        except ValueError:
            ap.error("--only: %r is not a comma-separated list of mutant numbers" % args.only)
        if any(k < 0 or k >= len(sites) for k in chosen):
            ap.error("--only: mutants are numbered 0 to %d" % (len(sites) - 1))
    elif args.sample and args.sample < len(sites):
        step = len(sites) / args.sample
        if not 0 <= args.sample_offset < step:
            ap.error("--sample-offset: give 0 to %d for --sample %d" % (int(step) - 1, args.sample))
        chosen = sorted({int(i * step) + args.sample_offset for i in range(args.sample)})
    else:
        chosen = list(range(len(sites)))
    started = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    out = os.path.abspath(os.path.join(args.out, started.replace(":", "")))
    os.makedirs(out, exist_ok=True)
    print("mutation bench: %d of %d mutants of %s, %d at a time; results in %s" % (
        len(chosen), len(sites), os.path.relpath(args.source), args.jobs, out), flush=True)
    rows = []
    with open(os.path.join(out, "results.tsv"), "w") as tsv, \
            concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {pool.submit(judge_mutant, args, k, source, out): k for k in chosen}
        for done, f in enumerate(concurrent.futures.as_completed(futures), 1):
            r = f.result()
            rows.append(r)
            tsv.write(json.dumps(r, sort_keys=True) + "\n")
            tsv.flush()
            print("[%d/%d] mutant %d (line %d, %s: %s): %s%s" % (
                done, len(chosen), r["index"], r["line"], r["kind"], r["detail"], r["outcome"],
                " by " + r["by"] if r.get("by") and r["outcome"] == "killed" else
                (", wider runs: " + r["wider"] + (" by " + r["by"] if r.get("wider") == "killed" else ""))
                if r.get("wider") else ""), flush=True)
    rows.sort(key=lambda r: r["index"])
    score, md = summarize(rows, sites, source.splitlines(), out, started, args)
    print(md)
    return 0


if __name__ == "__main__":
    sys.exit(main())
