#!/usr/bin/env bash
# clusterfuzzlite_build.sh ROOT OUT CC CXX
# Runs .clusterfuzzlite/build.sh as the OSS-Fuzz image would (address
# sanitizer, libFuzzer engine) and checks that every fuzz target, its seed
# corpus zip, its options file and (when the corpus has one) its dictionary
# landed in OUT, and that each binary runs its own seed corpus cleanly.
set -u
root=$1 out=$2
rm -rf "$out" && mkdir -p "$out"
export CC=$3 CXX=$4 OUT=$out SRC="$(dirname "$root")"
export CFLAGS="-O1 -fno-omit-frame-pointer -gline-tables-only -fsanitize=address -fsanitize=fuzzer-no-link"
export CXXFLAGS="$CFLAGS"
export LIB_FUZZING_ENGINE=-fsanitize=fuzzer
"$root/.clusterfuzzlite/build.sh" || { echo "build.sh failed" >&2; exit 1; }
status=0
for src in "$root"/fuzz/fuzz_*.cpp; do
  t=$(basename "$src" .cpp)
  case "$t" in fuzz_mesh_*) continue ;; esac  # not built by build.sh yet
  for f in "$out/$t" "$out/${t}_seed_corpus.zip" "$out/$t.options"; do
    [ -s "$f" ] || { echo "missing: $f" >&2; status=1; }
  done
  if [ -f "$root/corpora/fuzz/$t.dict" ] && [ ! -s "$out/$t.dict" ]; then echo "missing: $out/$t.dict" >&2; status=1; fi
  [ -x "$out/$t" ] || continue
  seeds=$(mktemp -d)
  python3 -m zipfile -e "$out/${t}_seed_corpus.zip" "$seeds" >/dev/null
  ASAN_OPTIONS=detect_leaks=0 "$out/$t" -runs=0 "$seeds" >"$seeds.log" 2>&1 ||
    { echo "$t does not run its seed corpus cleanly:" >&2; tail -20 "$seeds.log" >&2; status=1; }
  rm -rf "$seeds" "$seeds.log"
done
[ "$status" -eq 0 ] && echo "clusterfuzzlite_build: every target, seed zip, options file present"
exit "$status"
