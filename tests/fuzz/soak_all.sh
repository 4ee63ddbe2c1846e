#!/usr/bin/env bash
# soak_all.sh VGC WORK_DIR
# `vgc fuzz --all` (docs/fuzzing.md "Soak") on stand-ins for the 13
# libFuzzer binaries: every target is run (two at a time) from its
# committed corpus and its fixed crashes, a finding does not stop the soak
# (the stand-in for fuzz_text "crashes" once and keeps going; the table
# counts it and the exit code is 1), the CPU time each stand-in burns is
# measured (not the wall clock: each also sleeps), each
# run's new input is merged into the work corpus (-merge=1), the next soak
# starts from that work corpus, and the table is in a fixed target order.
. "$(dirname "$0")/stand_in_lib.sh" soak_all "$@"
targets="verse_packet text stream differential mesh_manifold mesh_subdivision property_layers property_polygons
  property_creases property_bones property_values property_ids property_commands"
for t in $targets; do
  mkdir -p "$work/src/corpora/fuzz/fuzz_$t"
  echo "seed of $t" >"$work/src/corpora/fuzz/fuzz_$t/seed-1"
  cat >"$work/fuzz/fuzz_$t" <<'SCRIPT'
#!/usr/bin/env bash
# A stand-in libFuzzer: -merge=1 OUT IN copies IN's files missing from OUT;
# one input file: a re-run to sign a crash; otherwise a fork-mode campaign.
me=$(basename "$0")
args=() merge=0 prefix=""
for a in "$@"; do
  case "$a" in
    -merge=1) merge=1 ;;
    -artifact_prefix=*) prefix=${a#-artifact_prefix=} ;;
    -*) ;;
    *) args+=("$a") ;;
  esac
done
if [ "$merge" = 1 ]; then
  for f in "${args[1]}"/*; do [ -e "${args[0]}/$(basename "$f")" ] || cp "$f" "${args[0]}/"; done
  echo "MERGE-OUTER: done"
  exit 0
fi
if [ -f "${args[0]}" ]; then
  echo "vgc-fuzz: FINDING in $me: the stand-in's finding"
  exit 1
fi
corpus=${args[0]}
n=$(ls "$corpus" | wc -l)
# A fixed amount of computing (about 0.2 CPU s, however loaded the machine
# is), then 0.5 s asleep: CPU time is not wall time.
for ((i = 0; i < 200000; i++)); do :; done
sleep 0.5
echo "new input of $me, run $n" >"$corpus/new-$n"
if [ "$me" = fuzz_text ]; then
  echo "crash" >"${prefix}crash-1"
  echo "#10: cov: 7 ft: 8 corp: $((n + 1)) exec/s 10 oom/timeout/crash: 0/0/1 time: 1s job: 1 dft_time: 0"
fi
echo "#20: cov: 7 ft: 9 corp: $((n + 1)) exec/s 20 oom/timeout/crash: 0/0/0 time: 1s job: 2 dft_time: 0"
echo "INFO: exiting: 0 time: 1s"
SCRIPT
  chmod +x "$work/fuzz/fuzz_$t"
done
mkdir -p "$work/src/corpora/fuzz/fuzz_verse_packet-crashes"
echo "fixed crash" >"$work/src/corpora/fuzz/fuzz_verse_packet-crashes/crash-old"

soak() {
  "$vgc" fuzz --all --time 2 --jobs 2 --fuzz-build "$work" --source-dir "$work/src" \
    --work-corpus "$work/wc" >"$work/soak.out" 2>"$work/soak.err"
}
soak
rc=$?
cat "$work/soak.out"
[ "$rc" = 1 ] || { cat "$work/soak.err"; fail "exit $rc, expected 1 (fuzz_text's finding)"; }
table=$(ls "$work"/src/reports/fuzz/soak/*/soak.json) || fail "no soak.json"
python3 - "$table" "$work/wc" <<'PY' || exit 1
import json, os, sys
s = json.load(open(sys.argv[1]))
names = [r["target"] for r in s["rows"]]
want = ["fuzz_" + t for t in "verse_packet text stream differential mesh_manifold mesh_subdivision property_layers property_polygons property_creases property_bones property_values property_ids property_commands".split()]
assert names == want, names
for r in s["rows"]:
    t = r["target"]
    assert r["campaign_exit"] in (0, 1), (t, r["campaign_exit"])
    assert r["executions"] == 20, (t, r["executions"])
    assert r["merged"] and r["work_files"] == r["start_files"] + 1, (t, r["work_files"])  # and the new input
    # The stand-in computes ~0.2 CPU s and sleeps 0.5 s: CPU time is measured, not the wall time.
    assert 0.05 < r["cpu_s"] < r["wall_s"] - 0.4, (t, r["cpu_s"], r["wall_s"])
    assert r["findings"] == (1 if t == "fuzz_text" else 0), (t, r["findings"])
vp = s["rows"][0]
assert vp["start_files"] == 2, vp["start_files"]  # the seed and the fixed crash
assert "the stand-in's finding" in open(os.path.join(os.path.dirname(sys.argv[1]), "soak.md")).read()
PY
# A second soak starts from the work corpus the first one left.
soak
python3 - "$work/src/reports/fuzz/soak" <<'PY' || exit 1
import json, os, sys
runs = sorted(os.listdir(sys.argv[1]))
assert len(runs) == 2, runs
s = json.load(open(os.path.join(sys.argv[1], runs[-1], "soak.json")))
st = {r["target"]: r for r in s["rows"]}
assert st["fuzz_stream"]["work_files_before"] == 2 and st["fuzz_stream"]["start_files"] == 3, st["fuzz_stream"]
assert st["fuzz_stream"]["work_files"] == 3, st["fuzz_stream"]["work_files"]
PY
echo "soak_all: 13 targets, a finding counted without stopping, CPU time measured, work corpus merged and reused"
