# bench_manifold: reference/geometry/mesh_topology vs oracles/cgal_manifold (and the
# reference's split normals) on a ~100k-face mesh. Run: build-*/bench/bench_manifold
if(NOT TARGET bench_manifold AND TARGET vgc_oracle_cgal)
  add_executable(bench_manifold ${CMAKE_CURRENT_LIST_DIR}/bench_manifold.cpp)
  target_link_libraries(bench_manifold PRIVATE vgc_reference vgc_oracle_cgal benchmark::benchmark)
endif()
