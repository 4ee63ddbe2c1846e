# bench_verse_host: a real mesh's commands sent to a Verse host over
# loopback and seen by a subscriber (issue 28): vgc's host in process (its
# node followed by digest, or --whole read whole as before), or any running
# host (--host). Run: build/bench/bench_verse_host [--whole | --host A:P] MESH...
if(NOT TARGET bench_verse_host AND TARGET vgc_mesh_import AND TARGET vgc_verse)
  add_executable(bench_verse_host ${CMAKE_CURRENT_LIST_DIR}/bench_verse_host.cpp)
  target_link_libraries(bench_verse_host PRIVATE vgc_mesh_import vgc_verse)
endif()
