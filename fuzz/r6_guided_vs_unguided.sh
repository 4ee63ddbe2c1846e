#!/usr/bin/env bash
# r6_guided_vs_unguided.sh R6_DIR SECONDS WORK [SEEDS] — does fuzzing guided
# by a Verse host's own coverage pay against r6? (docs/fuzzing.md "Against
# the r6 host, guided by its own coverage"; issue 30 item 4.)
#
# R6_DIR is an r6 tree (ffforks/verse) built with clang's inline 8-bit
# counters and vgc's coverage runtime (docs/fuzzing.md "Building an
# implementation for it"); its `verse` and `host_id.rsa` are copied into
# WORK twice, one host for each route, so that two hosts never share a key
# file. For each seed (default "1 2 3"), guided (`--impl-coverage guide`)
# then unguided (`observe`: the same host, its counters counted, nothing
# steered), one after the other, each for SECONDS, the two routes side by
# side: `vgc fuzz wire` on port $PORT_WIRE (default 47610) and `vgc fuzz
# differential --baseline BASELINE` (default $WORK/r6-baseline.txt, which
# must exist: the clauses certify reports against r6) on $PORT_DIFF (47620),
# each host started by vgc (--host-cmd). Then prints the table: r6's
# counters reached in all and in its geometry node and unpacker code
# (vs_node_geometry.c, v_gen_pack_g_node.c, v_man_pack_node.c, v_pack.c,
# v_pack_method.c; fuzz/impl_coverage_by_file.py), executions per second,
# and the seconds to each known r6 deviation (none: "-"):
#   2-byte datagram   wire: STABLE-1 after a raw datagram shorter than an id
#   truncated write   wire: ATOMIC-1 after a truncated command
#   storage bound     wire: ID-BOUND-1 or VERTEX-SET-1 after an id-magnitude input
#   16-byte name      differential: LAYER-TYPE-1
# Runs from the vgc source tree: VGC (default build/cli/vgc) and
# VGC_FUZZ_BUILD_DIR (default build-fuzz, with fuzz_differential built).
set -u
r6=$1 secs=$2 work=$3 seeds=${4:-1 2 3}
vgc=${VGC:-build/cli/vgc}
fbuild=${VGC_FUZZ_BUILD_DIR:-build-fuzz}
pw=${PORT_WIRE:-47610} pd=${PORT_DIFF:-47620}
baseline=${BASELINE:-$work/r6-baseline.txt}
here=$(cd "$(dirname "$0")" && pwd)
[ -x "$r6/verse" ] || { echo "r6_guided_vs_unguided: no $r6/verse" >&2; exit 2; }
[ -f "$baseline" ] || { echo "r6_guided_vs_unguided: no baseline $baseline" >&2; exit 2; }
mkdir -p "$work"
for route in wire diff; do
  mkdir -p "$work/r6-$route"
  cp "$r6/verse" "$work/r6-$route/"
  [ -f "$r6/host_id.rsa" ] && cp "$r6/host_id.rsa" "$work/r6-$route/"
done
for s in $seeds; do
  for m in guide observe; do
    for route in wire diff; do
      rm -rf "$work/$route-$m-$s" && mkdir -p "$work/$route-$m-$s/corpora/fuzz"
    done
    cp -r "$here/../corpora/fuzz/fuzz_differential" "$here/../corpora/fuzz/fuzz_differential.dict" \
      "$work/diff-$m-$s/corpora/fuzz/"
    echo "r6_guided_vs_unguided: seed $s, $m, $secs s ($(date -u +%H:%M:%S))"
    "$vgc" fuzz wire --impl "verse:127.0.0.1:$pw" --host-cmd "cd '$work/r6-wire' && exec ./verse -port=$pw" \
      --impl-coverage "$m" --time "$secs" --seed "$s" --source-dir "$work/wire-$m-$s" \
      >"$work/wire-$m-$s.out" 2>&1 &
    "$vgc" fuzz differential --impl "verse:127.0.0.1:$pd" --host-cmd "cd '$work/r6-diff' && exec ./verse -port=$pd" \
      --impl-coverage "$m" --time "$secs" --seed "$s" --baseline "$baseline" --fuzz-build "$fbuild" \
      --source-dir "$work/diff-$m-$s" >"$work/diff-$m-$s.out" 2>&1 &
    wait
  done
done
python3 - "$work" "$here/impl_coverage_by_file.py" $seeds <<'PY'
import glob, json, os, subprocess, sys
work, tool, seeds = sys.argv[1], sys.argv[2], sys.argv[3:]
files = ["vs_node_geometry.c", "v_gen_pack_g_node.c", "v_man_pack_node.c", "v_pack.c", "v_pack_method.c"]
def run_dir(route, m, s):
    sub = "wire" if route == "wire" else "fuzz_differential"
    d = glob.glob(os.path.join(work, "%s-%s-%s" % (route, m, s), "reports", "fuzz", sub, "*"))
    return d[0] if d else None
def by_file(d):
    out = subprocess.run([sys.executable, tool, d] + files, capture_output=True, text=True).stdout.split()
    return (int(out[-1]), int(out[-2])) if out and out[-3] == "total" else (None, None)
def first(findings, pred):
    t = [f[1] for f in findings if pred(f[0], f[2])]
    return "%.0f" % min(t) if t else "-"
print("| seed | mode | wire: r6 counters (geometry+unpacker) | wire: inputs/s | 2-byte datagram | truncated write | storage bound | differential: r6 counters (geometry+unpacker) | differential: exec/s | 16-byte name |")
print("|---|---|---|---|---|---|---|---|---|---|")
for s in seeds:
    for m in ("guide", "observe"):
        w, d = run_dir("wire", m, s), run_dir("diff", m, s)
        row = [s, "guided" if m == "guide" else "unguided"]
        if w and os.path.exists(os.path.join(w, "summary.json")):
            j = json.load(open(os.path.join(w, "summary.json")))
            ic = j.get("implementation_coverage", {})
            r, c = by_file(w)
            fs = [(g["key"], g["first_seen_s"], g["message"]) for g in j["findings"]]
            row += ["%s of %s (%s of %s)" % (ic.get("counters_reached"), ic.get("counters"), r, c),
                    "%.2f" % (j["inputs"] / j["wall_s"] if j["wall_s"] else 0),
                    first(fs, lambda k, msg: "STABLE-1" in k and "shorter than a packet id" in msg),
                    first(fs, lambda k, msg: "ATOMIC-1" in k and "truncated" in k),
                    first(fs, lambda k, msg: ("ID-BOUND-1" in k or "VERTEX-SET-1" in k) and "id-magnitude" in k)]
        else:
            row += ["(no summary)", "", "", "", ""]
        if d and os.path.exists(os.path.join(d, "summary.json")):
            j = json.load(open(os.path.join(d, "summary.json")))
            ic = j.get("implementation_coverage") or {}
            r, c = by_file(d)
            t = [c2.get("first_seen_s") for c2 in j["crashes"] if c2.get("clause") == "LAYER-TYPE-1" and c2.get("first_seen_s") is not None]
            row += ["%s of %s (%s of %s)" % (ic.get("counters_reached"), ic.get("counters"), r, c),
                    "%.1f" % j["exec_per_s_mean"], "%.0f" % min(t) if t else "-"]
        else:
            row += ["(no summary)", "", ""]
        print("| " + " | ".join(str(x) for x in row) + " |")
PY
