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
grep -q -- "counterexample: .*$clause" "$(ls "$work"/src/reports/fuzz/"$name"/*/counterexamples/crash-1.vgc)" \
  || fail "the counterexample's header does not name $clause"
echo "summary_clause: one crash of two inputs, shown as $clause"
