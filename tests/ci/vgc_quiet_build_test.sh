#!/usr/bin/env bash
# vgc_quiet_build_test.sh SOURCE_DIR BUILD_DIR — `./vgc build TARGET` with
# nothing to rebuild prints no "Built target" line (issue 19, item 10: the
# inner loop's output is what changed, not a line per target). TARGET is
# vgc_quiet_build_probe, a target with no dependencies and no commands
# (tests/ci/CMakeLists.txt): building it never rebuilds anything a test
# running beside this one uses.
set -u
src=$1 build=$2
out=$(VGC_BUILD_DIR="$build" "$src/vgc" build vgc_quiet_build_probe 2>&1)
rc=$?
fail() { echo "vgc_quiet_build: $*" >&2; printf '%s\n' "$out" >&2; exit 1; }
[ $rc = 0 ] || fail "exit $rc"
case "$out" in *"Built target"*) fail "it printed Built target lines with nothing to rebuild" ;; esac
echo "vgc_quiet_build: nothing rebuilt, nothing but 'vgc: building' said"
