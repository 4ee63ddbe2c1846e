#!/bin/sh
# function_length.sh [SOURCE_DIR]: no product function over 120 lines apart
# from data tables (issue 29's done-when). pmccabe (Debian package pmccabe)
# measures every function of the product folders; column 5 is its length in
# lines. Prints each function over the limit that the allow-list below does
# not name, as LINES FILE(LINE): FUNCTION; exit 1 when there is any.
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

long=$(find reference verse conformance oracles fuzz cli bench runtime \
         \( -name '*.cpp' -o -name '*.c' -o -name '*.h' \) | grep -v faulty_plugins | sort |
       xargs pmccabe 2>/dev/null |
       awk -v limit="$limit" -v allowed="$allowed" '
         BEGIN { n = split(allowed, a, "\n")
                 for (i = 1; i <= n; i++) { sub(/ *#.*/, "", a[i]); if (a[i] != "") ok[a[i]] = 1 } }
         $5 > limit { file = $6; sub(/\(.*/, "", file); if (!((file " " $7) in ok)) print $5, $6, $7 }' |
       sort -rn)
if [ -n "$long" ]; then
  echo "functions over $limit lines (split them into named steps, or name a data table in tools/function_length.sh):"
  echo "$long"
  exit 1
fi
echo "no product function over $limit lines but the allowed"
