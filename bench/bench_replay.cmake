# bench_replay: the time `vgc replay`'s check takes on long fan/grid programs,
# reference in process and `vgc serve` behind exec: (issue 21).
# Run: build/bench/bench_replay [--routes reference,exec] [--shape fan|grid] SIZE...
if(NOT TARGET bench_replay AND TARGET vgc_conformance)
  add_executable(bench_replay ${CMAKE_CURRENT_LIST_DIR}/bench_replay.cpp)
  target_link_libraries(bench_replay PRIVATE vgc_conformance)
endif()
