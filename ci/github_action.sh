#!/usr/bin/env bash
# github_action.sh — what the composite GitHub Action (action.yml at the
# repository root) runs: certify an implementation with vgc, put the run's
# summary.md into the job summary, set the step's outputs, and fail the step
# unless the verdict is conformant. docs/ci.md describes the action.
#
# Inputs come from the environment, as action.yml passes them:
#   INPUT_IMPL (required)  reference | exec:CMD | plugin:PATH   (vgc certify --impl)
#   INPUT_BASELINE         baseline file, relative to the workspace   (--baseline)
#   INPUT_CLAUSES          clause-id globs, comma-separated           (--clauses, default *)
#   INPUT_CASES            cases per property                         (--cases, default 200)
#   INPUT_SEED             the run's seed                             (--seed, default 1)
#   INPUT_SHARD            I/N                                        (--shard, default 1/1)
#   INPUT_BUDGET           seconds for the whole run                  (--budget, default 300)
#   INPUT_TIMEOUT          seconds per answer                         (--timeout, default 5)
#   INPUT_START_TIMEOUT    seconds to start the implementation        (--start-timeout, default 60)
#   INPUT_STRICT           true: also gate on IMPLEMENTATION-DEFINED clauses (--strict)
#   INPUT_REPORTS          where runs are written (default $RUNNER_TEMP/vgc-reports)
#   INPUT_VGC              the vgc program to use (relative: to the workspace);
#                          empty: `vgc` from PATH if there is one (the .deb),
#                          else built from the action's own checkout with
#                          `./vgc build vgc`
#   INPUT_WORKING_DIRECTORY  where certify runs (default $GITHUB_WORKSPACE), so
#                          relative paths in exec: commands and plugin: paths work
#   INPUT_ARTIFACT_NAME    the artifact's name (default vgc-report, or
#                          vgc-report-shard-I-of-N for a shard)
#   INPUT_MERGE            a directory holding the run directories of every
#                          shard of one run (the shards' artifacts, downloaded):
#                          instead of certifying, `vgc merge` them into one run
#                          with the unsharded verdict (the matrix's final job);
#                          impl is then ignored
# and the runner's: GITHUB_WORKSPACE, GITHUB_STEP_SUMMARY, GITHUB_OUTPUT,
# RUNNER_TEMP, GITHUB_ACTION_PATH (the action's checkout).
#
# Outputs (to $GITHUB_OUTPUT): verdict (conformant | not-conformant |
# incomplete | error), exit-code (vgc's: 0, 1 or 2; 130 or 143 for a run
# cancelled by SIGINT or SIGTERM, incomplete), report-dir (the run
# directory; empty when vgc wrote none), summary (its summary.md), junit
# (its junit.xml), artifact-name.
#
# Exit status: 0 when the verdict is conformant, otherwise vgc's exit code
# (1 not conformant, 2 incomplete or error), after an `::error::` line that
# quotes vgc's own words.
set -uo pipefail

