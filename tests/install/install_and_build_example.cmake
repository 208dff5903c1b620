# install_and_build_example.cmake — the ctest Install.TheExampleBuildsAgainstThePackage:
# `cmake --install` into a fresh prefix, then examples/render_scene configured
# with find_package(wavefront) from there, built and run on the Cornell box;
# the man page and the bash completion must be installed too.
# cmake -DBUILD=... -DSOURCE=... -DWORK=... -P install_and_build_example.cmake
file(REMOVE_RECURSE "${WORK}")
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${ARGN} failed (${status}):\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()
run(${CMAKE_COMMAND} --install "${BUILD}" --prefix "${WORK}/prefix")
foreach(file bin/wavefront share/man/man1/wavefront.1 share/bash-completion/completions/wavefront
             include/wavefront/path_state.h include/wavefront/host/render/renderer.h
             lib/cmake/wavefront/wavefrontConfig.cmake)
  if(NOT EXISTS "${WORK}/prefix/${file}")
    message(FATAL_ERROR "cmake --install did not install ${file}")
  endif()
endforeach()
file(READ "${WORK}/prefix/share/man/man1/wavefront.1" man)
if(NOT man MATCHES "pool\\\\?-size")
  message(FATAL_ERROR "the man page does not list render's flags")
endif()
run(${CMAKE_COMMAND} -S "${SOURCE}/examples/render_scene" -B "${WORK}/example"
    -DCMAKE_PREFIX_PATH=${WORK}/prefix -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build "${WORK}/example" -j2)
run("${WORK}/example/render_scene" "${SOURCE}/scenes/cornell-box.gltf" "${WORK}/cornell.exr")
if(NOT last_output MATCHES "mean radiance 0\\.[1-9]" OR NOT EXISTS "${WORK}/cornell.exr")
  message(FATAL_ERROR "the example rendered nothing sensible: ${last_output}")
endif()
message(STATUS "${last_output}")
file(REMOVE_RECURSE "${WORK}")
