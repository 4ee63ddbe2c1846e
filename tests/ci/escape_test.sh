#!/usr/bin/env bash
# escape_test.sh VGC PYTHON3 — bytes that are not vgc's (a file's, an
# argument's, an implementation's) reach the terminal, summary.md,
# junit.xml and report.html escaped (issue 19, item 5): no control byte but
# newline and tab, and junit.xml stays well-formed XML. They used to reach
# the terminal raw: `vgc apply` of a file holding "\e]0;pwned\a" set the
# terminal's title.
set -uo pipefail
[ $# -ge 2 ] || { echo "usage: $0 VGC PYTHON3" >&2; exit 2; }
vgc=$1 python=$2
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_escape.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 2
fail() { echo "escape: $*" >&2; exit 1; }
# clean FILE WHAT: FILE holds no control byte but \n and \t.
clean() {
  "$python" - "$1" <<'PY' || fail "$2: raw control bytes reach the output ($1)"
import sys
data = open(sys.argv[1], "rb").read()
bad = [i for i, b in enumerate(data) if (b < 32 and b not in (9, 10)) or b == 127]
if bad:
    i = bad[0]
    sys.stderr.write("first at byte %d: %r\n" % (i, data[max(0, i - 30):i + 10]))
    sys.exit(1)
PY
}

printf '\x1b]0;pwned\x07\x1b[31mred\n' >f
"$vgc" apply f >out 2>err; [ $? = 2 ] || fail "apply of a bad file did not exit 2"
clean err "vgc apply's parse error"
grep -q 'x1b' err || fail "vgc apply's parse error does not show the escaped bytes: $(cat err)"

"$vgc" apply "$(printf 'no\x1b[31msuch')" >out 2>err
clean err "vgc apply of a missing file named with an escape"

printf 'LAYER-BASE-1 \x1b[31mred\x07\n\x01\x02bin\xff\n' >bl
"$vgc" certify --cases 2 --clauses LAYER-BASE-1 --baseline bl --reports R >out 2>err
clean err "a binary baseline's error"
clean out "a binary baseline's error (stdout)"

# An exec implementation that writes escapes and invalid UTF-8 to stderr
# and to its answers, then dies.
cat >impl.sh <<'SH'
#!/bin/sh
while IFS= read -r line; do
  case "$line" in
    '?hello') echo "vgc-exec 1 evil"; printf '\033]0;pwned\007\377\n' >&2 ;;
    '?reset') echo ok ;;
    '?snapshot') printf 'vgc-snapshot 1\033[31m\001\nend\n' ;;
    *) printf '\033[2J\033]0;pwned\007 dying\n' >&2; exit 3 ;;
  esac
done
SH
chmod +x impl.sh
"$vgc" certify --cases 2 --clauses 'LAYER-*' --impl "exec:./impl.sh #$(printf '\x1b[31m')" --reports R2 >out 2>err
rc=$?
[ $rc = 1 ] || [ $rc = 2 ] || { cat out err; fail "certify of the evil implementation exited $rc"; }
clean out "certify's stdout"
clean err "certify's stderr"
for f in summary.md junit.xml report.html report.json; do
  [ -s "R2/latest/$f" ] || fail "no $f"
  clean "R2/latest/$f" "$f"
done
for f in R2/latest/counterexamples/*.vgc; do [ -e "$f" ] && clean "$f" "$f"; done
"$python" -c 'import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])' R2/latest/junit.xml ||
  fail "junit.xml is not well-formed XML"
echo "escape: foreign bytes reach the terminal and the reports escaped"
