#!/bin/sh
# Handshakes, then closes its stdin and lingers a moment before exiting 0:
# the suite's next write fails with EPIPE (SIGPIPE must not kill the suite).
# tests/adapter/exec_faults_test.cpp: Crash.
IFS= read -r line
echo "vgc-exec 1 closes-input"
IFS= read -r line
echo ok
exec 0<&-
sleep 0.3
exit 0
