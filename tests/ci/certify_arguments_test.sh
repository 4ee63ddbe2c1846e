#!/usr/bin/env bash
# certify_arguments_test.sh VGC — `vgc certify` checks its arguments before
# any case runs (issue 19, item 6): a --baseline that is a directory, or that
# cannot be read, is an error (a directory used to be taken as an empty
# baseline); a --reports directory that cannot really be written (a file
# is created and removed there first) is an error at once, not after the
# whole run (`--reports /proc/x` used to run every case, then fail). Then
# every other option value, of every subcommand (issue 31, item 7; below).
set -uo pipefail
[ $# -ge 1 ] || { echo "usage: $0 VGC" >&2; exit 2; }
vgc=$1
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_certify_args.XXXXXX")
trap 'chmod -R u+w "$tmp"; rm -rf "$tmp"' EXIT
cd "$tmp" || exit 2
fail() { echo "certify_arguments: $*" >&2; exit 1; }
# expect_usage WHAT WORD ARGS...: exit 2 within 5 s, the message holds WORD,
# and no case ran (no progress line, no report).
expect_usage() {
  local what=$1 word=$2; shift 2
  local t0=$(date +%s)
  "$vgc" certify --cases 2000 --clauses 'LAYER-*' "$@" >out 2>err
  local rc=$? t=$(( $(date +%s) - t0 ))
  [ $rc = 2 ] || { cat out err >&2; fail "$what: exit $rc, expected 2"; }
  [ $t -lt 5 ] || fail "$what: took $t s: it ran cases first"
  grep -qi -- "$word" err || { cat err >&2; fail "$what: the message does not say '$word'"; }
  ! grep -q "cases (" err || { cat err >&2; fail "$what: cases ran before the error"; }
}
mkdir bdir
expect_usage "a baseline that is a directory" "directory" --baseline bdir --reports R
printf 'LAYER-BASE-1 known\n' >unreadable; chmod 000 unreadable
if ! cat unreadable >/dev/null 2>&1; then  # root reads anything: then this case says nothing
  expect_usage "an unreadable baseline" "cannot read" --baseline unreadable --reports R
fi
expect_usage "reports under /proc" "reports" --reports /proc/x
printf 'x' >afile
expect_usage "reports under a file" "reports" --reports afile/sub
mkdir ro; chmod 555 ro
if ! touch ro/probe 2>/dev/null; then
  expect_usage "a read-only reports directory" "reports" --reports ro/R
fi

# Every option value is checked before any work (issue 31, item 7): empty,
# out of range and meaningless values and combinations, in every
# subcommand, are exit 2 with a message naming the option; never an abort
# (`--reports ""` was an uncaught filesystem_error, exit 134, after a whole
# certification with `--mesh ""`), a clamp (`--seed 18446744073709551616`
# ran with seed 18446744073709551615), a run that stops at once (`--budget
# inf`) or an option silently ignored (`--levels` without `--mesh`, `serve
# --like-r6` without `--verse`).
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >tri.obj
printf 'layer_create 1 vertex_xyz_real64 0 real64 a\n' >one.vgc
expect_usage "an empty --reports" "--reports" --reports ""
expect_usage "an empty --impl" "--impl" --impl "" --reports R
expect_usage "an empty --clauses" "--clauses" --clauses "" --reports R
expect_usage "an empty --baseline" "--baseline" --baseline "" --reports R
expect_usage "a seed past 2^64-1" "--seed" --seed 18446744073709551616 --reports R
expect_usage "a negative seed" "--seed" --seed -1 --reports R
expect_usage "a hexadecimal seed" "--seed" --seed 0x10 --reports R
for bad in inf nan -1 0 1e300 "" 5s; do
  expect_usage "--budget '$bad'" "--budget" --budget "$bad" --reports R
  expect_usage "--timeout '$bad'" "--timeout" --timeout "$bad" --reports R
  expect_usage "--start-timeout '$bad'" "--start-timeout" --start-timeout "$bad" --reports R
done
expect_usage "a size of 0" "--max-size" --max-size 0 --reports R
for bad in 1/0 0/2 3/2 "1/ 2" "+1/2" 1/99999999999 1 ""; do
  expect_usage "--shard '$bad'" "--shard" --shard "$bad" --reports R
done
expect_usage "--levels without --mesh" "--levels" --levels 3 --reports R
expect_usage "--verse-bone-form off the Verse wire" "--verse-bone-form" --verse-bone-form spec --reports R
[ ! -e R ] || fail "a refused run left $tmp/R behind"

# expect_refused WHAT WORD ARGS...: any subcommand; exit 2 within 10 s,
# the message holds WORD, nothing aborted.
expect_refused() {
  local what=$1 word=$2; shift 2
  timeout 20 "$vgc" "$@" </dev/null >out 2>err
  local rc=$?
  [ $rc = 2 ] || { cat out err >&2; fail "$what: exit $rc, expected 2"; }
  grep -qi -- "$word" err || { cat err >&2; fail "$what: the message does not say '$word'"; }
  ! grep -q "terminate called" err || { cat err >&2; fail "$what: aborted"; }
}
expect_refused "cases past an int" "--cases" certify --cases 99999999999 --reports R
expect_refused "no cases" "--cases" certify --cases 0 --reports R
expect_refused "an octal-looking count" "--cases" certify --cases 0x10 --reports R
expect_refused "an empty --mesh" "--mesh" certify --mesh "" --reports R
expect_refused "an empty --mesh and --reports" "--reports" certify --mesh "" --reports ""
expect_refused "--levels 5" "--levels" certify --mesh tri.obj --levels 5 --reports R
# --budget, --clauses, --timeout and --levels apply to a mesh run; what draws
# cases does not.
for opt in "--seed 3" "--cases 9" "--max-size 9" "--baseline one.vgc"; do
  # shellcheck disable=SC2086
  expect_refused "$opt with --mesh" "${opt%% *}" certify --mesh tri.obj $opt --reports R
done
[ ! -e R ] || fail "a refused run left $tmp/R behind"
expect_refused "replay of an empty file name" "file" replay ""
expect_refused "replay --timeout inf" "--timeout" replay one.vgc --timeout inf
expect_refused "replay --start-timeout 0" "--start-timeout" replay one.vgc --start-timeout 0
expect_refused "replay --verse-bone-form off the wire" "--verse-bone-form" replay one.vgc --verse-bone-form r6
expect_refused "merge of an empty run directory" "run_dirs" merge ""
expect_refused "merge --reports ''" "--reports" merge R1 R2 --reports ""
expect_refused "result of an empty clause id" "clause" result R ""
expect_refused "result of an empty run directory" "run_dir" result "" LAYER-BASE-1
expect_refused "result of an unknown clause id" "unknown clause id" result R LAYER-BASE-99
expect_refused "fuzz --time inf" "--time" fuzz stream --time inf
expect_refused "fuzz --jobs 0" "--jobs" fuzz stream --jobs 0
expect_refused "fuzz --seed past 2^32-1" "--seed" fuzz stream --seed 4294967296
expect_refused "fuzz --timeout -1" "--timeout" fuzz differential --timeout -1
expect_refused "fuzz --wall-cap nan" "--wall-cap" fuzz --all --cpu-time --wall-cap nan
expect_refused "fuzz --target-time NAME=inf" "--target-time" fuzz --all --target-time stream=inf
expect_refused "fuzz --max-len 0" "--max-len" fuzz stream --max-len 0
expect_refused "fuzz --impl ''" "--impl" fuzz differential --impl ""
expect_refused "serve --verse ''" "--verse" serve --verse ""
expect_refused "serve --like-r6 without --verse" "--like-r6" serve --like-r6
expect_refused "serve --done with --verse" "--done" serve --done --verse 0
expect_refused "serve --impl ''" "--impl" serve --impl ""
expect_refused "import of an empty file name" "file" import ""
expect_refused "apply of an empty file name" "file" apply ""

echo "certify_arguments: bad baselines and unwritable reports directories are rejected before any case; every empty, out-of-range or meaningless option value of every subcommand is exit 2 naming the option"
