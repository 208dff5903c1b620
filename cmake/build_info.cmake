# Writes OUT (build_info.h): the commit the build was made from and the build
# type, for `wavefront --version`. Run at every build; the file is rewritten
# only when its text changes, so nothing recompiles needlessly.
execute_process(COMMAND git -C "${ROOT}" describe --always --dirty --abbrev=12
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
if(failed OR commit STREQUAL "")
  set(commit "unknown (not built from a git checkout)")
endif()
set(text "#define WF_COMMIT \"${commit}\"\n#define WF_BUILD_TYPE \"${BUILD_TYPE}\"\n")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
