#!/usr/bin/env bash
# concurrent_runs.sh VGC WORK_DIR
# Two `vgc fuzz` campaigns of the same target and seed started together (a
# script timing faults side by side does this) each get a run directory of
# their own and each write a whole summary. They used to share one
# directory, named by the second and the seed, and one of them aborted.
. "$(dirname "$0")/stand_in_lib.sh" concurrent_runs "$@"
cat >"$work/fuzz/fuzz_stream" <<'SCRIPT'
#!/usr/bin/env bash
echo "#1	INITED cov: 10 ft: 20 corp: 1/9b exec/s: 1 rss: 30Mb"
sleep 1
echo "Done 1 runs in 1 second(s)"
SCRIPT
chmod +x "$work/fuzz/fuzz_stream"
"$vgc" fuzz stream --time 5 --seed 7 --fuzz-build "$work" --source-dir "$work/src" >"$work/a.out" 2>&1 &
a=$!
"$vgc" fuzz stream --time 5 --seed 7 --fuzz-build "$work" --source-dir "$work/src" >"$work/b.out" 2>&1 &
b=$!
wait $a; ra=$?
wait $b; rb=$?
[ $ra = 0 ] && [ $rb = 0 ] || { tail -5 "$work/a.out" "$work/b.out"; fail "exit codes $ra and $rb, expected 0 and 0"; }
n=$(ls "$work"/src/reports/fuzz/fuzz_stream/*/summary.json | wc -l)
[ "$n" = 2 ] || { ls -R "$work/src/reports"; fail "$n summaries, expected one per campaign"; }
echo "concurrent_runs: two campaigns, two run directories, two summaries"
