#!/bin/sh
# Answers ?hello and ?reset, then never answers a command: it starts a child
# (sleep) and waits for it, so the whole process group must be killed.
# tests/adapter/exec_faults_test.cpp: Timeout within the limit.
while IFS= read -r line; do
  case "$line" in
    '?hello') echo "vgc-exec 1 hang-on-command";;
    '?reset') echo ok;;
    '?quit') exit 0;;
    *) echo "hang_on_command: sleeping on: $line" >&2; sleep 1000;;
  esac
done
