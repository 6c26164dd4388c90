# scripts/slurm/campaign-shards.sbatch as Slurm's job array would run it (SLURM_ARRAY_TASK_ID and
# _COUNT set by hand, tasks 0 and 1 of 2), then `merge`: the one-process run's report.
# Arguments: EXE, SCRIPT, PYTHON, COMPARE, OUT (the submit directory).
set(args "--family random:1500 --family hard/points --chunk 100 --no-timing --no-progress")
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
foreach(task 0 1)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env SLURM_ARRAY_TASK_ID=${task}
                          SLURM_ARRAY_TASK_COUNT=2 SLURM_SUBMIT_DIR=${OUT} SLURM_CPUS_PER_TASK=1
                          GJK=${EXE} "GJK_ARGS=${args}" OUT=shards bash ${SCRIPT}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "array task ${task} exited ${rc}\n${out}\n${err}")
  endif()
endforeach()
execute_process(COMMAND ${EXE} merge ${OUT}/shards/shard-0 ${OUT}/shards/shard-1 --out ${OUT}/merged
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "merge exited ${rc}\n${err}")
endif()
separate_arguments(arglist UNIX_COMMAND "${args}")
execute_process(COMMAND ${EXE} run ${arglist} --out ${OUT}/one RESULT_VARIABLE rc OUTPUT_QUIET
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the one-process run exited ${rc}\n${err}")
endif()
execute_process(COMMAND ${PYTHON} ${COMPARE} ${OUT}/one ${OUT}/merged RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the merged shards' report differs:\n${out}\n${err}")
endif()
message(STATUS "${out}")
