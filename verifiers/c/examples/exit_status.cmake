# Run a test program with ARGS (a ;-list) and require exit status RC and, if given, output
# matching EXPECT: for statuses CTest cannot tell apart (1 failures, 2 usage error).
execute_process(COMMAND ${EXE} ${ARGS} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 120)
if(NOT rc STREQUAL "${RC}")
    message(FATAL_ERROR "${EXE} ${ARGS}: exit status ${rc}, expected ${RC}\n${out}${err}")
endif()
if(DEFINED EXPECT AND NOT "${out}${err}" MATCHES "${EXPECT}")
    message(FATAL_ERROR "${EXE} ${ARGS}: no match for '${EXPECT}' in:\n${out}${err}")
endif()
