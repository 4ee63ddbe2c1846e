#!/bin/bash -eu
# .clusterfuzzlite/build.sh — build every vgc fuzz target for ClusterFuzzLite
# / OSS-Fuzz (docs/fuzzing.md "ClusterFuzzLite").
#
# Inputs (the OSS-Fuzz build environment): CC, CXX, CFLAGS, CXXFLAGS (they
# carry the sanitizer, -fsanitize=fuzzer-no-link and, in the image,
# -stdlib=libc++), LIB_FUZZING_ENGINE (e.g. -fsanitize=fuzzer), OUT (where
# the targets go), SRC (checkouts; the project is $SRC/vgc in the image, or
# the tree holding this script), WORK (scratch; a temporary directory if
# unset).
# Outputs in $OUT, per target (every name in the build's
# fuzz/fuzz_targets.txt: fuzz_stream, fuzz_text, fuzz_differential,
# fuzz_verse_packet, fuzz_mesh_manifold, fuzz_mesh_subdivision, fuzz_property_<group>): the
# binary, <target>_seed_corpus.zip (corpora/fuzz/<target>/ and every fixed
# crash in corpora/fuzz/<target>-crashes/), <target>.dict when the corpus
# has one, and <target>.options.
#
# How: the project's own CMake with -DVGC_FUZZ=ON, instrumented only by
# $CXXFLAGS (VGC_FUZZ_SANITIZERS=none) and linked with $LIB_FUZZING_ENGINE
# (VGC_FUZZ_ENGINE), building only the fuzz targets.
# Dependencies: the Dockerfile checks out pinned sources of the C++
# libraries into $SRC (they must be compiled with the image's libc++ and
# flags); each one present there is built and installed into
# $WORK/vgc-deps first. Any not present is taken from the system: that is
# how tests/fuzz/clusterfuzzlite_build.sh runs this script on Debian
# packages. CGAL is used without GMP/MPFR (the oracle uses
# Simple_cartesian<double> only), so the binaries need no libgmp at run
# time; OpenSubdiv is linked statically when built here, and GMP (the
# Verse login's RSA in fuzz_verse_packet, libgmp-dev in the Dockerfile)
# statically from libgmp.a.
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if [ -d "$here/../reference" ]; then
  ROOT="$(cd "$here/.." && pwd)"
else
  ROOT="$SRC/vgc"
fi
: "${OUT:?OUT must name the output directory}"
: "${LIB_FUZZING_ENGINE:?LIB_FUZZING_ENGINE must name the fuzzing engine link flags}"
mkdir -p "$OUT"
if [ -z "${WORK:-}" ]; then
  WORK="$(mktemp -d)"
  trap 'rm -rf "$WORK"' EXIT
fi
DEPS="$WORK/vgc-deps"
BUILD="$WORK/vgc-build"
jobs="$(nproc 2>/dev/null || echo 2)"
SRC="${SRC:-$(dirname "$ROOT")}"

# build_dep DIR [CMAKE ARGS...]: configure, build and install $SRC/DIR into
# $DEPS with the fuzzing compiler and flags, if the checkout exists.
build_dep() {
  local dir=$1
  shift
  [ -f "$SRC/$dir/CMakeLists.txt" ] || return 0
  echo "build.sh: building dependency $dir"
  cmake -S "$SRC/$dir" -B "$WORK/dep-$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$DEPS" \
    -DCMAKE_PREFIX_PATH="$DEPS" -DBUILD_SHARED_LIBS=OFF -DBUILD_TESTING=OFF "$@" >"$WORK/dep-$dir.log" 2>&1 ||
    { tail -40 "$WORK/dep-$dir.log"; exit 1; }
  cmake --build "$WORK/dep-$dir" -j "$jobs" >>"$WORK/dep-$dir.log" 2>&1 || { tail -40 "$WORK/dep-$dir.log"; exit 1; }
  cmake --install "$WORK/dep-$dir" >>"$WORK/dep-$dir.log" 2>&1 || { tail -40 "$WORK/dep-$dir.log"; exit 1; }
}
build_dep fmt -DFMT_DOC=OFF -DFMT_TEST=OFF
build_dep rapidcheck -DRC_ENABLE_GTEST=ON
build_dep googletest -DBUILD_GMOCK=OFF -DINSTALL_GTEST=ON
build_dep CLI11 -DCLI11_BUILD_TESTS=OFF -DCLI11_BUILD_EXAMPLES=OFF -DCLI11_BUILD_DOCS=OFF
build_dep json -DJSON_BuildTests=OFF
build_dep pugixml
build_dep cgal -DCGAL_DISABLE_GMP=ON
build_dep OpenSubdiv -DNO_EXAMPLES=ON -DNO_TUTORIALS=ON -DNO_REGRESSION=ON -DNO_DOC=ON -DNO_TESTS=ON \
  -DNO_GLTESTS=ON -DNO_PTEX=ON -DNO_OMP=ON -DNO_TBB=ON -DNO_CUDA=ON -DNO_OPENCL=ON -DNO_CLEW=ON \
  -DNO_OPENGL=ON -DNO_METAL=ON -DNO_DX=ON -DNO_GLFW=ON -DNO_GLEW=ON -DNO_MACOS_FRAMEWORK=ON

extra=()
if [ -f "$DEPS/lib/libosdCPU.a" ]; then
  extra+=("-DOPENSUBDIV_CPU_LIBRARY=$DEPS/lib/libosdCPU.a")
fi
echo "build.sh: configuring vgc (VGC_FUZZ=ON, engine: $LIB_FUZZING_ENGINE)"
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=None -DCMAKE_PREFIX_PATH="$DEPS" -DVGC_FUZZ=ON \
  -DVGC_FUZZ_SANITIZERS=none -DVGC_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" -DCGAL_DISABLE_GMP=ON \
  -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE "${extra[@]}" >"$WORK/vgc-configure.log" 2>&1 ||
  { tail -40 "$WORK/vgc-configure.log"; exit 1; }
read -r -a targets <"$BUILD/fuzz/fuzz_targets.txt"
echo "build.sh: building ${targets[*]}"
cmake --build "$BUILD" -j "$jobs" --target "${targets[@]}"

zip_dir() {  # zip_dir ARCHIVE DIR... (files only, flat)
  local archive=$1
  shift
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

for target in "${targets[@]}"; do
  cp "$BUILD/fuzz/$target" "$OUT/$target"
  zip_dir "$OUT/${target}_seed_corpus.zip" "$ROOT/corpora/fuzz/$target" "$ROOT/corpora/fuzz/$target-crashes"
  if [ -f "$ROOT/corpora/fuzz/$target.dict" ]; then cp "$ROOT/corpora/fuzz/$target.dict" "$OUT/"; fi
  case "$target" in
    fuzz_mesh_*) max_len=256 ;;  # 1 + 16 vertex bytes + 24 faces of at most 8 bytes = 209
    *) max_len=1024 ;;
  esac
  {
    echo "[libfuzzer]"
    echo "max_len = $max_len"
    if [ -f "$ROOT/corpora/fuzz/$target.dict" ]; then echo "dict = $target.dict"; fi
  } >"$OUT/$target.options"
done
echo "build.sh: built ${#targets[@]} targets into $OUT"
