# man_page.cmake — build/wavefront.1 from the program's own help: help2man
# reads `wavefront --help`, and each command's --help (cache's warm and clear
# too) is added as a section of its own, so the page lists every flag as
# --help does. Each flag becomes a roff tagged paragraph (.TP), which man
# wraps to the reader's width, where --help's own lines run to 200 columns.
# cmake -DBINARY=... -DOUT=... -P man_page.cmake

# `text` as roff: backslashes and hyphens escaped, no line starting a request.
function(roff_escape text out)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  if(text MATCHES "^[.']")
    set(text "\\&${text}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# One command's --help as roff: headings ("Options:") as .SS, each entry as
# .TP with its names in bold, its help (wrapped or not) as the paragraph.
string(REPEAT "." 26 any26) # CMake's regular expressions have no {26}
function(help_as_roff help out)
  # CMake lists split on ';' and group on brackets: hide both while splitting.
  string(REPLACE ";" "@SEMICOLON@" help "${help}")
  string(REPLACE "[" "@OPEN@" help "${help}")
  string(REPLACE "]" "@CLOSE@" help "${help}")
  string(REPLACE "\n" ";" lines "${help}")
  set(roff "")
  set(open_entry FALSE)
  foreach(line IN LISTS lines)
    string(REPLACE "@SEMICOLON@" ";" line "${line}")
    string(REPLACE "@OPEN@" "[" line "${line}")
    string(REPLACE "@CLOSE@" "]" line "${line}")
    if(line MATCHES "^      +([^ ].*)$") # a help wrapped below its entry
      roff_escape("${CMAKE_MATCH_1}" words)
      string(APPEND roff "${words}\n")
    elseif(line MATCHES "^  ([^ ]${any26}) ([^ ].*)$") # an entry and its help, from column 30 (CLI11's)
      string(STRIP "${CMAKE_MATCH_1}" names)
      roff_escape("${names}" names)
      roff_escape("${CMAKE_MATCH_2}" words)
      string(APPEND roff ".TP\n\\fB${names}\\fR\n${words}\n")
    elseif(line MATCHES "^  ([^ ].*)$") # an entry whose help is on the next line
      roff_escape("${CMAKE_MATCH_1}" names)
      string(APPEND roff ".TP\n\\fB${names}\\fR\n")
    elseif(line MATCHES "^([A-Z][^:]*):$") # a heading
      string(APPEND roff ".SS ${CMAKE_MATCH_1}\n")
    elseif(line STREQUAL "")
      continue()
    else()
      roff_escape("${line}" words)
      string(APPEND roff ".PP\n${words}\n")
    endif()
  endforeach()
  set(${out} "${roff}" PARENT_SCOPE)
endfunction()

set(extra "${OUT}.sections")
file(WRITE "${extra}" "")
foreach(command "render" "devices" "cache" "cache warm" "cache clear")
  separate_arguments(words UNIX_COMMAND "${command}")
  execute_process(COMMAND "${BINARY}" ${words} --help OUTPUT_VARIABLE text RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "wavefront ${command} --help failed")
  endif()
  help_as_roff("${text}" roff)
  string(TOUPPER "${command}" title)
  file(APPEND "${extra}" "[${title} COMMAND]\n${roff}\n")
endforeach()
# The version line alone: the rest of --version (commit, platforms) would
# run on as one paragraph, and says more of the machine that built the page
# than of the program.
execute_process(COMMAND "${BINARY}" --version OUTPUT_VARIABLE version RESULT_VARIABLE status)
string(REGEX REPLACE "\n.*" "" version "${version}")
execute_process(COMMAND help2man --no-info --name "wavefront path tracing on OpenCL devices"
                        --version-string "${version}" --include "${extra}" --output "${OUT}" "${BINARY}"
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "help2man failed")
endif()
