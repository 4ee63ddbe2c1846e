#!/bin/sh
# Handshakes correctly, then answers commands with something the protocol
# does not allow, chosen by $1:
#   words     "sure, why not"
#   reason2   "rejected NO SUCH_LAYER" (a reason of two words)
#   document  ?snapshot answers "here you go" (not a document)
#   twice     answers every command with two lines, "ok" and "ok"
# tests/adapter/exec_faults_test.cpp: ProtocolError quoting the line.
mode=${1:-words}
while IFS= read -r line; do
  case "$line" in
    '?hello') echo "vgc-exec 1 garbage-answer";;
    '?reset') echo ok;;
    '?snapshot') if [ "$mode" = document ]; then echo "here you go"; else printf 'vgc-snapshot 1\nend\n'; fi;;
    '?derived') printf 'vgc-derived 1\nend\n';;
    '?quit') exit 0;;
    *)
      case "$mode" in
        words) echo "sure, why not";;
        reason2) echo "rejected NO SUCH_LAYER";;
        twice) echo ok; echo ok;;
        *) echo ok;;
      esac;;
  esac
done