annotate() {  # annotate TITLE MESSAGE: an ::error:: workflow command (% and newlines escaped)
  local m=${2//%/%25}
  m=${m//$'\r'/%0D}
  m=${m//$'\n'/%0A}
  printf '::error title=%s::%s\n' "$1" "$m"
}

fail() {  # fail MESSAGE: a problem with the action's own inputs or environment
  annotate "vgc certify" "$1"
  [ -n "${GITHUB_OUTPUT:-}" ] && printf 'verdict=error\nexit-code=2\nreport-dir=\n' >>"$GITHUB_OUTPUT"
  [ -n "${GITHUB_STEP_SUMMARY:-}" ] && printf '## vgc certify: error\n\n%s\n' "$1" >>"$GITHUB_STEP_SUMMARY"
  exit 2
}

for v in GITHUB_WORKSPACE GITHUB_STEP_SUMMARY GITHUB_OUTPUT RUNNER_TEMP; do
  [ -n "${!v:-}" ] || fail "$v is not set: run this script as a step of a GitHub Actions job (action.yml), or set it to a file or directory to run it by hand"
done
merge_from=${INPUT_MERGE:-}
[ -n "$merge_from" ] || [ -n "${INPUT_IMPL:-}" ] || fail "the input 'impl' is required: reference, exec:'./my-host --vgc' or plugin:path/to/libmy_node.so (docs/adapters.md)"

action_dir=${GITHUB_ACTION_PATH:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
workdir=${INPUT_WORKING_DIRECTORY:-$GITHUB_WORKSPACE}
case "$workdir" in /*) ;; *) workdir=$GITHUB_WORKSPACE/$workdir ;; esac
[ -d "$workdir" ] || fail "working-directory '$workdir' does not exist: give a directory of your checkout"

# 1. The vgc program.
vgc=${INPUT_VGC:-}
case "$vgc" in "" | /*) ;; *) vgc=$GITHUB_WORKSPACE/$vgc ;; esac
if [ -z "$vgc" ]; then
  if command -v vgc >/dev/null 2>&1; then
    vgc=$(command -v vgc)
  else
    echo "::group::Building vgc from $action_dir (./vgc build vgc)"
    "$action_dir/vgc" build vgc || fail "building vgc from $action_dir failed (the log above says why); on a runner that is not Debian 12, run the job in the container debian:bookworm (docs/ci.md), or install the vgc .deb first and the action uses vgc from PATH"
    echo "::endgroup::"
    vgc=${VGC_BUILD_DIR:-$action_dir/build}/cli/vgc
  fi
fi
[ -x "$vgc" ] || fail "the vgc program '$vgc' (input 'vgc') is not an executable file: leave the input empty to build vgc, or give the path of an installed one"

# 2. The options.
args=(certify --impl "${INPUT_IMPL:-}")
if [ -n "${INPUT_BASELINE:-}" ]; then
  baseline=$INPUT_BASELINE
  case "$baseline" in /*) ;; *) baseline=$GITHUB_WORKSPACE/$baseline ;; esac
  args+=(--baseline "$baseline")
fi
[ -n "${INPUT_CLAUSES:-}" ] && args+=(--clauses "$INPUT_CLAUSES")
[ -n "${INPUT_CASES:-}" ] && args+=(--cases "$INPUT_CASES")
[ -n "${INPUT_SEED:-}" ] && args+=(--seed "$INPUT_SEED")
[ -n "${INPUT_BUDGET:-}" ] && args+=(--budget "$INPUT_BUDGET")
[ -n "${INPUT_TIMEOUT:-}" ] && args+=(--timeout "$INPUT_TIMEOUT")
[ -n "${INPUT_START_TIMEOUT:-}" ] && args+=(--start-timeout "$INPUT_START_TIMEOUT")
shard=${INPUT_SHARD:-1/1}
args+=(--shard "$shard")
case "${INPUT_STRICT:-false}" in
  true) args+=(--strict) ;;
  false | "") ;;
  *) fail "the input 'strict' is '${INPUT_STRICT}': give true or false" ;;
esac
reports=${INPUT_REPORTS:-$RUNNER_TEMP/vgc-reports}
case "$reports" in /*) ;; *) reports=$GITHUB_WORKSPACE/$reports ;; esac
args+=(--reports "$reports")

if [ -n "$merge_from" ]; then  # the final job of a sharded run: merge, do not certify
  case "$merge_from" in /*) ;; *) merge_from=$GITHUB_WORKSPACE/$merge_from ;; esac
  mapfile -t shard_dirs < <(find "$merge_from" -name report.json -printf '%h\n' | sort)
  [ ${#shard_dirs[@]} -gt 0 ] || fail "the input 'merge' is '$merge_from', which holds no run directory (no report.json): download the shards' artifacts into it first"
  args=(merge "${shard_dirs[@]}" --reports "$reports")
  shard=1/1
fi

artifact=${INPUT_ARTIFACT_NAME:-}
if [ -z "$artifact" ]; then
  artifact=vgc-report
  [ "$shard" != 1/1 ] && artifact="vgc-report-shard-${shard/\//-of-}"
fi

# 3. The run. The console shows vgc's own lines (one per property: CI logs);
# stdout is kept to find the run directory vgc names ("report: DIR/summary.md").
#
# A cancelled job: the runner sends SIGINT to this script (the step's entry
# process) only, then SIGTERM 7.5 s later, then kills the process tree. So
# vgc runs in the background, in a session of its own (a terminal's Ctrl-C
# reaches it once, through us, not twice: a second signal makes vgc exit
# without its report), and `wait` (which a trapped signal interrupts, unlike
# a foreground command) is how this script waits for it. The trap passes the
# signal on; vgc then stops, writes its incomplete report and exits 128 +
# the signal within a second or two, and the outputs and the job summary
# below are written for it as for any run (action.yml uploads the report
# with always()).
out=$RUNNER_TEMP/vgc-certify-stdout.$$
err=$RUNNER_TEMP/vgc-certify-stderr.$$
fifo=$RUNNER_TEMP/vgc-certify-stderr-fifo.$$
echo "vgc ${args[0]} in $workdir:"
printf ' %q' "$vgc" "${args[@]}"
echo
rm -f "$fifo"
mkfifo "$fifo" || fail "cannot create a fifo under RUNNER_TEMP ($RUNNER_TEMP)"
(trap '' INT TERM; exec tee "$err" <"$fifo") &
tee_pid=$!
(cd "$workdir" && exec setsid "$vgc" "${args[@]}" >"$out" 2>"$fifo") &
vgc_pid=$!
cancelled=
pass_on() {  # pass_on SIGNAL: a cancelled job's signal, passed on to vgc
  cancelled=$1
  echo "vgc certify action: SIG$1 received: passing it on to vgc, which writes an incomplete report"
  kill -"$1" "$vgc_pid" 2>/dev/null
}
trap 'pass_on INT' INT
trap 'pass_on TERM' TERM
while :; do  # `wait` returns early when a trapped signal arrives: then wait again
  wait "$vgc_pid"
  code=$?
  kill -0 "$vgc_pid" 2>/dev/null || break
done
while kill -0 "$tee_pid" 2>/dev/null; do wait "$tee_pid"; done
rm -f "$fifo"
cat "$out"

report_dir=$(sed -n 's|^report: \(.*\)/summary\.md$|\1|p' "$out" | tail -n 1)
case "$code" in
  0) verdict=conformant ;;
  1) verdict=not-conformant ;;
  *) if [ -n "$report_dir" ]; then verdict=incomplete; else verdict=error; fi ;;
esac
[ -n "$cancelled" ] && [ -z "$report_dir" ] && verdict=error  # cut short before vgc wrote a report

{
  echo "verdict=$verdict"
  echo "exit-code=$code"
  echo "report-dir=$report_dir"
  echo "summary=${report_dir:+$report_dir/summary.md}"
  echo "junit=${report_dir:+$report_dir/junit.xml}"
  echo "artifact-name=$artifact"
} >>"$GITHUB_OUTPUT"

# 4. The job summary: the run's own summary.md, or vgc's error.
if [ -n "$report_dir" ] && [ -f "$report_dir/summary.md" ]; then
  [ "$shard" != 1/1 ] && printf '_vgc shard %s_\n\n' "$shard" >>"$GITHUB_STEP_SUMMARY"
  cat "$report_dir/summary.md" >>"$GITHUB_STEP_SUMMARY"
  printf '\n' >>"$GITHUB_STEP_SUMMARY"
else
  {
    printf '## vgc certify: error (exit %s), no report\n\n' "$code"
    printf '```\n'
    grep '^vgc' "$err" | tail -n 20
    printf '```\n'
  } >>"$GITHUB_STEP_SUMMARY"
fi

# 5. The step's status.
first_line=$(grep -m 1 -E ': (conformant|not-conformant|incomplete) \(' "$out")
case "$verdict" in
  conformant) ;;
  not-conformant)
    # One annotation per finding line ("  fail     CLAUSE  message").
    sed -n 's/^  \(fail\|crash\|timeout\) \+\([A-Z0-9-]\+\) \+\(.*\)$/\1 \2\t\3/p' "$out" |
      while IFS=$'\t' read -r title message; do annotate "vgc $title" "$message"; done
    annotate "vgc certify" "${first_line:-not conformant} (report: $report_dir/summary.md)" ;;
  incomplete)
    if [ -n "$cancelled" ]; then
      annotate "vgc certify" "${first_line:-incomplete}: the job was cancelled (SIG$cancelled); the report of what was judged before is in $report_dir/summary.md"
    else
      annotate "vgc certify" "${first_line:-incomplete}: some clauses could not be judged (the 'unchecked' lines above say why); raise 'cases' or 'budget' (report: $report_dir/summary.md)"
    fi ;;
  error)
    msg=$(grep '^vgc' "$err" | grep -v '^vgc certify: .*(seed [0-9]*, ' | grep -v '^vgc certify: what to do' | tail -n 1)
    fix=$(grep '^vgc certify: what to do: ' "$err" | tail -n 1)
    annotate "vgc certify" "${msg:-vgc exited with $code and wrote no report (the log above says why)}${fix:+ — ${fix#vgc certify: }}" ;;
esac
rm -f "$out" "$err"
[ "$verdict" = conformant ] && exit 0
exit "$code"
