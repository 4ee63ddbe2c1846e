#!/usr/bin/env bash
# shards_test.sh — N shards of a certify run, read together as docs/ci.md
# ("Shards, and how their reports combine") says, give the unsharded run's
# verdict and clause statuses.
#
#   shards_test.sh VGC FAULT_PLUGIN [PYTHON3]
#
# For the reference and for the fault plugin with VGC_FAULT=base-layer-destroyable
# (LAYER-BASE-2, which properties in two of three shards find), at 100
# cases and seed 1 (CASES=N to change): the worst shard exit code (1 over 2 over 0)
# is the unsharded exit code; every property runs in exactly one shard,
# but storage.scale, whose cases are split over the shards (their cases add
# up to the unsharded run's); a
# clause the unsharded run fails fails in some shard, one it passes passes
# in every shard that does not skip it; and each clause's `exercised`
# counts summed over the shards are the unsharded counts.
set -uo pipefail

[ $# -ge 2 ] || { echo "usage: $0 VGC FAULT_PLUGIN [PYTHON3]" >&2; exit 2; }
vgc=$1
fault_plugin=$2
python=${3:-python3}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_shards_test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
failures=0

for impl in reference "plugin:$fault_plugin"; do
  name=${impl%%:*}
  codes=()
  mkdir -p "$tmp/$name"
  for shard in 1/1 1/3 2/3 3/3; do
    dir=$tmp/$name/${shard/\//of}
    VGC_FAULT=base-layer-destroyable "$vgc" certify --impl "$impl" --seed 1 --cases "${CASES:-100}" --shard "$shard" --reports "$dir" --quiet \
      >"$dir.out" 2>&1
    codes+=("$?")
  done
  echo "$name: unsharded exit ${codes[0]}, shards ${codes[*]:1}"
  worst=0
  for c in "${codes[@]:1}"; do
    if [ "$c" -eq 1 ] || { [ "$c" -eq 2 ] && [ "$worst" -ne 1 ]; }; then worst=$c; fi
  done
  if [ "$worst" -ne "${codes[0]}" ]; then
    echo "FAIL: $name: the worst shard exit code $worst is not the unsharded ${codes[0]}"
    failures=$((failures + 1))
  fi
  "$python" - "$tmp/$name" <<'PY' || failures=$((failures + 1))
import glob, json, sys
root = sys.argv[1]
def report(d):
    return json.load(open(glob.glob(f"{root}/{d}/*/*/report.json")[0]))
full = report("1of1")
shards = [report(f"{i}of3") for i in (1, 2, 3)]
problems = []
ran = {}
for s in shards:
    for p in s["properties"]:
        if p["status"] != "skipped" or not p["note"].startswith("in shard"):
            ran[p["id"]] = ran.get(p["id"], 0) + 1
for p in full["properties"]:
    if p["id"] == "storage.scale":
        cases = sum(q["cases"] for s in shards for q in s["properties"] if q["id"] == p["id"])
        if cases != p["cases"]:
            problems.append(f"storage.scale ran {cases} cases over the shards, {p['cases']} unsharded")
        continue
    if p["status"] != "skipped" and ran.get(p["id"]) != 1:
        problems.append(f"property {p['id']} ran in {ran.get(p['id'], 0)} shards")
for c in full["clauses"]:
    cid = c["id"]
    mine = [next(x for x in s["clauses"] if x["id"] == cid) for s in shards]
    judged = [x["status"] for x in mine if x["status"] != "skipped"]
    if c["status"] in ("fail", "crash", "timeout") and c["status"] not in judged:
        problems.append(f"{cid}: {c['status']} unsharded, {judged} in the shards")
    if c["status"] == "pass" and (not judged or any(j != "pass" for j in judged)):
        problems.append(f"{cid}: pass unsharded, {judged} in the shards")
    total = sum(x["exercised"] for x in mine)
    if total != c["exercised"]:
        problems.append(f"{cid}: exercised {c['exercised']} unsharded, {total} summed over the shards")
for p in problems:
    print("FAIL: " + p)
print(f"{len(full['clauses'])} clauses compared, {len(problems)} differences")
sys.exit(1 if problems else 0)
PY
done

[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "all checks passed"
