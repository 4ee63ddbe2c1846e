# bench_subdivision: reference Catmull-Clark vs OpenSubdiv refining a
# 100k-face mesh with the same creases, after checking they agree (median
# of forked runs: wall, CPU, peak memory). Run: build/bench/bench_subdivision [levels [repeats]]
if(NOT TARGET bench_subdivision AND TARGET vgc_oracle_osd)
  add_executable(bench_subdivision ${CMAKE_CURRENT_LIST_DIR}/bench_subdivision.cpp)
  target_link_libraries(bench_subdivision PRIVATE vgc_oracle_osd vgc_reference)
endif()
