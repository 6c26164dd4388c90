# `mpirun -n 2 gjk-validate run ...` gives the one-process run's report (scripts/compare_reports.py:
# everything but timing, date, host, threads and command) and the same cases.jsonl.
# Arguments: EXE, MPIEXEC, PYTHON, COMPARE, OUT.
# --allow-run-as-root and --oversubscribe: what a root container with 2 cores needs (OpenMPI).
set(args run --family random:2000 --family hard/sliver --family hard/points --chunk 300
         --no-timing --no-progress --per-case)
execute_process(COMMAND ${EXE} ${args} --out ${OUT}/one RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the one-process run exited ${rc}")
endif()
execute_process(COMMAND ${MPIEXEC} --allow-run-as-root --oversubscribe -n 2 ${EXE} ${args}
                        --out ${OUT}/two
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mpirun -n 2 exited ${rc}\n${out}\n${err}")
endif()
execute_process(COMMAND ${PYTHON} ${COMPARE} ${OUT}/one ${OUT}/two RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the reports differ:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/one/cases.jsonl
                        ${OUT}/two/cases.jsonl RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cases.jsonl differs between the one-process run and mpirun -n 2")
endif()
message(STATUS "${out}")
