#!/usr/bin/env bash
# certify_mesh_test.sh VGC REQUESTS_PLUGIN PLAIN_PLUGIN — a user's own mesh
# (issue 21 item 3). `vgc import` turns an OBJ grid of quads into a command
# file and refuses a 5-corner face naming file:line:col with foreign bytes
# escaped; `vgc certify --mesh` builds the mesh on the implementation and
# judges each claimed derived-geometry capability per level: the reference
# passes all four checks (exit 0); an exec implementation whose ?subdivide
# answers are skewed (subdivision_skew_proxy.py) fails SUBD-CATMARK-1 at
# levels 1 and 2 and nothing else (exit 1); the fault plugin with
# classify-misses-boundary fails MESH-CLASSIFY-1; a plugin claiming no
# capability has only the mesh's storage judged (exit 0); a node dropping ids
# past a storage bound fails VERTEX-SET-1 on a 66 x 66 grid; over the Verse
# wire (vgc serve --verse) the build is judged by the snapshot alone. The skewed run's directory holds
# the report, its picture marking the divergent refined points.
set -uo pipefail
[ $# -ge 3 ] || { echo "usage: $0 VGC REQUESTS_PLUGIN PLAIN_PLUGIN" >&2; exit 2; }
vgc=$1 requests=$2 plain=$3
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_certify_mesh.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 2
fail() { echo "certify_mesh: $*" >&2; exit 1; }

# A 3x3 grid of quads with one raised vertex (open: one boundary loop).
for j in 0 1 2 3; do for i in 0 1 2 3; do
  z=0; [ "$i$j" = 11 ] && z=0.3
  echo "v $i $j $z"
done; done >grid.obj
for j in 0 1 2; do for i in 0 1 2; do
  a=$((j * 4 + i + 1)); echo "f $a $((a + 1)) $((a + 5)) $((a + 4))"
done; done >>grid.obj

"$vgc" import grid.obj >grid.vgc 2>import.err || { cat import.err >&2; fail "vgc import of a quad grid failed"; }
[ "$(grep -c '^vertex_set_xyz_real64 0 ' grid.vgc)" = 16 ] || fail "import: expected 16 vertices"
[ "$(grep -c '^polygon_set_corner_uint32 1 ' grid.vgc)" = 9 ] || fail "import: expected 9 polygons"
grep -q 'OBJ has no creases' grid.vgc || fail "import: the file does not say what becomes of sharpness"
"$vgc" apply --strict grid.vgc >/dev/null || fail "the imported file does not apply on the reference"

bad=$'five\x1b[31m.obj'
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 2 2\nf 1 2 3 4 5\n' >"$bad"
"$vgc" import "$bad" >/dev/null 2>bad.err && fail "import accepted a 5-corner face"
grep -q '^five\\x1b\[31m\.obj:6:3: error: a face of 5 corners' bad.err || { cat -v bad.err >&2; fail "import's error does not name file:line:col escaped"; }

check() {  # check NAME EXPECTED_RC LINE-REGEX... : certify --mesh output has each line
  local name=$1 want=$2 rc
  shift 2
  rc=$(cat "$name.rc")
  [ "$rc" = "$want" ] || { cat "$name.out" >&2; fail "$name: exit $rc, expected $want"; }
  for re in "$@"; do grep -Eq -e "$re" "$name.out" || { cat "$name.out" >&2; fail "$name: no line matching $re"; }; done
}

"$vgc" certify --mesh grid.obj --levels 2 >ref.out 2>&1; echo $? >ref.rc
check ref 0 '^  pass +MESH-CLASSIFY-1 +manifold' '^  pass +NORMALS-SPLIT-1 +normals' \
  '^  pass +SUBD-CATMARK-1 +subdivision level 1' '^  pass +SUBD-CATMARK-1 +subdivision level 2' ': conformant on grid.obj'

# The proxy never answers ?digest (which certify --mesh does not ask), so
# the replay below must ask what certify asked, no more.
export VGC_PROXY_DIGEST_HANG=1
"$vgc" certify --mesh grid.obj --levels 2 --impl "exec:$here/subdivision_skew_proxy.py $vgc" --reports R \
  >skew.out 2>&1; echo $? >skew.rc
check skew 1 '^  fail +SUBD-CATMARK-1 +subdivision level 1 .*OpenSubdiv' '^  fail +SUBD-CATMARK-1 +subdivision level 2' \
  '^  pass +MESH-CLASSIFY-1' '^  pass +NORMALS-SPLIT-1' 'not conformant on grid.obj \(2 fail, 2 pass; stored as the reference stores it\)'
# Its run directory: the finding with the picture of the refined points.
run=$(sed -n 's/^report: \(.*\)\/summary.md$/\1/p' skew.out)
[ -s "$run/report.json" ] && [ -s "$run/counterexamples/SUBD-CATMARK-1.vgc" ] || fail "skew: no run directory written"
grep -q 'class="divergent-expected"' "$run/report.html" || fail "skew: report.html draws no divergent point"
grep -q '"id": "mesh.subdivision.level1"' "$run/report.json" || fail "skew: report.json has no per-level check"
# The mesh is judged whole: its program is not called shrunk nor given a seed.
grep -q "^The mesh's program, as vgc import writes it (a user's mesh is judged whole, not shrunk) (25 commands, from a fresh node; found by \`mesh.subdivision.level1\`):" \
  "$run/summary.md" || fail "skew: summary.md does not say the program is the mesh's own"
grep -q 'Shrunk counterexample' "$run/summary.md" "$run/report.html" && fail "skew: the mesh's program is called shrunk"
# The console prints the finding's replay line (issue 31 item 5), runnable
# as printed from any directory: it shows the finding again (exit 1).
line=$(sed -n 's/^ *replay SUBD-CATMARK-1: //p' skew.out)
[ -n "$line" ] || { cat skew.out >&2; fail "skew: no replay line on the console"; }
(cd / && eval "$line" >"$OLDPWD/skew.replay" 2>&1); rc=$?
[ $rc = 1 ] && grep -q SUBD-CATMARK-1 skew.replay || { cat skew.replay >&2; fail "skew: the printed replay line did not show the finding from / (exit $rc)"; }
grep -q '^#! mesh$' "$run/counterexamples/SUBD-CATMARK-1.vgc" || fail "skew: the counterexample is not marked #! mesh"
# Replay is certify for one program: the same finding in the same words.
grep -q "^fail SUBD-CATMARK-1 (MUST)" skew.replay || { cat skew.replay >&2; fail "skew: replay does not say fail SUBD-CATMARK-1 (MUST)"; }
unset VGC_PROXY_DIGEST_HANG

# A right answer later than vgc's --timeout (3 s: a loaded machine starts the
# proxy in over 1 s): a timeout naming what to raise,
# the run incomplete (exit 2), never a fail of the clause (issue 28).
VGC_PROXY_SLOW=8 "$vgc" certify --mesh grid.obj --levels 2 --timeout 3 \
  --impl "exec:$here/subdivision_skew_proxy.py $vgc" --reports R >slow.out 2>&1; echo $? >slow.rc
check slow 2 '^  timeout +SUBD-CATMARK-1 +subdivision level 2 .*raise --timeout' '^  pass +SUBD-CATMARK-1 +subdivision level 1' \
  ': incomplete on grid.obj' 'give --timeout more seconds'
grep -Eq '^  fail ' slow.out && { cat slow.out >&2; fail "slow: a limit of vgc's was reported as a fail"; }

# --clauses, --budget and --levels are honoured with --mesh (issue 28 item 4).
"$vgc" certify --mesh grid.obj --clauses 'SUBD-*' --levels 1 >sel.out 2>&1; echo $? >sel.rc
check sel 0 '^  pass +SUBD-CATMARK-1 +subdivision level 1' ': conformant on grid.obj \(1 pass;'
grep -Eq 'MESH-CLASSIFY-1|NORMALS-SPLIT-1|level 2' sel.out && { cat sel.out >&2; fail "sel: a check --clauses/--levels left out ran"; }
"$vgc" certify --mesh grid.obj --clauses 'NOPE-*' >nope.out 2>&1; echo $? >nope.rc
check nope 2 "--clauses pattern 'NOPE-\*' matches no clause id"
"$vgc" certify --mesh grid.obj --budget 0.000001 >budget.out 2>&1; echo $? >budget.rc
# Either of the budget's two limits may stop it first: its CPU seconds, or
# (on a loaded machine, 1e-05 s after the start) its wall-clock guard.
check budget 2 'stopped: the (budget \(--budget 1e-06: CPU seconds of vgc and the implementation\)|wall-clock guard \(1e-05 s, 10 x --budget, not counting the time spent waiting for a CPU\)) ran out' \
  ': incomplete on grid.obj'
grep -Eq '^  pass ' budget.out && { cat budget.out >&2; fail "budget: a check ran past the budget"; }

# The first SIGTERM stops a long mesh check within a second and writes an
# incomplete report (exit 143): a 150 x 150 quad grid, level 4.
python3 -c '
n = 150
for j in range(n + 1):
    for i in range(n + 1): print("v %d %d %g" % (i, j, ((i * 7 + j * 13) % 10) / 10.0))
for j in range(n):
    for i in range(n):
        a = j * (n + 1) + i + 1
        print("f %d %d %d %d" % (a, a + 1, a + n + 2, a + n + 1))' >big.obj
"$vgc" certify --mesh big.obj --levels 4 --clauses 'SUBD-*' --reports C >cancel.out 2>&1 &
pid=$!
for _ in $(seq 100); do grep -q 'up to level 4' cancel.out && break; sleep 0.1; done
sleep 2
kill -TERM "$pid"
t0=$(date +%s%N)
wait "$pid"; echo $? >cancel.rc
ms=$((($(date +%s%N) - t0) / 1000000))
check cancel 143 'stopped: cancelled by SIGTERM' ': incomplete on big.obj'
[ "$ms" -le 1000 ] || { cat cancel.out >&2; fail "cancel: the run took $ms ms to stop after SIGTERM"; }
run=$(sed -n 's/^report: \(.*\)\/summary.md$/\1/p' cancel.out)
grep -q '"verdict": "incomplete"' "$run/report.json" 2>/dev/null || { cat cancel.out >&2; fail "cancel: no incomplete report"; }

VGC_FAULT=classify-misses-boundary "$vgc" certify --mesh grid.obj --impl "plugin:$requests" >classify.out 2>&1
echo $? >classify.rc
check classify 1 '^  fail +MESH-CLASSIFY-1 +manifold .*boundary_loops' '^  pass +SUBD-CATMARK-1 +subdivision level 2'

# A plugin claiming no capability: the storage of the mesh is still judged.
"$vgc" certify --mesh grid.obj --impl "plugin:$plain" >plain.out 2>&1; echo $? >plain.rc
check plain 0 '^  built +the mesh: 25 commands, the same snapshot' '^  not-claimed +SUBD-CATMARK-1' \
  'conformant on grid.obj \(4 not-claimed; stored as the reference stores it\)' 'only the storage of the mesh was judged'
run=$(sed -n 's/^report: \(.*\)\/summary.md$/\1/p' plain.out)
grep -q '"id": "mesh.build"' "$run/report.json" || fail "plain: report.json has no mesh.build check"

# A node that drops ids past a storage bound (4,129, as the r6 host's):
# a 66 x 66 grid's last vertices are lost, and the final snapshot shows it.
for j in $(seq 0 65); do for i in $(seq 0 65); do echo "v $i $j 0"; done; done >big.obj
for j in $(seq 0 64); do for i in $(seq 0 64); do
  a=$((j * 66 + i + 1)); echo "f $a $((a + 1)) $((a + 67)) $((a + 66))"
done; done >>big.obj
VGC_FAULT=ids-past-storage-bound "$vgc" certify --mesh big.obj --levels 1 --impl "plugin:$requests" >bound.out 2>&1
echo $? >bound.rc
check bound 1 '^  fail +VERTEX-SET-1 +building the mesh \(8581 commands.*snapshot differs' 'not conformant on big.obj'

# The Verse wire route reports no verdicts: the build is judged by the
# snapshot alone (it was failed at the first command: "observed rejected").
. "$here/../fuzz/live_host_lib.sh"
start_verse_host "$vgc" "" 127.0.0.1:0 host.log || fail "vgc serve --verse did not start"
"$vgc" certify --mesh grid.obj --levels 1 --impl "verse:127.0.0.1:$host_port" >verse.out 2>&1; echo $? >verse.rc
check verse 0 '^  built +the mesh: 25 commands, the same snapshot' 'conformant on grid.obj'
echo "certify_mesh: import and certify --mesh judge a user's mesh per capability and level; faults are caught"
