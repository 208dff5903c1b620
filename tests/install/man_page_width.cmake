# man_page_width.cmake — the ctest Install.TheManPageFitsEightyColumns: the
# page build/wavefront.1 formatted by nroff for 80 columns, as
# `MANWIDTH=80 man -l` formats it, has no line past column 80, lists the flags
# of every command (cache warm's among them), and keeps --version's platform
# lines out of its description.
# cmake -DPAGE=build/wavefront.1 -P man_page_width.cmake
execute_process(COMMAND nroff -man -Tascii -rLL=80n "${PAGE}" OUTPUT_VARIABLE text RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "nroff failed on ${PAGE} (groff-base: scripts/setup.sh --tests installs it)")
endif()
string(ASCII 8 backspace)
string(REGEX REPLACE ".${backspace}" "" text "${text}") # bold and underline by overstriking
# One character for another where CMake's lists would split or group.
string(REPLACE ";" "," lines "${text}")
string(REPLACE "[" "(" lines "${lines}")
string(REPLACE "]" ")" lines "${lines}")
string(REPLACE "\n" ";" lines "${lines}")
set(too_long 0)
foreach(line IN LISTS lines)
  string(LENGTH "${line}" length)
  if(length GREATER 80)
    message(SEND_ERROR "past column 80: ${line}")
    math(EXPR too_long "${too_long} + 1")
  endif()
endforeach()
foreach(expected "CACHE WARM COMMAND" "--pool-size" "--cache-dir" "--queue-push")
  string(FIND "${text}" "${expected}" at)
  if(at EQUAL -1)
    message(SEND_ERROR "the page does not hold ${expected}")
  endif()
endforeach()
string(FIND "${text}" "Portable Computing Language" at)
if(NOT at EQUAL -1)
  message(SEND_ERROR "the page holds --version's platform lines")
endif()
message(STATUS "${PAGE}: ${too_long} lines past column 80")
