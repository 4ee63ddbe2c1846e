#!/usr/bin/env bash
# stop_at_first.sh VGC WORK_DIR
# `vgc fuzz --stop-at-first` in fork mode stops the jobs once a crash input
# is saved, and saved means written whole. The stand-in for the libFuzzer
# binary creates its crash file empty, writes it 1.5 s later (as a slow
# fopen ... fwrite would), then never stops. The campaign must keep the
# whole input (stopping at the empty file used to leave an input that
# replayed to nothing), stop before --time, and say it stopped.
. "$(dirname "$0")/stand_in_lib.sh" stop_at_first "$@"
cat >"$work/fuzz/fuzz_stream" <<'SCRIPT'
#!/usr/bin/env bash
prefix="" last=""
for a in "$@"; do
  case "$a" in -artifact_prefix=*) prefix=${a#-artifact_prefix=} ;; esac
  last=$a
done
[ -f "$last" ] && exit 0  # run on one input (the campaign's re-run): nothing found
echo "#1	INITED cov: 10 ft: 20 corp: 1/9b exec/s: 1 rss: 30Mb"
: >"${prefix}crash-0123"
sleep 1.5
printf 'the whole input\n' >"${prefix}crash-0123"
sleep 300
SCRIPT
chmod +x "$work/fuzz/fuzz_stream"
out=$("$vgc" fuzz stream --time 60 --stop-at-first --jobs 2 --fuzz-build "$work" --source-dir "$work/src" 2>&1)
rc=$?
printf '%s\n' "$out" | tail -n 12
summary=$(ls "$work"/src/reports/fuzz/fuzz_stream/*/summary.json) || fail "no summary.json (exit $rc)"
python3 - "$summary" <<'PY' || exit 1
import json, os, sys
s = json.load(open(sys.argv[1]))
assert s["killed_at_deadline"] is False, "ran to the deadline instead of stopping at the finding"
assert s["crash_inputs"] == 1, s["crash_inputs"]
crashes = os.path.join(os.path.dirname(sys.argv[1]), "crashes", "crash-0123")
data = open(crashes).read()
assert data == "the whole input\n", "the saved input is %r: the jobs were stopped while it was being written" % data
PY
echo "stop_at_first: stopped at the finding, its input whole"
