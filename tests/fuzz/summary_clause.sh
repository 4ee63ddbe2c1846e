#!/usr/bin/env bash
# summary_clause.sh VGC PROPERTY_TARGET FAULT_PLUGIN FAULT INPUT CLAUSE WORK_DIR
# `vgc fuzz` signs crashes with digits folded, for deduplication, but its
# summary must print the clause id exactly as the finding names it.
# A stand-in for the libFuzzer binary (the normal build has none) plays the
# campaign: it saves INPUT twice (once with a trailing byte, which
# byte_cases ignores: the same finding) as crash inputs. `vgc fuzz` then
# re-runs each through the real PROPERTY_TARGET (the replay driver) against
# the faulty plugin, and must report ONE unique crash of two inputs, shown
# with CLAUSE (e.g. BONE-FOREST-1, never BONE-FOREST-N).
set -u
vgc=$1 target=$2 plugin=$3 fault=$4 input=$5 clause=$6 work=$7
fail() { echo "summary_clause: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work/fuzz" "$work/src"
name=$(basename "$target")
cp "$input" "$work/crash-a"
{ cat "$input"; printf 'x'; } >"$work/crash-b"
cat >"$work/fuzz/$name" <<SCRIPT
#!/usr/bin/env bash
for a in "\$@"; do
  case "\$a" in -artifact_prefix=*) prefix=\${a#-artifact_prefix=} ;; -fork=*) campaign=1 ;; esac
done
if [ -n "\${campaign:-}" ]; then
  cp "$work/crash-a" "$work/crash-b" "\$prefix"
  echo "#2	DONE   cov: 10 ft: 20 corp: 1/9b exec/s: 2 rss: 30Mb"
  exit 0
fi
exec "$target" "\$@"
SCRIPT
chmod +x "$work/fuzz/$name"
out=$(VGC_FAULT="$fault" "$vgc" fuzz "${name#fuzz_}" --time 1 --impl "plugin:$plugin" --fuzz-build "$work" \
      --source-dir "$work/src" 2>&1)
rc=$?
printf '%s\n' "$out" | tail -n 20
[ "$rc" -eq 1 ] || fail "expected exit 1 (crashes found), got $rc"
summary=$(ls "$work"/src/reports/fuzz/"$name"/*/summary.json) || fail "no summary.json"
python3 - "$summary" "$clause" <<'PY' || exit 1
import json, re, sys
s = json.load(open(sys.argv[1])); clause = sys.argv[2]
c = s["crashes"]
assert len(c) == 1, "expected one unique crash, got %d" % len(c)
assert c[0]["inputs"] == 2, "expected 2 inputs in the crash, got %s" % c[0]["inputs"]
assert clause in c[0]["signature"].split(), "signature does not name %s: %s" % (clause, c[0]["signature"])
folded = re.sub(r"\d+", "N", clause)
assert folded in c[0]["dedup_key"], "dedup key not folded: %s" % c[0]["dedup_key"]
PY
md=$(dirname "$summary")/summary.md
grep -q -- "\*\*.*$clause " "$md" || fail "summary.md does not show $clause: $(grep '^- \*\*' "$md")"
! grep -q -- "${clause%-*}-N" "$md" || fail "summary.md shows a folded clause id"
grep -q -- "counterexample: .*$clause" "$(ls "$work"/src/reports/fuzz/"$name"/*/counterexamples/crash-1*.vgc)" \
  || fail "the counterexample's header does not name $clause"
# Grouped by clause; the replay command carries the run's environment and
# `vgc replay` of the counterexample names the same clause.
python3 - "$summary" "$clause" "$fault" <<'PY' || exit 1
import json, sys
s = json.load(open(sys.argv[1])); clause, fault = sys.argv[2], sys.argv[3]
g = s["clauses"]
assert [x["clause"] for x in g] == [clause], "clause groups: %s" % g
assert not g[0]["in_baseline"] and s["new_crashes"] == 1, "no baseline given, yet marked"
c = s["crashes"][0]
assert c["clause"] == clause, c["clause"]
assert ("VGC_FAULT='%s'" % fault) in c["replay"], "replay lacks VGC_FAULT: %s" % c["replay"]
assert ("VGC_FAULT='%s'" % fault) in c["replay_fuzzer"] and "VGC_FUZZ_PLUGIN=" in c["replay_fuzzer"], c["replay_fuzzer"]
w = c["replay"].split()
assert w[1].split("/")[-1] == "vgc" and w[2] == "replay", c["replay"]  # ./vgc, vgc or the installed path
assert c["replayed_clause"] == clause, "vgc replay named %r" % c["replayed_clause"]
assert s["time_to_first_finding_s"] is not None
PY
# With the clause in a --baseline: marked, not new, exit 0.
printf '# known\n%s accepted for this test\n' "$clause" >"$work/baseline.txt"
out=$(VGC_FAULT="$fault" "$vgc" fuzz "${name#fuzz_}" --time 1 --impl "plugin:$plugin" --fuzz-build "$work" \
      --source-dir "$work/src" --baseline "$work/baseline.txt" 2>&1)
rc=$?
[ "$rc" -eq 0 ] || fail "with $clause in the baseline: expected exit 0, got $rc: $(printf '%s\n' "$out" | tail -5)"
summary=$(ls -t "$work"/src/reports/fuzz/"$name"/*/summary.json | head -1)
python3 - "$summary" "$clause" <<'PY' || exit 1
import json, sys
s = json.load(open(sys.argv[1])); clause = sys.argv[2]
g = s["clauses"]
assert g[0]["clause"] == clause and g[0]["in_baseline"], g
assert g[0]["baseline_reason"] == "accepted for this test", g[0]["baseline_reason"]
assert s["new_crashes"] == 0
PY
grep -q -- "$clause.*\[baseline: accepted for this test\]" "$(dirname "$summary")/summary.md" || fail "summary.md does not mark the baseline"
echo "summary_clause: one crash of two inputs, shown as $clause, grouped, replayed to it, marked by the baseline"
