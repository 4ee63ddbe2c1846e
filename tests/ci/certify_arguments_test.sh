#!/usr/bin/env bash
# certify_arguments_test.sh VGC — `vgc certify` checks its arguments before
# any case runs (issue 19, item 6): a --baseline that is a directory, or that
# cannot be read, is an error (a directory used to be taken as an empty
# baseline); a --reports directory that cannot really be written (a file
# is created and removed there first) is an error at once, not after the
# whole run (`--reports /proc/x` used to run every case, then fail).
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
echo "certify_arguments: bad baselines and unwritable reports directories are rejected before any case"
