#!/bin/sh
# function_length.sh [SOURCE_DIR]: no product function over 120 lines apart
# from data tables (issue 29's done-when). pmccabe (Debian package pmccabe)
# measures every function of the product folders; column 5 is its length in
# lines. Prints each function over the limit that the allow-list below does
# not name, and each spine held to a lower limit (below) that is over it,
# as LINES FILE(LINE): FUNCTION; exit 1 when there is any.
# fuzz/faulty_plugins are deliberately wrong implementations, not product.
set -eu
cd "${1:-.}"
command -v pmccabe >/dev/null 2>&1 || { echo "function_length.sh: pmccabe not found (apt-get install pmccabe)" >&2; exit 2; }
limit=120
# What may stay longer: FILE FUNCTION (as pmccabe spells it), one a line,
# then # and why.
allowed='
conformance/clause_catalog.cpp vgc::clause_catalog  # a data table, one entry a clause
'

# Spines of named steps held shorter: FUNCTION (as pmccabe spells it) and
# its limit, one a line (issue 29: run_certification and run_property under
# 60, as fuzz's run_campaign).
held='
vgc::run_certification 60
vgc::run_property 60
vgc::run_campaign 60
'

long=$(find reference verse conformance oracles fuzz cli bench runtime \
         \( -name '*.cpp' -o -name '*.c' -o -name '*.h' \) | grep -v faulty_plugins | sort |
       xargs pmccabe 2>/dev/null |
       awk -v limit="$limit" -v allowed="$allowed" -v held="$held" '
         BEGIN { n = split(allowed, a, "\n")
                 for (i = 1; i <= n; i++) { sub(/ *#.*/, "", a[i]); if (a[i] != "") ok[a[i]] = 1 }
                 n = split(held, h, "\n")
                 for (i = 1; i <= n; i++) if (split(h[i], w, " ") == 2) short[w[1]] = w[2] }
         ($7 in short) && $5 > short[$7] { print $5, $6, $7, "(a spine: at most " short[$7] " lines)"; next }
         $5 > limit { file = $6; sub(/\(.*/, "", file); if (!((file " " $7) in ok)) print $5, $6, $7 }' |
       sort -rn)
if [ -n "$long" ]; then
  echo "functions over $limit lines, or spines over their limit (split them into named steps, or name a data table in tools/function_length.sh):"
  echo "$long"
  exit 1
fi
echo "no product function over $limit lines but the allowed"
