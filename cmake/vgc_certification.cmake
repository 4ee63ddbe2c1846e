# vgc_certification.cmake — installed as vgcCertification.cmake and included
# by vgcConfig.cmake: vgc_add_certification(), which registers a CTest test
# that certifies an implementation with the imported vgc::vgc program.
#
#   vgc_add_certification(NAME <test name> IMPL <implementation>
#                         [BASELINE <file>] [CLAUSES <globs>] [CASES <n>]
#                         [SEED <n>] [TIMEOUT <seconds>] [STRICT]
#                         [ENVIRONMENT <var=value>...])
#
# The test runs
#   vgc certify --impl <IMPL> --reports <build dir>/vgc_reports/<NAME> --quiet
#               [--baseline <abs file>] [--clauses <globs>] [--cases <n>]
#               [--seed <n>] [--timeout <s>] [--strict]
# in CMAKE_CURRENT_BINARY_DIR. vgc's exit code is the test's result: 0
# (conformant) passes; 1 (not conformant) and 2 (usage or infrastructure
# error, incomplete run) fail. vgc's verdict, findings and errors are the
# test's output (ctest --output-on-failure shows them).
#
# IMPL is passed as one argument and may hold generator expressions, e.g.
# plugin:$<TARGET_FILE:my_node>. A relative BASELINE is relative to
# CMAKE_CURRENT_SOURCE_DIR. ENVIRONMENT sets the test's ENVIRONMENT property.

if(CMAKE_VERSION VERSION_LESS 3.20)
  message(FATAL_ERROR "vgcCertification.cmake needs CMake 3.20 or newer (cmake_path); this is ${CMAKE_VERSION}")
endif()

function(vgc_add_certification)
  cmake_parse_arguments(PARSE_ARGV 0 arg "STRICT" "NAME;IMPL;BASELINE;CLAUSES;CASES;SEED;TIMEOUT" "ENVIRONMENT")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "vgc_add_certification: unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  foreach(required NAME IMPL)
    if(NOT arg_${required})
      message(FATAL_ERROR "vgc_add_certification: ${required} is required")
    endif()
  endforeach()
  foreach(value BASELINE CLAUSES CASES SEED TIMEOUT)
    if(value IN_LIST arg_KEYWORDS_MISSING_VALUES)
      message(FATAL_ERROR "vgc_add_certification: ${value} needs a value")
    endif()
  endforeach()
  if(NOT TARGET vgc::vgc)
    message(FATAL_ERROR "vgc_add_certification: no vgc::vgc target; call find_package(vgc CONFIG REQUIRED) first")
  endif()

  set(command vgc::vgc certify --impl "${arg_IMPL}"
      --reports "${CMAKE_CURRENT_BINARY_DIR}/vgc_reports/${arg_NAME}" --quiet)
  if(DEFINED arg_BASELINE)
    cmake_path(ABSOLUTE_PATH arg_BASELINE BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" OUTPUT_VARIABLE baseline)
    list(APPEND command --baseline "${baseline}")
  endif()
  if(DEFINED arg_CLAUSES)
    list(APPEND command --clauses "${arg_CLAUSES}")
  endif()
  if(DEFINED arg_CASES)
    list(APPEND command --cases "${arg_CASES}")
  endif()
  if(DEFINED arg_SEED)
    list(APPEND command --seed "${arg_SEED}")
  endif()
  if(DEFINED arg_TIMEOUT)
    list(APPEND command --timeout "${arg_TIMEOUT}")
  endif()
  if(arg_STRICT)
    list(APPEND command --strict)
  endif()

  add_test(NAME "${arg_NAME}" COMMAND ${command} WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
  set_tests_properties("${arg_NAME}" PROPERTIES LABELS vgc_certification)
  if(arg_ENVIRONMENT)
    set_tests_properties("${arg_NAME}" PROPERTIES ENVIRONMENT "${arg_ENVIRONMENT}")
  endif()
endfunction()
