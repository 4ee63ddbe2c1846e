#!/usr/bin/env bash
# verse_shards_test.sh VGC — shards give the unsharded verdict on every
# route, the Verse wire included, and divide the work (issue 31 items 1, 9).
#
# Two `vgc serve --verse` hosts on two loopback ports (one host per CI job):
# the unsharded run against host A; shard 1/3 against A, shards 2/3 and 3/3
# against B. Each shard must be complete (exit 0: the reference behind the
# host is conformant; a shard used to be `incomplete` because the property
# at scale, which the wire cannot run, landed in it), `vgc merge` must
# accept shards of one implementation on two ports (it refused: "the runs
# differ in implementation") and give the unsharded run's exit code, counts
# and, per clause, status and exercised count. Then the work: the judged
# commands of each shard, on the wire and through exec: (4 shards, where
# storage.scale is most of the run), are within 1.5x of the mean: a count,
# not a time, so the check does not depend on the machine's load.
set -uo pipefail
[ $# -ge 1 ] || { echo "usage: $0 VGC" >&2; exit 2; }
vgc=$1
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_verse_shards.XXXXXX")
cd "$tmp" || exit 2
. "$here/../fuzz/live_host_lib.sh"
trap 'cleanup_hosts; rm -rf "$tmp"' EXIT
fail() { echo "verse_shards: $*" >&2; exit 1; }

start_verse_host "$vgc" "" 127.0.0.1:0 a.log || fail "host A did not start"
a=$host_port
start_verse_host "$vgc" "" 127.0.0.1:0 b.log || fail "host B did not start"
b=$host_port

"$vgc" certify --quiet --impl "verse:127.0.0.1:$a" --reports W >w.out 2>&1
whole_rc=$?
[ $whole_rc = 0 ] || { cat w.out >&2; fail "the unsharded run exited $whole_rc, expected 0"; }
for k in 1 2 3; do
  port=$b
  [ $k = 1 ] && port=$a
  "$vgc" certify --quiet --impl "verse:127.0.0.1:$port" --shard $k/3 --reports S >s$k.out 2>&1
  rc=$?
  [ $rc = 0 ] || { cat s$k.out >&2; fail "shard $k/3 exited $rc, expected 0 (each shard of a conformant host is complete)"; }
done
"$vgc" merge S/verse-*/*/ --reports M >m.out 2>&1
rc=$?
[ $rc = $whole_rc ] || { cat m.out >&2; fail "merge of shards on two ports exited $rc, the unsharded run $whole_rc"; }
python3 - W M S <<'PY' || fail "the merged run differs from the unsharded one, or the shards are unbalanced (above)"
import glob, json, sys
def one(pattern):
    (path,) = [p for p in glob.glob(pattern) if "/latest/" not in p]
    return json.load(open(path))
w = one(sys.argv[1] + "/verse-*/*/report.json")
m = one(sys.argv[2] + "/verse-*/*/report.json")
assert w["counts"] == m["counts"], (w["counts"], m["counts"])
assert w["verdict"] == m["verdict"], (w["verdict"], m["verdict"])
for a, b in zip(w["clauses"], m["clauses"]):
    assert (a["id"], a["status"], a["exercised"]) == (b["id"], b["status"], b["exercised"]), (a, b)
sent = []
for path in sorted(glob.glob(sys.argv[3] + "/verse-*/*/report.json")):
    r = json.load(open(path))
    sent.append(sum(k["sent"] for k in r["command_kinds"].values()))
mean = sum(sent) / len(sent)
assert all(s <= 1.5 * mean for s in sent), "judged commands per shard on the wire: %s (mean %.0f)" % (sent, mean)
print("verse_shards: merged = unsharded (%s); wire shards' judged commands %s" % (m["counts"], sent))
PY

for k in 1 2 3 4; do
  "$vgc" certify --quiet --impl "exec:$vgc serve" --shard $k/4 --reports E >e$k.out 2>&1
  rc=$?
  [ $rc = 0 ] || { cat e$k.out >&2; fail "exec shard $k/4 exited $rc, expected 0"; }
done
python3 - E <<'PY' || fail "the exec shards are unbalanced (above)"
import glob, json, sys
sent = []
for path in sorted(p for p in glob.glob(sys.argv[1] + "/*/*/report.json") if "/latest/" not in p):
    r = json.load(open(path))
    sent.append(sum(k["sent"] for k in r["command_kinds"].values()))
mean = sum(sent) / len(sent)
assert len(sent) == 4 and all(s <= 1.5 * mean for s in sent), "judged commands per exec shard: %s (mean %.0f)" % (sent, mean)
print("verse_shards: exec shards' judged commands %s" % sent)
PY
echo "verse_shards: shards on two ports merge into the unsharded run; shards divide the work within 1.5x"
