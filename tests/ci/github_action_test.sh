#!/usr/bin/env bash
# github_action_test.sh — ci/github_action.sh (what action.yml runs), run
# locally as a GitHub runner would run it: GITHUB_WORKSPACE, RUNNER_TEMP,
# GITHUB_STEP_SUMMARY, GITHUB_OUTPUT and GITHUB_ACTION_PATH point at a
# temporary directory, the INPUT_* variables are set as action.yml sets them.
#
#   github_action_test.sh SOURCE_DIR VGC FAULT_PLUGIN
#
# Checks, per run, the exit status, the outputs written, the job summary
# appended (what was there before is kept) and the ::error:: annotations:
# the reference (conformant, exit 0); the fault plugin with a seeded fault
# (not conformant, exit 1, naming LAYER-BASE-2); the same with a baseline
# relative to the workspace (conformant); a shard (its artifact name); a run
# cut short by its budget (incomplete, exit 2, with a report); a plugin that
# does not exist (error, exit 2, no report, vgc's message in the summary and
# the annotation); a program the shell cannot find (the annotation says what
# to do); a missing impl input; a job cancelled in the middle of the run
# (SIGINT to the script: outputs, summary and report all the same); and the
# merge of three shards (input merge: the unsharded verdict; a missing
# shard named).
set -uo pipefail

