#!/usr/bin/env bash
# fuzz/time_to_find.sh — a benchmark, not a test: for each fault of the fault
# plugin (tests/conformance/faults, VGC_FAULT=<fault>), how many seconds
# `vgc fuzz differential` takes to its first finding, from the committed
# corpus and from an empty corpus: the median over the seeds, each run
# capped. Prints a Markdown table (docs/fuzzing.md "Time to find").
#
#   fuzz/time_to_find.sh [--target differential|mesh_subdivision] [--cap S]
#                        [--seeds "1 2 3"] [--faults "a b ..."]
#                        [--corpora "committed empty"] [--vgc VGC] [--plugin SO]
#                        [--fuzz-build DIR]
#
# --target mesh_subdivision times the mesh subdivision target instead, on
# the seeded faults of the reference's subdivision (VGC_FUZZ_MESH_FAULT,
# fuzz/targets/fuzz_mesh_subdivision.cpp: every one by default); its findings are
# disagreements with OpenSubdiv, named by scheme, not by clause.
#
# Defaults: cap 120 s, seeds 1 2 3, both corpora, every fault the
# differential target can reach (see below), build/cli/vgc,
# build/tests/conformance/libvgc_fault_plugin.so, build-fuzz. Each run is
#   VGC_FAULT=<fault> vgc fuzz differential --impl plugin:SO --seed N
#       --time CAP --stop-at-first [--empty-corpus] --jobs 1
# and its time is summary.json's time_to_first_finding_s (from the start of
# `vgc fuzz` to the first saved crash input: startup and corpus loading
# included); not found within the cap counts as the cap and prints ">CAP".
# The clause column is the clause the first run's finding named (the fault
# table's clause is in parentheses when they differ).
#
# Faults left out unless named with --faults, and why: the capability
# faults (subdivision-ignores-creases, classify-misses-boundary,
# normals-flat, loop-warren-weights, edit-holes-ignored,
# subdivision-non-manifold-smooth, loop-edges-by-vertex-pair): the
# differential target sends commands only, no capability request (the mesh
# targets and certify judge them); wrong-reason-codes: a
# SHOULD-level difference, a note and never a finding; pick-highest-layer-id:
# an implementation choice the check follows (implementation_choice.h).
set -u
root="$(cd "$(dirname "$0")/.." && pwd)"
cap=120 seeds="1 2 3" faults="" corpora="committed empty" target=differential
vgc="$root/build/cli/vgc" plugin="$root/build/tests/conformance/libvgc_fault_plugin.so"
fuzz_build="${VGC_FUZZ_BUILD_DIR:-$root/build-fuzz}"
while [ $# -gt 0 ]; do
  case "$1" in
    --cap) cap=$2; shift 2 ;;
    --target) target=$2; shift 2 ;;
    --seeds) seeds=$2; shift 2 ;;
    --faults) faults=$2; shift 2 ;;
    --corpora) corpora=$2; shift 2 ;;
    --vgc) vgc=$2; shift 2 ;;
    --plugin) plugin=$2; shift 2 ;;
    --fuzz-build) fuzz_build=$2; shift 2 ;;
    *) echo "time_to_find: unknown option $1" >&2; exit 2 ;;
  esac
done
table="$root/tests/conformance/faults/faulty_node.cpp"
[ -x "$vgc" ] || { echo "time_to_find: no vgc at $vgc (build it, or --vgc)" >&2; exit 2; }
[ -f "$plugin" ] || { echo "time_to_find: no fault plugin at $plugin (build vgc_fault_plugin, or --plugin)" >&2; exit 2; }
[ -x "$fuzz_build/fuzz/fuzz_$target" ] || { echo "time_to_find: no $fuzz_build/fuzz/fuzz_$target" >&2; exit 2; }
expected_clause() { sed -nE "s/^ *\\{\"$1\", \"([^\"]*)\".*/\\1/p" "$table" | head -1; }
case "$target" in
  differential) fault_var=VGC_FAULT impl=(--impl "plugin:$plugin") ;;
  mesh_subdivision)
    fault_var=VGC_FUZZ_MESH_FAULT impl=()
    expected_clause() { :; }
    [ -n "$faults" ] || faults=$(sed -nE 's/.*fault == "([a-z-]+)".*/\1/p' "$root/fuzz/targets/fuzz_mesh_subdivision.cpp" | tr '\n' ' ')
    ;;
  *) echo "time_to_find: --target is differential or mesh_subdivision, not $target" >&2; exit 2 ;;
