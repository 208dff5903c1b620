# man_page.cmake — build/wavefront.1 from the program's own help: help2man
# reads `wavefront --help` and `--version`, and each command's --help is
# added as a section of its own, so the page lists every flag as --help does.
# cmake -DBINARY=... -DOUT=... -P man_page.cmake
set(extra "${OUT}.sections")
file(WRITE "${extra}" "")
foreach(command render devices cache)
  execute_process(COMMAND "${BINARY}" ${command} --help OUTPUT_VARIABLE text RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "wavefront ${command} --help failed")
  endif()
  string(TOUPPER "${command}" title)
  file(APPEND "${extra}" "[${title} COMMAND]\n.nf\n${text}\n.fi\n\n")
endforeach()
execute_process(COMMAND help2man --no-info --name "wavefront path tracing on OpenCL devices"
                        --include "${extra}" --output "${OUT}" "${BINARY}"
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "help2man failed")
endif()
