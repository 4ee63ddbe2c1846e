#!/usr/bin/env bash
# install_consumer_test.sh — the install and the vgc CMake package, end to end.
#
#   install_consumer_test.sh BUILD_DIR SOURCE_DIR VERSION REFERENCE_PLUGIN FAULT_PLUGIN [CMAKE [CTEST]]
#
# Installs BUILD_DIR into an empty temporary prefix (cmake --install), checks
# the installed files and that bin/vgc needs nothing from the build tree,
# then configures a consumer project that does find_package(vgc CONFIG
# REQUIRED) with CMAKE_PREFIX_PATH=<prefix>, compiles a C file against
# vgc::plugin_header and registers certifications with
# vgc_add_certification(). Its ctest must pass for the reference node (in
# process and as a plugin named through a generator expression, --strict,
# a baseline that tolerates a known fault), and fail for the fault plugin
# with VGC_FAULT=base-layer-destroyable (naming LAYER-BASE-2) and for a
# missing plugin (exit 2, vgc's own message in the output). Then
# examples/c_host (a C node with its own CMakeLists.txt) is copied out of
# SOURCE_DIR and built against the same prefix alone: its ctest must pass,
# and built with -DC_HOST_FAULT=UNROTATED_CHILDREN fail naming
# BONE-DOWNSTREAM-1, with a replay line that names the installed vgc and,
# run as printed, shows the failure again. Temporary directories are
# removed on exit.
set -euo pipefail

