#!/usr/bin/env bash
# clusterfuzzlite_build.sh ROOT OUT CC CXX
# Runs .clusterfuzzlite/build.sh as the OSS-Fuzz image would (libFuzzer
# engine; no sanitizer, see CFLAGS below), here with the Debian packages instead of the
# image's source-built libraries, and checks that EVERY fuzz target — one
# per fuzz/targets/fuzz_*.cpp and one fuzz_property_<group> per corpus directory
# corpora/fuzz/fuzz_property_<group>/ — landed in OUT with its seed corpus
# zip, its options file and (when the corpus has one) its dictionary, and
# that each binary runs up to 40 of its seed inputs cleanly. The expected
# list is derived here, not read from build.sh's output, so a target
# build.sh forgets fails the test. Uses ccache when installed (CMake reads
# CMAKE_CXX_COMPILER_LAUNCHER from the environment).
set -u
root=$1 out=$2
rm -rf "$out" && mkdir -p "$out"
work="$out.work"
rm -rf "$work" && mkdir -p "$work"
# SRC: an empty directory, so build.sh finds no dependency checkout (a
# developer's sibling checkout of, say, json must not be built) and uses the
# Debian packages.
mkdir -p "$work/src"
export CC=$3 CXX=$4 OUT=$out SRC="$work/src" WORK=$work
# The engine's instrumentation (-fsanitize=fuzzer-no-link) and link flags,
# without AddressSanitizer and at -O0: this test proves build.sh builds and
# ships every target; ASan would make it ~60 % slower (180 s against 114 s
# cold on this 2-core machine) and the ASan+UBSan build of the same CMake
# targets is the one `./vgc fuzz` builds and runs.
export CFLAGS="-O0 -fsanitize=fuzzer-no-link"
export CXXFLAGS="$CFLAGS"
export LIB_FUZZING_ENGINE=-fsanitize=fuzzer
if command -v ccache >/dev/null 2>&1; then
  # Paths under ROOT hashed relative to it, and the build directory not
  # hashed, so a rerun from another build directory of the tree hits.
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
fi
start=$(date +%s)
"$root/.clusterfuzzlite/build.sh" || { echo "build.sh failed" >&2; exit 1; }
echo "clusterfuzzlite_build: build.sh took $(($(date +%s) - start)) s"
expected=()
for src in "$root"/fuzz/targets/fuzz_*.cpp; do expected+=("$(basename "$src" .cpp)"); done
for d in "$root"/corpora/fuzz/fuzz_property_*/; do expected+=("$(basename "$d")"); done
status=0
for t in "${expected[@]}"; do
  for f in "$out/$t" "$out/${t}_seed_corpus.zip" "$out/$t.options"; do
    [ -s "$f" ] || { echo "missing: $f" >&2; status=1; }
  done
  if [ -f "$root/corpora/fuzz/$t.dict" ] && [ ! -s "$out/$t.dict" ]; then echo "missing: $out/$t.dict" >&2; status=1; fi
  [ -x "$out/$t" ] || continue
  seeds=$(mktemp -d)
  python3 -m zipfile -e "$out/${t}_seed_corpus.zip" "$seeds" >/dev/null
  mapfile -t inputs < <(find "$seeds" -type f | sort | head -40)
  ASAN_OPTIONS=detect_leaks=0 "$out/$t" "${inputs[@]}" >"$seeds.log" 2>&1 ||
    { echo "$t does not run its seed inputs cleanly:" >&2; tail -20 "$seeds.log" >&2; status=1; }
  grep -q "Executed .* in" "$seeds.log" || { echo "$t ran no input" >&2; status=1; }
  echo "clusterfuzzlite_build: $t ran ${#inputs[@]} seed inputs"
  rm -rf "$seeds" "$seeds.log"
done
rm -rf "$work"
[ "$status" -eq 0 ] && echo "clusterfuzzlite_build: all ${#expected[@]} targets, seed zips, options files present and running"
exit "$status"
