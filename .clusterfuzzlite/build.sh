#!/bin/bash -eu
# .clusterfuzzlite/build.sh — build every vgc fuzz target for ClusterFuzzLite
# / OSS-Fuzz (docs/fuzzing.md "ClusterFuzzLite").
#
# Inputs (the OSS-Fuzz build environment): CC, CXX, CFLAGS, CXXFLAGS (they
# carry the sanitizer and -fsanitize=fuzzer-no-link), LIB_FUZZING_ENGINE
# (e.g. -fsanitize=fuzzer), OUT (where the targets go), SRC (checkouts; the
# project is $SRC/vgc in the image, or the tree holding this script).
# Outputs in $OUT, per target fuzz_<name>: the binary, <target>_seed_corpus.zip
# (corpora/fuzz/<target>/ and every fixed crash in corpora/fuzz/<target>-crashes/),
# <target>.dict and <target>.options.
#
# The targets need only the C++17 standard library, the reference sources
# and libdl, so this compiles them directly, without CMake and without the
# suite's other dependencies.
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if [ -d "$here/../reference" ]; then
  ROOT="$(cd "$here/.." && pwd)"
else
  ROOT="$SRC/vgc"
fi
: "${OUT:?OUT must name the output directory}"
mkdir -p "$OUT"
WORKDIR="$(mktemp -d)"
trap 'rm -rf "$WORKDIR"' EXIT

flags=(-std=c++17 -I"$ROOT/reference" -I"$ROOT/fuzz" -I"$ROOT/conformance/adapter")
# shellcheck disable=SC2206
cxxflags=($CXXFLAGS)

# The reference (every source: it is standard-library only) and the fuzz
# support code, compiled in parallel into one archive.
sources=("$ROOT"/reference/*.cpp "$ROOT"/fuzz/node_invariants.cpp "$ROOT"/fuzz/command_mutator.cpp
         "$ROOT"/fuzz/plugin_node.cpp "$ROOT"/fuzz/reference_plugin_table.cpp "$ROOT"/fuzz/finding.cpp)
jobs="$(nproc 2>/dev/null || echo 2)"
pids=()
for src in "${sources[@]}"; do
  obj="$WORKDIR/$(basename "$(dirname "$src")")_$(basename "$src" .cpp).o"
  "$CXX" "${cxxflags[@]}" "${flags[@]}" -c "$src" -o "$obj" &
  pids+=($!)
  if [ "${#pids[@]}" -ge "$jobs" ]; then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p"; done
ar rcs "$WORKDIR/libvgc_fuzz.a" "$WORKDIR"/*.o

zip_dir() {  # zip_dir ARCHIVE DIR... (files only, flat)
  local archive=$1; shift
  local files=()
  for d in "$@"; do
    [ -d "$d" ] || continue
    for f in "$d"/*; do [ -f "$f" ] && files+=("$f"); done
  done
  rm -f "$archive"
  [ "${#files[@]}" -gt 0 ] || return 0
  if command -v zip >/dev/null 2>&1; then
    zip -q -j "$archive" "${files[@]}"
  else
    python3 -m zipfile -c "$archive" "${files[@]}"
  fi
}

for target_src in "$ROOT"/fuzz/fuzz_*.cpp; do
  target="$(basename "$target_src" .cpp)"
  case "$target" in fuzz_mesh_*) continue ;; esac  # need the oracles (CGAL, OpenSubdiv): not built here yet
  "$CXX" "${cxxflags[@]}" "${flags[@]}" "$target_src" "$WORKDIR/libvgc_fuzz.a" \
    $LIB_FUZZING_ENGINE -ldl -o "$OUT/$target"
  zip_dir "$OUT/${target}_seed_corpus.zip" "$ROOT/corpora/fuzz/$target" "$ROOT/corpora/fuzz/$target-crashes"
  if [ -f "$ROOT/corpora/fuzz/$target.dict" ]; then cp "$ROOT/corpora/fuzz/$target.dict" "$OUT/"; fi
  {
    echo "[libfuzzer]"
    echo "max_len = 1024"
    if [ -f "$ROOT/corpora/fuzz/$target.dict" ]; then echo "dict = $target.dict"; fi
  } >"$OUT/$target.options"
done
echo "build.sh: built $(ls "$ROOT"/fuzz/fuzz_*.cpp | wc -l) targets into $OUT"
