#!/usr/bin/env bash
# dedup_minimize.sh VGC FAULT_PLUGIN WORK_DIR — fuzz findings are grouped by
# clause and status, and each group's counterexample is minimized before it
# is written (issue 19, item 9). A stand-in for fuzz_property_layers saves
# three crash inputs whose FINDING lines name LAYER-BASE-2 with three
# different messages, each printing a 14-command counterexample of which
# one command (layer_destroy 1) shows it. `vgc fuzz` against the fault
# plugin (VGC_FAULT=base-layer-destroyable) must report ONE finding of three
# inputs, with a counterexample of at most 2 commands that `vgc replay`
# still names LAYER-BASE-2. It used to report three "unique" findings, each
# with the 14 commands.
. "$(dirname "$0")/stand_in_lib.sh" dedup_minimize "$1" "$3"
plugin=$2
name=fuzz_property_layers
for k in a b c; do printf 'input %s' "$k" >"$work/crash-$k"; done
cat >"$work/fuzz/$name" <<SCRIPT
#!/usr/bin/env bash
for a in "\$@"; do
  case "\$a" in -artifact_prefix=*) prefix=\${a#-artifact_prefix=} ;; -fork=*) campaign=1 ;; -*) ;; *) input=\$a ;; esac
done
if [ -n "\${campaign:-}" ]; then
  cp "$work/crash-a" "$work/crash-b" "$work/crash-c" "\$prefix"
  echo "#2	DONE   cov: 10 ft: 20 corp: 1/9b exec/s: 2 rss: 30Mb"
  exit 0
fi
case "\$(cat "\$input")" in
  *a) what="observed ok" ;;
  *b) what="observed ok, and the layer is gone" ;;
  *c) what="the base layer was destroyed" ;;
esac
echo "vgc-fuzz: FINDING in $name: LAYER-BASE-2 (MUST, fail): \\\`layer_destroy 1\\\`: expected rejected BASE_LAYER, \$what"
echo "----8<---- counterexample.vgc"
for i in 0 1 2 3 4 5 6 7 8 9 10 11; do echo "vertex_set_xyz_real64 0 \$i \$i 0.5 -1"; done
echo 'layer_create 5 "extra" VERTEX_REAL 0 0'
echo "layer_destroy 1"
echo "----8<----"
exit 1
SCRIPT
chmod +x "$work/fuzz/$name"
out=$(VGC_FAULT=base-layer-destroyable "$vgc" fuzz property_layers --time 1 --impl "plugin:$plugin" --fuzz-build "$work" \
      --source-dir "$work/src" 2>&1)
rc=$?
[ "$rc" -eq 1 ] || { printf '%s\n' "$out" | tail -20; fail "expected exit 1 (a finding), got $rc"; }
summary=$(ls "$work"/src/reports/fuzz/$name/*/summary.json) || fail "no summary.json"
python3 - "$summary" <<'PY' || exit 1
import json, sys
s = json.load(open(sys.argv[1]))
c = s["crashes"]
assert len(c) == 1, "expected one finding, got %d: %s" % (len(c), [x["signature"] for x in c])
assert c[0]["inputs"] == 3, "expected 3 inputs in it, got %s" % c[0]["inputs"]
assert c[0]["clause"] == "LAYER-BASE-2", c[0]["clause"]
assert c[0]["replayed_clause"] == "LAYER-BASE-2", "vgc replay named %r" % c[0]["replayed_clause"]
PY
cex=$(ls "$work"/src/reports/fuzz/$name/*/counterexamples/crash-1*.vgc)
n=$(grep -c '^[a-z]' "$cex")
[ "$n" -le 2 ] || { cat "$cex"; fail "the counterexample has $n commands, expected at most 2 (minimized)"; }
grep -q '^layer_destroy 1$' "$cex" || { cat "$cex"; fail "the minimized counterexample lost layer_destroy 1"; }
echo "dedup_minimize: three inputs, one LAYER-BASE-2 finding, counterexample minimized to $n command(s)"
