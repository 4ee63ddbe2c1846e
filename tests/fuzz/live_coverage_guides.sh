#!/usr/bin/env bash
# live_coverage_guides.sh VGC FUZZ_BUILD TARGET PLUGIN SOURCE_DIR WORK
# (libFuzzer build only) Fuzzing guided by the implementation's own coverage
# (docs/fuzzing.md "Coverage of the implementation"), end to end over exec:
# PLUGIN is examples/c_host built with clang's inline 8-bit counters, PC
# table and vgc's coverage runtime, served by `VGC serve`.
#  1. The same committed corpus run once through TARGET (fuzz_differential,
#     -runs=0: libFuzzer only reads the corpus) with the node's coverage
#     guiding and only observed: the reference's coverage (cov) is the same,
#     the features (ft) are more when guiding: the node's edges are
#     libFuzzer features.
#  2. A short campaign of `VGC fuzz differential --impl exec:... --coverage-report`
#     says in its summary that the node's coverage was seen, how many of its
#     counters were reached and how many of its functions entered, and names
#     every function of the node (llvm-symbolizer on the PC table's entries):
#     ch_node_apply, which every input enters, among the entered ones at its
#     line in c_host_node.c, and as many never entered as the counts say.
set -u
vgc=$1 fbuild=$2 target=$3 plugin=$4 src=$5 work=$6
fail() { echo "live_coverage_guides: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work/corpus" "$work/src/corpora/fuzz/fuzz_differential"
cp "$src/corpora/fuzz/fuzz_differential/"* "$work/corpus/"
inited() {  # MODE -> "cov ft" of libFuzzer's INITED line
  VGC_FUZZ_IMPL="exec:$vgc serve --impl plugin:$plugin" VGC_FUZZ_IMPL_COVERAGE=$1 \
    "$target" -runs=0 -detect_leaks=0 -max_len=1024 "$work/corpus" >"$work/inited-$1.log" 2>&1 ||
    fail "$1: $target -runs=0 failed: $(tail -n 5 "$work/inited-$1.log")"
  sed -n 's/^#[0-9]*[[:space:]]*INITED cov: \([0-9]*\) ft: \([0-9]*\).*/\1 \2/p' "$work/inited-$1.log" | tail -n 1
}
read -r cov_g ft_g <<<"$(inited guide)"
read -r cov_o ft_o <<<"$(inited observe)"
echo "live_coverage_guides: corpus of $(ls "$work/corpus" | wc -l) inputs: guide cov $cov_g ft $ft_g; observe cov $cov_o ft $ft_o"
[ -n "$ft_g" ] && [ -n "$ft_o" ] || fail "no INITED line (see $work/inited-*.log)"
grep -q "the implementation's coverage is seen: [0-9]* counters" "$work/inited-guide.log" ||
  fail "the target did not say the node's coverage is seen: $(grep -m1 "coverage" "$work/inited-guide.log")"
[ "$cov_g" -eq "$cov_o" ] || fail "the reference's coverage differs: $cov_g vs $cov_o"
[ "$ft_g" -gt "$ft_o" ] || fail "guiding added no feature: ft $ft_g vs $ft_o"

cp "$src/corpora/fuzz/fuzz_differential/seed-cube.bin" "$work/src/corpora/fuzz/fuzz_differential/"
"$vgc" fuzz differential --impl "exec:$vgc serve --impl plugin:$plugin" --time 20 --seed 1 --fuzz-build "$fbuild" \
  --coverage-report \
  --source-dir "$work/src" >"$work/campaign.out" 2>&1
rc=$?
# 0 or 1: what it finds in the example node is not this test's business.
[ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || { tail -n 20 "$work/campaign.out"; fail "the campaign exited $rc"; }
summary=$(ls "$work"/src/reports/fuzz/fuzz_differential/*/summary.json) || fail "no summary.json"
python3 - "$summary" "$src" <<'PY' || fail "summary: see above"
import json, sys
s = json.load(open(sys.argv[1]))
ic = s["implementation_coverage"]
assert ic and ic["mode"] == "guide" and ic["seen"], ic
assert 0 < ic["counters_reached"] <= ic["counters"], ic
assert 0 < ic["functions_entered"] <= ic["function_entries"], ic
md = open(sys.argv[1].replace("summary.json", "summary.md")).read()
line = [l for l in md.splitlines() if l.startswith("| implementation coverage |")]
assert line and "counters reached" in line[0] and "functions entered" in line[0], line
print("live_coverage_guides: %s" % line[0])
# --coverage-report: every function named, the never-entered ones counted.
report = ic["coverage_report"]
assert report, "no coverage report: %s" % ic.get("coverage_report_note")
text = open(report).read()
never = ic["function_entries"] - ic["functions_entered"]
assert ic["functions_never_entered_count"] == never, (ic["functions_never_entered_count"], never)
assert "## Never entered (%d)" % never in text, text[:400]
assert "## Entered (%d)" % ic["functions_entered"] in text, text[:400]
entered = text.split("## Entered")[1]
import re
# Named at the line that opens it in the source (an entry PC named wrong
# lands inside another function, or on a line of its body).
src = open(sys.argv[2] + "/examples/c_host/c_host_node.c").read().splitlines()
opening = [i + 1 for i, l in enumerate(src) if l.startswith("const char* ch_node_apply(")]
apply = [l for l in entered.splitlines() if l.startswith("- `ch_node_apply`")]
assert opening and apply and apply[0].endswith("c_host_node.c:%d" % opening[0]), \
    "ch_node_apply not named at c_host_node.c:%s among the entered: %s" % (opening, apply or entered[:600])
names = [l.split("`")[1] for l in text.splitlines() if l.startswith("- `")]
assert len(names) == len(set(names)), "a function named twice: %s" % sorted(n for n in names if names.count(n) > 1)
unnamed = [l for l in text.splitlines() if l.startswith("- `") and "+0x" in l]
assert not unnamed, "functions not named: %s" % unnamed[:5]
assert "functions never entered" in md, "summary.md does not say how many functions were never entered"
html = open(sys.argv[1].replace("summary.json", "report.html")).read()
assert "no input entered" in html and all(n.split(" (")[0] in html for n in ic["functions_never_entered"]), \
    "report.html does not list the functions never entered"
print("live_coverage_guides: %d of %d functions never entered, every one named (%s)" % (never, ic["function_entries"], report))
PY
