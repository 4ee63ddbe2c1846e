#!/bin/sh
# An exec implementation that accepts every command ("ok") and exits with
# status 3 on the third command after it started (after a message on stderr).
# tests/adapter/exec_faults_test.cpp: Crash with detail, then reset() restarts it.
n=0
while IFS= read -r line; do
  case "$line" in
    '?hello') echo "vgc-exec 1 crash-on-third";;
    '?reset') echo ok;;
    '?snapshot') printf 'vgc-snapshot 1\nend\n';;
    '?derived') printf 'vgc-derived 1\nend\n';;
    '?quit') exit 0;;
    *)
      n=$((n + 1))
      if [ "$n" -eq 3 ]; then
        echo "crash_on_third: giving up on command $n" >&2
        exit 3
      fi
      echo ok;;
  esac
done