[ $# -ge 5 ] || { echo "usage: $0 BUILD_DIR SOURCE_DIR VERSION REFERENCE_PLUGIN FAULT_PLUGIN [CMAKE [CTEST]]" >&2; exit 2; }
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
version=$3
reference_plugin=$4
fault_plugin=$5
cmake=${6:-cmake}
ctest=${7:-ctest}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/vgc_install_test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
failures=0
check() {  # check DESCRIPTION COMMAND...: run it, report ok or FAIL
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; failures=$((failures + 1)); fi
}

# 1. The install.
"$cmake" --install "$build" --prefix "$prefix" >"$tmp/install.log" 2>&1 ||
  { cat "$tmp/install.log"; echo "FAIL: cmake --install $build --prefix $prefix"; exit 1; }
for f in bin/vgc include/vgc/vgc_plugin.h share/doc/vgc/README.md share/doc/vgc/docs/certify.md share/doc/vgc/docs/ci.md \
  lib/cmake/vgc/vgcConfig.cmake lib/cmake/vgc/vgcConfigVersion.cmake lib/cmake/vgc/vgcTargets.cmake \
  lib/cmake/vgc/vgcCertification.cmake lib/vgc/libvgc_coverage.a lib/vgc/vgc_coverage.o include/vgc/vgc_coverage_shm.h; do
  check "installed $f" test -f "$prefix/$f"
done
check "bin/vgc has no RPATH or RUNPATH" bash -c "! readelf -d '$prefix/bin/vgc' | grep -Eq 'RPATH|RUNPATH'"
# Outside its debug information (compilation directories), the program names no source or build path.
objcopy --strip-debug "$prefix/bin/vgc" "$tmp/vgc_without_debug_info"
check "bin/vgc names neither $source nor $build" bash -c "! grep -aqF -e '$source' -e '$build' '$tmp/vgc_without_debug_info'"
"$prefix/bin/vgc" --version >"$tmp/version.txt"
cat "$tmp/version.txt"
check "vgc --version names vgc $version" grep -qx "vgc $version" "$tmp/version.txt"
check "vgc --version names the clause catalog version" grep -qx "clause catalog version [0-9]*" "$tmp/version.txt"
check "vgc --version names the report format version" grep -qx "report format version [0-9]*" "$tmp/version.txt"

# 2. The consumer project.
mkdir -p "$tmp/consumer"
printf 'LAYER-BASE-2 the fault plugin lets the base layer be destroyed\n' >"$tmp/consumer/known_deviations.txt"
cat >"$tmp/consumer/plugin_header_check.c" <<'C'
/* plugin_header_check.c — vgc_plugin.h compiles through vgc::plugin_header. */
#include <vgc_plugin.h>
#if VGC_PLUGIN_ABI_VERSION != 1u
#error unexpected VGC_PLUGIN_ABI_VERSION
#endif
const vgc_plugin_v1_table* vgc_plugin_header_check_table;
C
cat >"$tmp/consumer/CMakeLists.txt" <<CMAKE
# A project gating on vgc: the installed package only.
cmake_minimum_required(VERSION 3.25)
project(vgc_consumer LANGUAGES C)
enable_testing()
find_package(vgc $version CONFIG REQUIRED)
foreach(target vgc::vgc vgc::plugin_header)
  if(NOT TARGET \${target})
    message(FATAL_ERROR "the vgc package gives no \${target}")
  endif()
endforeach()
get_target_property(vgc_location vgc::vgc IMPORTED_LOCATION_RELWITHDEBINFO)
message(STATUS "vgc::vgc is \${vgc_location}")

add_library(plugin_header_check OBJECT plugin_header_check.c)
target_link_libraries(plugin_header_check PRIVATE vgc::plugin_header)

# The reference plugin as a target, so IMPL can name it through a generator expression.
add_library(reference_node MODULE IMPORTED)
set_target_properties(reference_node PROPERTIES IMPORTED_LOCATION "$reference_plugin")

vgc_add_certification(NAME ref_conformance IMPL reference CASES 30 SEED 1)
vgc_add_certification(NAME ref_plugin_conformance IMPL "plugin:\$<TARGET_FILE:reference_node>" CASES 30 SEED 1
                      TIMEOUT 10 CLAUSES "*")
vgc_add_certification(NAME ref_strict IMPL reference CASES 30 CLAUSES "LAYER-*,BONE-*" STRICT)
vgc_add_certification(NAME fault_known IMPL "plugin:$fault_plugin" CASES 30 BASELINE known_deviations.txt
                      ENVIRONMENT VGC_FAULT=base-layer-destroyable)
vgc_add_certification(NAME fault_conformance IMPL "plugin:$fault_plugin" CASES 30
                      ENVIRONMENT VGC_FAULT=base-layer-destroyable)
vgc_add_certification(NAME missing_plugin IMPL "plugin:\${CMAKE_CURRENT_BINARY_DIR}/no_such_plugin.so")
CMAKE

consumer=$tmp/consumer_build
if ! "$cmake" -S "$tmp/consumer" -B "$consumer" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  >"$tmp/configure.log" 2>&1; then
  cat "$tmp/configure.log"
  echo "FAIL: the consumer project does not configure with CMAKE_PREFIX_PATH=$prefix"
  exit 1
fi
grep "vgc::vgc is" "$tmp/configure.log" || true
check "find_package found the installed package" grep -qx "vgc_DIR:PATH=$prefix/lib/cmake/vgc" "$consumer/CMakeCache.txt"
check "the tests run the installed vgc" grep -qF "$prefix/bin/vgc" "$consumer/CTestTestfile.cmake"
if ! "$cmake" --build "$consumer" >"$tmp/build.log" 2>&1; then
  cat "$tmp/build.log"
  echo "FAIL: the consumer project does not build (plugin_header_check.c against vgc::plugin_header)"
  exit 1
fi
echo "ok: plugin_header_check.c compiles against vgc::plugin_header"

# 3. Its ctest.
run_ctest() {  # run_ctest LOG REGEX: ctest -R REGEX in the consumer build, output to LOG, returns ctest's status
  local log=$1 regex=$2 rc=0
  (cd "$consumer" && "$ctest" --output-on-failure -R "$regex") >"$log" 2>&1 || rc=$?
  return $rc
}
rc=0
run_ctest "$tmp/pass.log" '^(ref_conformance|ref_plugin_conformance|ref_strict|fault_known)(\.|$)' || rc=$?
check "ctest passes the reference (in process, plugin, --strict) and the known fault (exit $rc)" test $rc -eq 0
check "ctest ran 4 certifications" grep -Eq "Test +#[0-9]+: ref_strict \.+ +Passed" "$tmp/pass.log"
check "ctest ran one test per clause" grep -Eq "Test +#[0-9]+: ref_conformance\.LAYER-NAME-1 \.+ +Passed" "$tmp/pass.log"
check "all of them passed" grep -q "100% tests passed, 0 tests failed" "$tmp/pass.log"
[ $rc -eq 0 ] || cat "$tmp/pass.log"
check "ref_conformance wrote its report into the build tree" \
  bash -c "ls '$consumer'/vgc_reports/ref_conformance/reference/*/report.json >/dev/null"

rc=0
run_ctest "$tmp/fault.log" '^fault_conformance(\.|$)' || rc=$?
check "ctest fails the fault plugin (VGC_FAULT=base-layer-destroyable)" test $rc -ne 0
check "its output names LAYER-BASE-2" grep -q "LAYER-BASE-2 (MUST): fail" "$tmp/fault.log"
check "its output gives the verdict" grep -q "verdict of the run: not-conformant" "$tmp/fault.log"
check "only LAYER-BASE-2's test fails" grep -q "1 tests failed" "$tmp/fault.log"
rc=0
run_ctest "$tmp/one.log" 'fault_conformance.LAYER-BASE-2' || rc=$?
check "ctest -R one clause certifies first (the fixture) and fails that clause" \
  grep -Eq "Test +#[0-9]+: fault_conformance \.+ +Passed" "$tmp/one.log"
[ $rc -ne 0 ] && grep -q "LAYER-BASE-2" "$tmp/fault.log" || cat "$tmp/fault.log"

rc=0
run_ctest "$tmp/missing.log" '^missing_plugin$' || rc=$?
check "ctest fails a missing plugin (vgc exit 2)" test $rc -ne 0
check "its output holds vgc's message and what to do" grep -q "vgc certify: plugin:.*no_such_plugin.so: .*no_such_plugin.so is not there: give the path of your plugin" "$tmp/missing.log"
[ $rc -ne 0 ] || cat "$tmp/missing.log"

# 4. examples/c_host, a C node with its own CMake project, built from a copy
# (so nothing can reach into the vgc tree) against the prefix alone; its
# ctest must pass, and with its seeded fault fail naming the clause, with a
# replay line that runs the installed vgc as printed.
mkdir "$tmp/c_host"
cp "$source/examples/c_host/"*.[ch] "$source/examples/c_host/CMakeLists.txt" "$tmp/c_host/"
build_example() {  # build_example DIR [CMAKE ARGS...]: configure and build it, output to DIR.log
  local dir=$1
  shift
  "$cmake" -S "$tmp/c_host" -B "$dir" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" \
    >"$dir.log" 2>&1 && "$cmake" --build "$dir" >>"$dir.log" 2>&1
}
runs_program() {  # runs_program LINE PROGRAM: LINE is [VGC_*='...' ...] PROGRAM replay ... (the environment's VGC_* repeated)
  printf '%s\n' "$1" | grep -qE "^([A-Z0-9_]+='[^']*' )*$2 replay "
}
run_example_ctest() {  # run_example_ctest DIR LOG: its ctest, output to LOG, returns ctest's status
  local rc=0
  (cd "$1" && "$ctest" --output-on-failure) >"$2" 2>&1 || rc=$?
  return $rc
}
example=$tmp/c_host_build
if build_example "$example"; then
  echo "ok: examples/c_host configures and builds against $prefix"
  check "examples/c_host found the installed package" grep -qx "vgc_DIR:PATH=$prefix/lib/cmake/vgc" "$example/CMakeCache.txt"
  check "examples/c_host runs the installed vgc" grep -qF "$prefix/bin/vgc" "$example/CTestTestfile.cmake"
  rc=0
  run_example_ctest "$example" "$tmp/c_host.log" || rc=$?
  check "examples/c_host: ctest passes (exit $rc)" test $rc -eq 0
  # every clause pass but the five optional capabilities it does not claim
  check "examples/c_host: its summary.md says CONFORMANT, every clause pass or not-claimed" bash -c \
    "grep -q -- '— CONFORMANT\$' '$example'/vgc_reports/c_host_conformance/*/*/summary.md &&
     grep -Eqx '[0-9]+ clauses: [0-9]+ pass, 5 not-claimed\..*' '$example'/vgc_reports/c_host_conformance/*/*/summary.md"
  [ $rc -eq 0 ] || cat "$tmp/c_host.log"
else
  cat "$example.log"
  echo "FAIL: examples/c_host does not configure and build against $prefix"
  failures=$((failures + 1))
fi

# The same build directory, reconfigured with the fault (a configure that
# reuses its cache is quicker than a new one).
if build_example "$example" -DC_HOST_FAULT=UNROTATED_CHILDREN; then
  rc=0
  run_example_ctest "$example" "$tmp/c_host_fault.log" || rc=$?
  check "examples/c_host with C_HOST_FAULT=UNROTATED_CHILDREN: ctest fails" test $rc -ne 0
  check "its output names BONE-DOWNSTREAM-1 failing" grep -q "BONE-DOWNSTREAM-1 (MUST): fail" "$tmp/c_host_fault.log"
  check "its output gives the verdict" grep -q "verdict of the run: not-conformant" "$tmp/c_host_fault.log"
  # The replay line names the installed program by its path (it is not on
  # PATH here); run it as printed: it shows the failure again (exit 1).
  replay_line=$(grep -m1 "replay: " "$tmp/c_host_fault.log" | sed 's/^.*replay: //') || true
  check "the replay line runs $prefix/bin/vgc" runs_program "$replay_line" "$prefix/bin/vgc"
  rc=0
  (cd / && eval "$replay_line") >"$tmp/c_host_replay.log" 2>&1 || rc=$?
  check "the replay line, run as printed from /, reproduces the failure (exit $rc)" test $rc -eq 1
  check "the replay names BONE-DOWNSTREAM-1" grep -q "BONE-DOWNSTREAM-1" "$tmp/c_host_replay.log"
  [ $rc -eq 1 ] || { echo "replay line: $replay_line"; cat "$tmp/c_host_fault.log" "$tmp/c_host_replay.log"; }
else
  cat "$example.log"
  echo "FAIL: examples/c_host with C_HOST_FAULT=UNROTATED_CHILDREN does not build against $prefix"
  failures=$((failures + 1))
fi
rc=0
"$cmake" -S "$tmp/c_host" -B "$example" -DC_HOST_FAULT=NO_SUCH_FAULT \
  >"$tmp/c_host_bad_fault.log" 2>&1 || rc=$?
check "an unknown C_HOST_FAULT stops the configure naming the faults" \
  bash -c "[ $rc -ne 0 ] && grep -q 'C_HOST_FAULT=NO_SUCH_FAULT is no seeded fault' '$tmp/c_host_bad_fault.log' &&
           grep -q 'UNROTATED_CHILDREN' '$tmp/c_host_bad_fault.log'"

if [ $failures -ne 0 ]; then
  echo "$failures check(s) failed"
  exit 1
fi
echo "all install checks passed"
