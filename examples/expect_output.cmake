# Runs EXE and fails unless it exits 0, writes nothing on stderr, and its stdout matches REGEX
# (a CMake regular expression). PASS_REGULAR_EXPRESSION alone ignores the exit code: a program
# that printed the right values and then crashed, or a leak report at exit under the sanitizers,
# would pass.
execute_process(COMMAND ${EXE} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc STREQUAL "0")
  message(FATAL_ERROR "${EXE} exited ${rc}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(NOT err STREQUAL "")
  message(FATAL_ERROR "${EXE} wrote to stderr:\n${err}")
endif()
if(NOT out MATCHES "${REGEX}")
  message(FATAL_ERROR "${EXE}: stdout does not match\n${REGEX}\nstdout:\n${out}")
endif()
message(STATUS "${EXE}: exit code 0, output as derived")
