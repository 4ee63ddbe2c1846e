#!/usr/bin/env bash
# vgc_script_test.sh SOURCE_DIR WORK_DIR — ./vgc says at once that a
# mistyped command is not one, naming the commands, and exits 2 without
# configuring or building anything (a typo used to cost a whole build).
set -u
src=$1 work=$2
rm -rf "$work"
out=$(VGC_BUILD_DIR="$work/build" "$src/vgc" certifi 2>&1)
rc=$?
fail() { echo "vgc_script: $*" >&2; printf '%s\n' "$out" >&2; exit 1; }
[ $rc = 2 ] || fail "exit $rc, expected 2"
case "$out" in *"no command 'certifi'"*"certify"*) ;; *) fail "the message does not name the mistake and the commands" ;; esac
[ ! -e "$work/build" ] || fail "it configured a build before rejecting the command"
echo "vgc_script: a mistyped command is rejected at once"
