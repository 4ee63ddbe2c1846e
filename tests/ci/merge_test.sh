#!/usr/bin/env bash
# merge_test.sh VGC FAULT_PLUGIN PYTHON3 REQUESTS_PLUGIN — `vgc merge` of
# the four shards of a run gives the unsharded run (issue 19, item 7): for
# the reference, for the fault plugin (VGC_FAULT=base-layer-destroyable)
# and for the fault plugin answering capability requests with three
# capability faults (findings whose pictures are drawn from what the
# implementation showed), the merged report.json has the unsharded
# verdict, exit code, counts, per-clause status, exercised counts, notes
# and findings (message, found_by, counterexample), and the same
# properties; report.html and summary.md are the unsharded ones but for
# the run directory, times and the start time (the pictures of capability
# findings, the replay commands' VGC_* environment and the rules used
# included: the merge lacked all three); merge's exit code is the
# unsharded one. It refuses shards of different seeds and names a missing
# shard. (There was no merge: reports/latest pointed at the last shard.)
set -uo pipefail
[ $# -ge 4 ] || { echo "usage: $0 VGC FAULT_PLUGIN PYTHON3 REQUESTS_PLUGIN" >&2; exit 2; }
vgc=$1 plugin=$2 python=$3 requests=$4
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_merge.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 2
fail() { echo "merge: $*" >&2; exit 1; }
run_dir() { sed -n 's/^report: \(.*\)\/summary.md$/\1/p' "$1"; }

for impl in reference "plugin:$plugin" "plugin:$requests"; do
  name=${impl%%:*}
  env=()
  [ "$impl" = "plugin:$plugin" ] && env=(VGC_FAULT=base-layer-destroyable)
  [ "$impl" = "plugin:$requests" ] && name=requests &&
    env=(VGC_FAULT=subdivision-ignores-creases,classify-misses-boundary,normals-flat)
  env "${env[@]}" "$vgc" certify --quiet --cases 40 --impl "$impl" --reports "$name/whole" >"$name.whole.out" 2>&1
  whole_rc=$?
  shards=()
  for k in 1 2 3 4; do
    env "${env[@]}" "$vgc" certify --quiet --cases 40 --impl "$impl" --shard "$k/4" --reports "$name/shards" \
      >"$name.$k.out" 2>&1
    shards+=("$(run_dir "$name.$k.out")")
  done
  "$vgc" merge "${shards[@]}" --reports "$name/merged" >"$name.merge.out" 2>&1
  merge_rc=$?
  [ "$merge_rc" = "$whole_rc" ] || { cat "$name.merge.out" >&2; fail "$name: merge exited $merge_rc, the unsharded run $whole_rc"; }
  "$python" - "$(run_dir "$name.whole.out")/report.json" "$(run_dir "$name.merge.out")/report.json" <<'PY' ||
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
for key in ("verdict", "exit_code", "counts", "new_failures", "known_failures", "should_failures",
            "profile_differences", "unchecked", "seed", "cases_per_property", "unreported_verdicts", "command_kinds"):
    assert a.get(key) == b.get(key), "%s: unsharded %r, merged %r" % (key, a.get(key), b.get(key))
ca = {c["id"]: c for c in a["clauses"]}
cb = {c["id"]: c for c in b["clauses"]}
assert ca.keys() == cb.keys(), sorted(set(ca) ^ set(cb))
for cid, c in ca.items():
    for key in ("status", "exercised", "note", "message", "found_by", "seed", "counterexample_commands", "properties"):
        assert c.get(key) == cb[cid].get(key), "%s %s: unsharded %r, merged %r" % (cid, key, c.get(key), cb[cid].get(key))
pa = [(p["id"], p["status"], p["cases"], p.get("findings")) for p in a["properties"]]
pb = [(p["id"], p["status"], p["cases"], p.get("findings")) for p in b["properties"]]
assert pa == pb, "properties: unsharded %r, merged %r" % (pa, pb)
PY
    fail "$name: the merged report.json differs from the unsharded one (above)"
  for f in summary.md report.html junit.xml; do
    [ -s "$(run_dir "$name.merge.out")/$f" ] || fail "$name: merged $f missing"
  done
  # report.html and summary.md: the same but for the run directory, the
  # times and the start time.
  for f in report.html summary.md; do
    "$python" - "$(run_dir "$name.whole.out")" "$(run_dir "$name.merge.out")" "$f" >"$name.$f.diff" <<'PY' ||
import difflib, re, sys
def norm(run_dir, f):
    t = open(run_dir + "/" + f, encoding="utf-8").read().replace(run_dir, "RUN")
    t = re.sub(r"\b\d+\.\d+ s\b", "T s", t)                        # the run's seconds
    t = re.sub(r"<td>\d+\.\d\d</td>", "<td>T</td>", t)               # a property's seconds (html)
    t = re.sub(r"\| \d+\.\d\d \|$", "| T |", t, flags=re.M)          # a property's seconds (md)
    t = re.sub(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ", "STARTED", t)
    return t.replace("><", ">\n<").splitlines()
a, b = norm(sys.argv[1], sys.argv[3]), norm(sys.argv[2], sys.argv[3])
d = list(difflib.unified_diff(a, b, "unsharded", "merged", lineterm="", n=1))
print("\n".join(d[:40]))
sys.exit(1 if d else 0)
PY
      { cat "$name.$f.diff" >&2; fail "$name: merged $f differs from the unsharded one (above)"; }
  done
  if [ "$name" = requests ]; then  # the capability findings have their pictures
    n=$(grep -o 'class="hl-edge"\|class="expected-point"\|class="observed-point"' "$(run_dir "$name.merge.out")/report.html" | wc -l)
    [ "$n" -gt 0 ] || fail "requests: the merged report.html draws no highlighted edge or refined point"
  fi
  # junit.xml: the same test cases with the same results (times aside).
  strip() { sed -E 's/ time="[^"]*"//; s/ name="vgc certify [^"]*"//' "$1" | grep -v "Replay:\|replay '"; }
  diff <(strip "$(run_dir "$name.whole.out")/junit.xml") <(strip "$(run_dir "$name.merge.out")/junit.xml") >"$name.junit.diff" ||
    { head -20 "$name.junit.diff" >&2; fail "$name: merged junit.xml differs from the unsharded one"; }
done

# Refusals: a missing shard is named; shards of another seed are refused.
plugin_shards=$(for k in 1 2 4; do run_dir "plugin.$k.out"; done)
"$vgc" merge $plugin_shards --reports bad >bad.out 2>&1
[ $? = 2 ] && grep -q "shard 3/4 is missing" bad.out || { cat bad.out >&2; fail "a missing shard is not named"; }
"$vgc" certify --quiet --cases 40 --seed 2 --shard 3/4 --reports other >other.out 2>&1
"$vgc" merge $(for k in 1 2 4; do run_dir "reference.$k.out"; done) "$(run_dir other.out)" --reports bad >bad2.out 2>&1
[ $? = 2 ] && grep -q "differ in seed" bad2.out || { cat bad2.out >&2; fail "shards of another seed are not refused"; }
echo "merge: four shards merged give the unsharded report.json, for the reference and a fault; bad sets are refused"