esac
if [ -z "$faults" ]; then
  skip=" none subdivision-ignores-creases classify-misses-boundary normals-flat loop-warren-weights edit-holes-ignored subdivision-non-manifold-smooth loop-edges-by-vertex-pair wrong-reason-codes pick-highest-layer-id "
  for f in $(sed -nE 's/^ *\{"([a-z0-9-]+)", "[^"]*", "[a-z]+".*/\1/p' "$table"); do
    case "$skip" in *" $f "*) ;; *) faults="$faults $f" ;; esac
  done
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -n | awk '{ v[NR] = $1 } END { if (NR == 0) print "?"; else if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
echo "time_to_find: fuzz_$target, cap $cap s, seeds $seeds, corpora $corpora; $(uptime)" >&2
header="| fault | $([ "$target" = differential ] && echo "clause found" || echo "finding") |"
rule="|---|---|"
for c in $corpora; do header="$header $c corpus: median s (runs) |"; rule="$rule---|"; done
echo "$header"
echo "$rule"
for f in $faults; do
  want=$(expected_clause "$f")
  clause=""
  row=""
  for c in $corpora; do
    times=""
    runs=""
    for s in $seeds; do
      extra=""
      [ "$c" = empty ] && extra="--empty-corpus"
      env "$fault_var=$f" "$vgc" fuzz "$target" "${impl[@]}" --seed "$s" --time "$cap" --stop-at-first \
        --jobs 1 $extra --fuzz-build "$fuzz_build" --source-dir "$root" >"$work/out" 2>&1
      summary=$(sed -n 's/^summary: //p' "$work/out" | tail -1)
      t=$(python3 - "$summary" "$cap" "$target" <<'PY' 2>/dev/null
import json, re, sys
s = json.load(open(sys.argv[1])); cap = float(sys.argv[2])
t = s.get("time_to_first_finding_s")
def named(c):
    # The clause; for the mesh target (no clause) the finding's first words.
    if c["clause"] or sys.argv[3] == "differential":
        return c["clause"] or "-"
    sig = re.sub(r"^FINDING in \S+: ", "", c["signature"]).split(" (")[0]
    if len(sig) > 64:
        sig = sig[:64].rsplit(" ", 1)[0] + " ..."
    return sig.replace(" ", "_") or "-"
print("%.1f %s" % (t, named(s["crashes"][0]) if s["crashes"] else "-") if t is not None and t <= cap
      else "%s -" % ("inf"))
PY
)
      [ -n "$t" ] || t="inf -"
      secs=${t%% *} found=${t#* }
      [ -z "$clause" ] && [ "$found" != "-" ] && clause=$found
      if [ "$secs" = inf ]; then times="$times $cap"; runs="$runs >$cap"; else times="$times $secs"; runs="$runs $secs"; fi
      echo "  $f $c seed $s: ${runs##* } ($found) ${summary:-no summary}" >&2
      [ -n "$summary" ] && rm -rf "$(dirname "$summary")"
    done
    m=$(printf '%s\n' $times | median)
    all_capped=1
    for r in $runs; do case "$r" in '>'*) ;; *) all_capped=0 ;; esac; done
    [ "$all_capped" = 1 ] && m=">$cap"
    # A median at the cap is a run not found: say so.
    [ "$m" = "$cap" ] && m=">$cap"
    row="$row $m (${runs# }) |"
  done
  shown=${clause:--}
  [ "$target" = differential ] || shown=${shown//_/ }
  [ -n "$want" ] && [ "$clause" != "$want" ] && shown="$shown ($want)"
  echo "| $f | $shown |$row"
done
