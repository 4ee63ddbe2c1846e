# bench_real_meshes: on real meshes (e.g. libcgal-demo's, extracted by the
# MeshCorpus.Extract test into build/tests/meshes/corpus), each check of
# certify --mesh with the reference in process beside its oracle alone
# (median of 3). Run: build/bench/bench_real_meshes [--levels N] MESH...
if(NOT TARGET bench_real_meshes AND TARGET vgc_capability_checks AND TARGET vgc_mesh_import)
  add_executable(bench_real_meshes ${CMAKE_CURRENT_LIST_DIR}/bench_real_meshes.cpp)
  target_link_libraries(bench_real_meshes PRIVATE vgc_capability_checks vgc_mesh_import vgc_conformance)
endif()
