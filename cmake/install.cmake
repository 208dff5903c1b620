# install.cmake — `cmake --install build [--prefix P]`: the wavefront
# program, its man page (help2man, from its own --help) and bash completion,
# the renderer as a library, wavefront::wavefront, with its headers and a
# CMake package, so that find_package(wavefront) works
# (examples/render_scene builds against it, tests/install/), and the Python
# module, alone in the component `python` that `pip install .` installs
# (pyproject.toml).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set_target_properties(wavefront_core PROPERTIES EXPORT_NAME wavefront OUTPUT_NAME wavefront)
install(TARGETS wavefront RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS wavefront_core EXPORT wavefrontTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY host/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/wavefront/host FILES_MATCHING PATTERN "*.h")
install(DIRECTORY include/wavefront/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/wavefront FILES_MATCHING PATTERN "*.h")
install(EXPORT wavefrontTargets NAMESPACE wavefront:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/wavefront)
configure_package_config_file(cmake/wavefrontConfig.cmake.in ${CMAKE_BINARY_DIR}/wavefrontConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/wavefront)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/wavefrontConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/wavefrontConfig.cmake ${CMAKE_BINARY_DIR}/wavefrontConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/wavefront)

find_program(WF_HELP2MAN help2man)
if(WF_HELP2MAN)
  add_custom_command(OUTPUT ${CMAKE_BINARY_DIR}/wavefront.1
                     COMMAND ${CMAKE_COMMAND} -DBINARY=$<TARGET_FILE:wavefront> -DOUT=${CMAKE_BINARY_DIR}/wavefront.1
                             -P ${CMAKE_SOURCE_DIR}/cmake/man_page.cmake
                     DEPENDS wavefront ${CMAKE_SOURCE_DIR}/cmake/man_page.cmake VERBATIM)
  add_custom_target(wf_man_page ALL DEPENDS ${CMAKE_BINARY_DIR}/wavefront.1)
  install(FILES ${CMAKE_BINARY_DIR}/wavefront.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "no man page (help2man not found)")
endif()
install(FILES scripts/wavefront-completion.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
        RENAME wavefront)

# `import wavefront` and `python -m wavefront`: the package wavefront/ (the
# module as its __init__, and __main__.py), in the wheel's root when pip
# builds it (scikit-build-core sets SKBUILD), else in the prefix's
# site-packages for the interpreter it was built for.
if(TARGET wavefront_python)
  if(SKBUILD)
    set(WF_PYTHON_INSTALL_DIR .)
  else()
    set(WF_PYTHON_INSTALL_DIR
        ${CMAKE_INSTALL_LIBDIR}/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/site-packages)
  endif()
  install(TARGETS wavefront_python LIBRARY DESTINATION ${WF_PYTHON_INSTALL_DIR}/wavefront COMPONENT python)
  install(FILES host/python/__main__.py DESTINATION ${WF_PYTHON_INSTALL_DIR}/wavefront COMPONENT python)
endif()
