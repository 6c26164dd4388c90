# Every Catch2 case of EXE is exactly one CTest entry, and that entry runs exactly that case
# (docs/testing.md, "Rules every test is held to"). catch_discover_tests turns each line of
# `EXE --list-test-names-only` into an entry "PREFIX<name>" running `EXE <name, escaped>`; a name
# that breaks this (a ';' splits it in two entries whose filters match nothing, and Catch2 exits 0
# for a filter that matches nothing) would pass unseen. This check, per binary:
#  1. lists the Catch2 cases (`EXE --list-test-names-only`);
#  2. lists the CTest entries whose command runs EXE (`ctest -N --show-only=json-v1` in BUILD);
#  3. fails unless the counts are equal, every entry runs with `-w NoTests` (no match = failure),
#     and each entry's filter, given to EXE, selects exactly the one case the entry is named for.
# Arguments: EXE, PREFIX (the entries' TEST_PREFIX), CTEST (ctest), BUILD (the build tree).

execute_process(COMMAND ${EXE} --list-test-names-only OUTPUT_VARIABLE listed RESULT_VARIABLE rc)
if(rc LESS 0 OR NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "${EXE} --list-test-names-only failed: ${rc}")
endif()
string(FIND "${listed}" ";" semicolon)
if(NOT semicolon EQUAL -1)
  message(FATAL_ERROR "a Catch2 case name contains ';' (CTest's discovery splits it into two "
                      "entries that run nothing): rename it\n${listed}")
endif()
string(REGEX REPLACE "\n$" "" listed "${listed}")
string(REPLACE "\n" ";" cases "${listed}")
list(LENGTH cases case_count)

execute_process(COMMAND ${CTEST} --test-dir ${BUILD} -N --show-only=json-v1 -R "^${PREFIX}"
                OUTPUT_VARIABLE json RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "ctest -N --show-only=json-v1 exited ${rc}")
endif()
string(JSON tests GET "${json}" tests)
string(JSON test_count LENGTH "${tests}")
set(entries 0)
set(problems "")
if(test_count GREATER 0)
  math(EXPR last "${test_count} - 1")
  foreach(i RANGE ${last})
    string(JSON test GET "${tests}" ${i}) # parse the long list once per entry, the entry from then on
    string(JSON name GET "${test}" name)
    string(JSON command ERROR_VARIABLE no_command GET "${test}" command)
    if(no_command)
      continue()
    endif()
    string(JSON exe GET "${command}" 0)
    if(NOT exe STREQUAL EXE)
      continue() # another program's test under the same prefix (the CLI tests, this check)
    endif()
    math(EXPR entries "${entries} + 1")
    string(JSON filter GET "${command}" 1)
    string(JSON argc LENGTH "${command}")
    set(no_tests_warning OFF)
    math(EXPR last_arg "${argc} - 1")
    foreach(a RANGE 2 ${last_arg})
      string(JSON arg GET "${command}" ${a})
      if(arg STREQUAL "NoTests")
        set(no_tests_warning ON)
      endif()
    endforeach()
    if(NOT no_tests_warning)
      string(APPEND problems "'${name}': runs without -w NoTests (a filter matching nothing passes)\n")
    endif()
    execute_process(COMMAND ${EXE} "${filter}" --list-test-names-only OUTPUT_VARIABLE selected)
    string(REGEX REPLACE "\n$" "" selected "${selected}")
    string(LENGTH "${PREFIX}" prefix_length)
    string(SUBSTRING "${name}" ${prefix_length} -1 case_name)
    if(NOT selected STREQUAL case_name)
      string(APPEND problems "'${name}': its filter '${filter}' selects '${selected}', not the case it is named for\n")
    endif()
  endforeach()
endif()
if(NOT entries EQUAL case_count)
  string(APPEND problems "${case_count} Catch2 cases but ${entries} CTest entries run ${EXE}\n")
endif()
if(problems)
  message(FATAL_ERROR "${problems}")
endif()
message(STATUS "${EXE}: ${case_count} Catch2 cases, ${entries} CTest entries, each running exactly its case")