[ $# -eq 3 ] || { echo "usage: $0 SOURCE_DIR VGC FAULT_PLUGIN" >&2; exit 2; }
source_dir=$(cd "$1" && pwd)
vgc=$(realpath "$2")
fault_plugin=$(realpath "$3")
script=$source_dir/ci/github_action.sh

tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_action_test.XXXXXX")
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
failures=0
check() {  # check DESCRIPTION COMMAND...
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; failures=$((failures + 1)); fi
}
output() {  # output NAME: the value the last run wrote to GITHUB_OUTPUT
  sed -n "s/^$1=//p" "$run/output" | tail -n 1
}

# action NAME [VAR=VALUE...]: one run of the script in a fresh runner layout
# ($tmp/NAME); sets $run and $status, keeps stdout+stderr in $run/log.
action() {
  run=$tmp/$1
  shift
  mkdir -p "$run/workspace" "$run/runner_temp"
  printf 'summary of an earlier step\n' >"$run/summary"
  : >"$run/output"
  env -i PATH=/usr/bin:/bin HOME="$run" \
    GITHUB_WORKSPACE="$run/workspace" RUNNER_TEMP="$run/runner_temp" \
    GITHUB_STEP_SUMMARY="$run/summary" GITHUB_OUTPUT="$run/output" GITHUB_ACTION_PATH="$source_dir" \
    INPUT_VGC="$vgc" INPUT_CASES=30 INPUT_SEED=1 "$@" \
    bash "$script" >"$run/log" 2>&1
  status=$?
  echo "--- $(basename "$run"): exit $status"
}
show() { sed 's/^/    /' "$run/log"; }

# 1. The reference: conformant.
action reference INPUT_IMPL=reference
check "reference: exit 0" test "$status" -eq 0 || show
check "reference: verdict=conformant" test "$(output verdict)" = conformant
check "reference: exit-code=0" test "$(output exit-code)" = 0
dir=$(output report-dir)
check "reference: report-dir is a run directory under RUNNER_TEMP" test -f "$dir/report.json" -a "${dir#"$run/runner_temp/vgc-reports/"}" != "$dir"
check "reference: summary output names its summary.md" test "$(output summary)" = "$dir/summary.md"
check "reference: junit output names its junit.xml" test -f "$(output junit)"
check "reference: artifact-name=vgc-report" test "$(output artifact-name)" = vgc-report
check "reference: the job summary keeps the earlier step's" grep -qx 'summary of an earlier step' "$run/summary"
check "reference: summary.md is appended whole" bash -c 'tail -n +2 "$1" | head -n "$(wc -l <"$2")" | cmp -s - "$2"' _ "$run/summary" "$dir/summary.md"
check "reference: the job summary says CONFORMANT" grep -q '^# vgc certify: reference .* CONFORMANT' "$run/summary"
check "reference: no ::error:: annotation" bash -c '! grep -q "^::error" "$1"' _ "$run/log"
check "reference: one log line per property" grep -q '^\[1/[0-9]*\] [a-z.]* *pass' "$run/log"

# 2. A seeded fault through the plugin route: not conformant.
action fault INPUT_IMPL="plugin:$fault_plugin" VGC_FAULT=base-layer-destroyable
check "fault: exit 1" test "$status" -eq 1 || show
check "fault: verdict=not-conformant" test "$(output verdict)" = not-conformant
check "fault: exit-code=1" test "$(output exit-code)" = 1
check "fault: report-dir is set (the artifact is uploaded)" test -f "$(output report-dir)/summary.md"
check "fault: the job summary says NOT CONFORMANT" grep -q '^# vgc certify: .* NOT CONFORMANT' "$run/summary"
check "fault: the job summary names LAYER-BASE-2" grep -q 'LAYER-BASE-2' "$run/summary"
check "fault: an annotation for LAYER-BASE-2" grep -q '^::error title=vgc fail LAYER-BASE-2::.*layer_destroy' "$run/log"
check "fault: an annotation with the verdict" grep -q '^::error title=vgc certify::plugin:.*: not-conformant (' "$run/log"

# 3. The same with a baseline, relative to the workspace: conformant.
mkdir -p "$tmp/baselined/workspace/ci"
printf 'LAYER-BASE-2 the fault plugin destroys base layers (known)\n' >"$tmp/baselined/workspace/ci/vgc-baseline.txt"
action baselined INPUT_IMPL="plugin:$fault_plugin" VGC_FAULT=base-layer-destroyable INPUT_BASELINE=ci/vgc-baseline.txt
check "baseline: exit 0" test "$status" -eq 0 || show
check "baseline: verdict=conformant" test "$(output verdict)" = conformant
check "baseline: the job summary lists it as known" grep -q 'Known deviations' "$run/summary"

# 4. A shard: its own artifact name and a note in the summary.
action shard INPUT_IMPL=reference INPUT_SHARD=2/3
check "shard: exit 0" test "$status" -eq 0 || show
check "shard: artifact-name=vgc-report-shard-2-of-3" test "$(output artifact-name)" = vgc-report-shard-2-of-3
check "shard: the job summary names the shard" grep -qx '_vgc shard 2/3_' "$run/summary"
check "shard: report.json says shard 2/3" grep -q '"shard": "2/3"' "$(output report-dir)/report.json"

# 5. A run its budget cuts short: incomplete, with a report.
action budget INPUT_IMPL=reference INPUT_CLAUSES=LAYER-BASE-1 INPUT_CASES=100000 INPUT_BUDGET=0.3
check "budget: exit 2" test "$status" -eq 2 || show
check "budget: verdict=incomplete" test "$(output verdict)" = incomplete
check "budget: report-dir is set" test -f "$(output report-dir)/report.json"
check "budget: the job summary says INCOMPLETE" grep -q '^# vgc certify: .* INCOMPLETE' "$run/summary"
check "budget: the annotation says what to do" grep -q "^::error title=vgc certify::.*incomplete.*raise 'cases' or 'budget'" "$run/log"

# 6. A plugin that is not there: error, no report, vgc's message.
action missing INPUT_IMPL=plugin:build/libnot_there.so
check "missing plugin: exit 2" test "$status" -eq 2 || show
check "missing plugin: verdict=error" test "$(output verdict)" = error
check "missing plugin: report-dir is empty (nothing to upload)" test -z "$(output report-dir)"
check "missing plugin: the job summary quotes vgc" grep -q '^vgc certify: .*libnot_there.so' "$run/summary"
check "missing plugin: the annotation quotes vgc" grep -q '^::error title=vgc certify::vgc certify: .*libnot_there.so' "$run/log"

# 7. A program the shell cannot find: vgc's account and its "what to do".
action nohost INPUT_IMPL='exec:./no-such-host --vgc'
check "no such program: exit 2" test "$status" -eq 2 || show
check "no such program: verdict=error" test "$(output verdict)" = error
check "no such program: the annotation says what to do" grep -q '^::error title=vgc certify::vgc certify: exec:./no-such-host --vgc: cannot start it.* — what to do: the shell found no such program' "$run/log"

# 8. No impl input.
action noimpl
check "no impl: exit 2" test "$status" -eq 2 || show
check "no impl: the annotation names the input" grep -q "^::error title=vgc certify::the input 'impl' is required" "$run/log"
check "no impl: verdict=error" test "$(output verdict)" = error

# 9. A cancelled job: the runner sends SIGINT to the script alone (the
# step's entry process) in the middle of the run. The script passes it on;
# vgc writes its incomplete report, and the outputs and the job summary are
# written for it (issue 31, item 6: the script used to have no trap; vgc
# ran on and the runner killed everything 10 s later, with no report).
run=$tmp/cancelled
mkdir -p "$run/workspace" "$run/runner_temp"
printf 'summary of an earlier step\n' >"$run/summary"
: >"$run/output"
# A command this script starts with & has SIGINT ignored (no job control),
# and bash cannot trap a signal ignored when it started: the runner starts
# the step's bash with SIGINT at its default, and so does python3 here.
python3 -c 'import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); os.execvp("env", sys.argv[1:])' \
  -i PATH=/usr/bin:/bin HOME="$run" \
  GITHUB_WORKSPACE="$run/workspace" RUNNER_TEMP="$run/runner_temp" \
  GITHUB_STEP_SUMMARY="$run/summary" GITHUB_OUTPUT="$run/output" GITHUB_ACTION_PATH="$source_dir" \
  INPUT_VGC="$vgc" INPUT_CASES=100000 INPUT_BUDGET=120 INPUT_SEED=1 INPUT_IMPL=reference \
  bash "$script" >"$run/log" 2>&1 &
script_pid=$!
# Once vgc runs its cases (its first line is printed after its signal
# handlers are in place), however long that takes on a loaded machine.
for _ in $(seq 600); do grep -q '(seed 1, ' "$run/log" 2>/dev/null && break; sleep 0.1; done
sleep 1
t0=$(date +%s%N)
kill -INT "$script_pid"
wait "$script_pid"
status=$?
ms=$(( ($(date +%s%N) - t0) / 1000000 ))
echo "--- cancelled: exit $status after $ms ms"
check "cancelled: the script ends within 5 s of SIGINT" test "$ms" -lt 5000
check "cancelled: exit 130" test "$status" -eq 130 || show
check "cancelled: verdict=incomplete" test "$(output verdict)" = incomplete
check "cancelled: exit-code=130" test "$(output exit-code)" = 130
check "cancelled: report-dir holds vgc's report (uploaded)" grep -q '"cancelled_by": "SIGINT"' "$(output report-dir)/report.json"
check "cancelled: the job summary is the run's summary.md" grep -q '^# vgc certify: reference .* INCOMPLETE' "$run/summary"
check "cancelled: the annotation says the job was cancelled" grep -q '^::error title=vgc certify::.*the job was cancelled (SIGINT)' "$run/log"
check "cancelled: action.yml uploads the report of a cancelled job (always())" \
  grep -q "if: \${{ always() && steps.certify.outputs.report-dir != '' }}" "$source_dir/action.yml"

# The matrix's final job: the shards' run directories (downloaded artifacts)
# merged into one run with the unsharded verdict (input merge).
shards=$tmp/shards
mkdir -p "$shards"
for k in 1 2 3; do
  action "shard$k" INPUT_IMPL="plugin:$fault_plugin" INPUT_SHARD="$k/3" VGC_FAULT=base-layer-destroyable
  cp -r "$(output report-dir)" "$shards/shard$k"
done
action merged INPUT_IMPL=ignored INPUT_MERGE="$shards"
check "merge: exit 1 (the unsharded verdict)" test "$status" -eq 1 || show
check "merge: verdict=not-conformant" test "$(output verdict)" = not-conformant
check "merge: one run directory" test -f "$(output report-dir)/report.json"
check "merge: the job summary is the merged run's" grep -q '^# vgc certify: plugin:.* NOT CONFORMANT' "$run/summary"
check "merge: an annotation names LAYER-BASE-2" grep -q '^::error title=vgc fail LAYER-BASE-2::' "$run/log"
rm -rf "$shards/shard2"
action merged_missing INPUT_IMPL=ignored INPUT_MERGE="$shards"
check "merge: a missing shard is an error naming it" grep -q 'shard 2/3 is missing' "$run/log"
check "merge: ... exit 2" test "$status" -eq 2

[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "all checks passed"
