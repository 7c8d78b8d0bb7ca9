# The adapter survives malformed input: run it on INPUT, and require output matching EXPECT and
# an exit status of 0 or 2 (never a crash or a sanitizer's abort).
execute_process(COMMAND ${ADAPTER} INPUT_FILE ${INPUT} OUTPUT_VARIABLE out ERROR_VARIABLE err
                RESULT_VARIABLE rc TIMEOUT 60)
if(NOT (rc STREQUAL "0" OR rc STREQUAL "2"))
    message(FATAL_ERROR "the adapter exited with '${rc}' on ${INPUT}\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT out MATCHES "${EXPECT}")
    message(FATAL_ERROR "the adapter's answer to ${INPUT} does not match '${EXPECT}':\n${out}")
endif()
