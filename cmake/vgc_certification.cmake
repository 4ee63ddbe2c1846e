# vgc_certification.cmake — installed as vgcCertification.cmake and included
# by vgcConfig.cmake: vgc_add_certification(), which registers CTest tests
# that certify an implementation with the imported vgc::vgc program: one
# certify run, and one test per clause that reads its report.
#
#   vgc_add_certification(NAME <test name> IMPL <implementation>
#                         [BASELINE <file>] [CLAUSES <globs>] [CASES <n>]
#                         [SEED <n>] [TIMEOUT <seconds>] [STRICT]
#                         [ENVIRONMENT <var=value>...])
#
# The test <NAME> runs
#   vgc certify --impl <IMPL> --reports <build dir>/vgc_reports/<NAME> --quiet
#               [--baseline <abs file>] [--clauses <globs>] [--cases <n>]
#               [--seed <n>] [--timeout <s>] [--strict]
# in CMAKE_CURRENT_BINARY_DIR, once. It passes when vgc wrote its report
# (whatever the verdict) and fails when it could not (bad options, an
# implementation that cannot be started): it is the FIXTURES_SETUP of
# fixture <NAME>. Then one test per clause of the catalog that CLAUSES
# selects, <NAME>.<CLAUSE-ID> (e.g. my_node.LAYER-NAME-1), requires that
# fixture and runs `vgc result <reports>/latest <CLAUSE-ID>`: it passes when
# the clause passes (or its finding does not gate the verdict: SHOULD, a
# profile difference, a known deviation; not-applicable, not-claimed),
# fails on a gating finding or when the clause is unchecked (an incomplete
# run), and is skipped when the run did not judge it. So `ctest` fails
# exactly when the verdict is not conformant or incomplete,
# `ctest -R LAYER-NAME-1` certifies once and shows that clause (CTest runs
# the fixture's setup test first), and each clause has a history of its
# own in CDash or a CI's test view. The per-clause tests are listed when
# ctest starts (`vgc clauses`), like gtest_discover_tests does.
#
# IMPL is passed as one argument and may hold generator expressions, e.g.
# plugin:$<TARGET_FILE:my_node>. A relative BASELINE is relative to
# CMAKE_CURRENT_SOURCE_DIR. ENVIRONMENT sets the certify test's ENVIRONMENT
# property. All the tests carry the label vgc_certification.

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
  # Passes when the report was written ("report: <dir>/summary.md"), whatever
  # the verdict: the clauses' tests judge it.
  set_tests_properties("${arg_NAME}" PROPERTIES LABELS vgc_certification FIXTURES_SETUP "${arg_NAME}"
                       PASS_REGULAR_EXPRESSION "report: [^\n]*summary\\.md")
  if(arg_ENVIRONMENT)
    set_tests_properties("${arg_NAME}" PROPERTIES ENVIRONMENT "${arg_ENVIRONMENT}")
  endif()

  # One test per clause, listed when ctest starts (the vgc program may not
  # exist yet at configure time).
  set(clauses "*")
  if(DEFINED arg_CLAUSES)
    set(clauses "${arg_CLAUSES}")
  endif()
  set(include_file "${CMAKE_CURRENT_BINARY_DIR}/vgc_certification_${arg_NAME}_clauses.cmake")
  set(run_dir "${CMAKE_CURRENT_BINARY_DIR}/vgc_reports/${arg_NAME}/latest")
  file(GENERATE OUTPUT "${include_file}" CONTENT "\
execute_process(COMMAND \"$<TARGET_FILE:vgc::vgc>\" clauses --clauses \"${clauses}\"
                OUTPUT_VARIABLE vgc_clauses RESULT_VARIABLE vgc_rc)
if(NOT vgc_rc EQUAL 0)
  message(WARNING \"vgc_add_certification(${arg_NAME}): `vgc clauses` failed (\${vgc_rc}): no per-clause tests\")
endif()
string(REGEX MATCHALL \"(^|\\n)[A-Z0-9]+(-[A-Z0-9]+)+\" vgc_ids \"\${vgc_clauses}\")
foreach(vgc_id IN LISTS vgc_ids)
  string(STRIP \"\${vgc_id}\" vgc_id)
  add_test(\"${arg_NAME}.\${vgc_id}\" \"$<TARGET_FILE:vgc::vgc>\" result \"${run_dir}\" \"\${vgc_id}\")
  set_tests_properties(\"${arg_NAME}.\${vgc_id}\" PROPERTIES FIXTURES_REQUIRED \"${arg_NAME}\"
                       SKIP_RETURN_CODE 77 LABELS vgc_certification)
endforeach()
")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${include_file}")
endfunction()
