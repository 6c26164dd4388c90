# Resume (docs/cli.md, "Shards, merge, MPI, resume"), in one test: ARGS ('|'-separated) run with the test hook
# GJK2D_VALIDATE_TEST_STOP_AFTER_CHUNKS=3 exits 4 leaving CHECKPOINT_DIR/checkpoint.json, then ARGS
# with --resume exits 0 with a last line "report:", writes REPORT and removes the checkpoint. Each
# run is checked by expect_exit.cmake (EXPECT_SCRIPT). One script, not two tests sharing a fixture:
# the two runs see the same directory with nothing in between (the fixture pair failed in parallel
# ctest runs with "no checkpoint to resume from", cause not found).
file(REMOVE_RECURSE "${CHECKPOINT_DIR}")
function(expect_run expect args)
  execute_process(COMMAND ${CMAKE_COMMAND} -DEXE=${EXE} -DEXPECT=${expect} "-DARGS=${args}" ${ARGN}
                          -P ${EXPECT_SCRIPT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${out}${err}")
  endif()
endfunction()
set(ENV{GJK2D_VALIDATE_TEST_STOP_AFTER_CHUNKS} 3)
expect_run(4 "${ARGS}" -DEXPECT_FILE=${CHECKPOINT_DIR}/checkpoint.json)
unset(ENV{GJK2D_VALIDATE_TEST_STOP_AFTER_CHUNKS})
expect_run(0 "${ARGS}|--resume" -DEXPECT_LAST_LINE=report: -DEXPECT_FILE=${REPORT})
if(EXISTS "${CHECKPOINT_DIR}/checkpoint.json")
  message(FATAL_ERROR "resumed run: the finished campaign left its checkpoint")
endif()
message(STATUS "stopped with exit code 4, resumed to a report")
