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

# `./vgc fuzz bogus` is rejected before any build, naming the targets; so is
# a baseline that is a directory (issue 19, item 6). Both used to start the
# whole build (and the clang fuzz build) first.
for args in "fuzz bogus" "fuzz --time 5 fuzz_bogus" "fuzz stream --baseline $work"; do
  rm -rf "$work"; mkdir -p "$work"
  out=$(VGC_BUILD_DIR="$work/build" VGC_FUZZ_BUILD_DIR="$work/build-fuzz" "$src/vgc" $args 2>&1)
  rc=$?
  [ $rc = 2 ] || fail "./vgc $args: exit $rc, expected 2"
  [ ! -e "$work/build" ] && [ ! -e "$work/build-fuzz" ] || fail "./vgc $args: it configured a build before rejecting it"
  case "$args" in
    *bogus*) case "$out" in *"unknown fuzz target"*"stream"*"property_"*) ;; *) fail "./vgc $args: the message does not name the targets" ;; esac ;;
    *baseline*) case "$out" in *"baseline"*"directory"*) ;; *) fail "./vgc $args: the message does not say the baseline is a directory" ;; esac ;;
  esac
done
echo "vgc_script: an unknown fuzz target or a bad baseline is rejected before any build"
