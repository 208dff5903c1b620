# check_generated.cmake — run GENERATOR into OUT and fail unless OUT is byte for
# byte the committed TABLES: a generated file must match its generator.
execute_process(COMMAND ${GENERATOR} OUTPUT_FILE ${OUT} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${GENERATOR} failed: ${result}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${TABLES} RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  message(FATAL_ERROR "${TABLES} differs from what ${GENERATOR} writes (${OUT}); regenerate it")
endif()
