#!/usr/bin/env python3
"""check_yaml.py — the CI recipes parse and have the shape they promise.

    check_yaml.py SOURCE_DIR

Parses (PyYAML, Debian package python3-yaml) action.yml, every workflow in
.github/workflows/, and every ```yaml block of docs/ci.md, then checks:
action.yml is a composite action whose inputs include impl (required),
baseline, clauses, cases, seed and shard, passes every input to
ci/github_action.sh as INPUT_<NAME> (and the script reads each), exposes
the verdict and report-dir outputs and uploads the report; ci.yml runs
`./vgc test` before `./vgc certify`; docs/ci.md has a whole GitHub workflow
that uses the action with a baseline and a shard matrix, and a whole GitLab
CI file with a baseline and parallel shards. Exit 0 when all hold, 1 with
one line per problem otherwise.
"""
import pathlib
import re
import sys

import yaml

root = pathlib.Path(sys.argv[1])
problems = []


def check(ok, what):
    print(("ok: " if ok else "FAIL: ") + what)
    if not ok:
        problems.append(what)


def load(text, where):
    try:
        return yaml.safe_load(text)
    except yaml.YAMLError as e:
        check(False, f"{where} parses as YAML: {e}")
        return None


def steps_of(workflow):
    for job in (workflow.get("jobs") or {}).values():
        for step in job.get("steps") or []:
            yield step


# action.yml
action = load((root / "action.yml").read_text(), "action.yml")
script = (root / "ci" / "github_action.sh").read_text()
if action:
    check(action.get("runs", {}).get("using") == "composite", "action.yml is a composite action")
    inputs = action.get("inputs") or {}
    for name in ("impl", "baseline", "clauses", "cases", "seed", "shard"):
        check(name in inputs, f"action.yml has the input {name}")
    check(inputs.get("impl", {}).get("required") is True, "action.yml: impl is required")
    steps = action["runs"].get("steps") or []
    certify = next((s for s in steps if s.get("id") == "certify"), {})
    check("ci/github_action.sh" in str(certify.get("run", "")), "action.yml runs ci/github_action.sh")
    env = certify.get("env") or {}
    for name in inputs:
        var = "INPUT_" + re.sub(r"[^A-Z0-9]", "_", name.upper())
        check(env.get(var) == "${{ inputs.%s }}" % name, f"action.yml passes the input {name} as {var}")
        check(var in script, f"ci/github_action.sh reads {var}")
    outputs = action.get("outputs") or {}
    for name in ("verdict", "report-dir"):
        check(name in outputs and "steps.certify.outputs." + name in outputs[name].get("value", ""),
              f"action.yml has the output {name}")
    upload = next((s for s in steps if str(s.get("uses", "")).startswith("actions/upload-artifact@")), None)
    check(upload is not None, "action.yml uploads the report as an artifact")
    # A cancelled job runs only the steps whose condition holds whatever
    # happened (GitHub's workflow cancellation reference): always(), not
    # !cancelled(), or the incomplete report of a cancelled run is lost.
    check(upload is not None and "always()" in str(upload.get("if", "")) and "cancelled()" not in str(upload.get("if", "")),
          "action.yml uploads the report of a cancelled job too (if: always() ...)")

# .github/workflows/*.yml
for path in sorted((root / ".github" / "workflows").glob("*.yml")):
    wf = load(path.read_text(), str(path.relative_to(root)))
    check(wf is not None and "jobs" in wf, f"{path.relative_to(root)} parses and has jobs")
ci = load((root / ".github" / "workflows" / "ci.yml").read_text(), "ci.yml") or {}
runs = [str(s.get("run", "")) for s in steps_of(ci)]
test_at = next((i for i, r in enumerate(runs) if r.strip().startswith("./vgc test")), None)
certify_at = next((i for i, r in enumerate(runs) if r.strip().startswith("./vgc certify")), None)
check(test_at is not None and certify_at is not None and test_at < certify_at,
      "ci.yml runs ./vgc test, then ./vgc certify")

# docs/ci.md
doc = (root / "docs" / "ci.md").read_text()
blocks = re.findall(r"^```yaml\n(.*?)^```", doc, re.S | re.M)
check(len(blocks) >= 2, f"docs/ci.md has yaml blocks ({len(blocks)})")
github, gitlab = [], []
for i, text in enumerate(blocks):
    y = load(text, f"docs/ci.md yaml block {i + 1}")
    if not isinstance(y, dict):
        continue
    if "jobs" in y:
        github.append((y, text))
    elif any(isinstance(v, dict) and "script" in v for v in y.values()):
        gitlab.append((y, text))
uses_action = [
    t for y, t in github
    if any(re.match(r"^[\w.-]+/vgc@", str(s.get("uses", ""))) for s in steps_of(y))
]
check(bool(uses_action), "docs/ci.md: a GitHub workflow that uses the vgc action")
check(any("shard:" in t and "matrix" in t and "baseline:" in t for t in uses_action),
      "docs/ci.md: a GitHub workflow with a baseline and a shard matrix")
check(any("--shard" in t and "parallel:" in t and "--baseline" in t and "junit" in t for _, t in gitlab),
      "docs/ci.md: a GitLab CI file with a baseline, parallel shards and JUnit reports")
check(any(any(isinstance(v, dict) and "vgc merge" in " ".join(map(str, v.get("script", []))) and
              "certify" in v.get("needs", []) for v in y.values()) for y, _ in gitlab),
      "docs/ci.md: the GitLab CI file merges the shards (vgc merge) in a job after them")

# The nightly wire soak: a CPU budget whose wall-clock cap, with the time to
# build, ends inside the job's timeout (a soak killed by the runner writes no
# table).
batch = load((root / ".github" / "workflows" / "cflite_batch.yml").read_text(), "cflite_batch.yml") or {}
soak = (batch.get("jobs") or {}).get("WireSoak") or {}
runs = [str(s.get("run", "")) for s in soak.get("steps") or [] if "fuzz --all" in str(s.get("run", ""))]
check(len(runs) == 1, "cflite_batch.yml: the WireSoak job runs one vgc fuzz --all")
if runs:
    m_time = re.search(r"--time (\d+)", runs[0])
    m_cap = re.search(r"--wall-cap ([\d.]+)", runs[0])
    check("--cpu-time" in runs[0] and m_time and m_cap, "WireSoak: a --cpu-time soak with --time and --wall-cap")
    if m_time and m_cap:
        cap_min = float(m_time.group(1)) * float(m_cap.group(1)) / 60
        check(cap_min + 20 <= float(soak.get("timeout-minutes", 0)),
              f"WireSoak: its wall cap ({cap_min:.0f} min) and 20 min of build fit in timeout-minutes")

sys.exit(1 if problems else 0)
