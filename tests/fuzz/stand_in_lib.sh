# stand_in_lib.sh — sourced by the campaign tests that run `vgc fuzz` on a
# stand-in for a libFuzzer binary (time_limit.sh, stop_at_first.sh,
# concurrent_runs.sh). Usage, at the top of a test script:
#   . "$(dirname "$0")/stand_in_lib.sh" NAME "$@"     # arguments: VGC WORK_DIR
# Sets vgc and work, defines fail (prefixed with NAME), and makes a fresh
# WORK_DIR with fuzz/ (the stand-in binaries go there: --fuzz-build WORK_DIR)
# and src/ (--source-dir: the reports are written under it).
set -u
stand_in_test=$1 vgc=$2 work=$3
fail() { echo "$stand_in_test: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work/fuzz" "$work/src"
