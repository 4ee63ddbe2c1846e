#!/bin/sh
# Reads its input but never answers anything, not even ?hello.
# tests/adapter/exec_faults_test.cpp: opening it fails with a Timeout.
while IFS= read -r line; do
  echo "silent_hello: ignoring $line" >&2
done
