# `cmake --install build` (default prefix /usr/local), stripped unless
# GLSLRUN_INSTALL_DEBUG (cmake/install_strip.cmake), in three components
# (`cmake --install build --component NAME`):
#   runtime      the glslrun command, its man page and bash/zsh completion,
#                libglslrun.so.0, the licence
#   development  the public headers, the static libraries, the libglslrun.so
#                link, the CMake package (find_package(glslrun)) and the
#                pkg-config files (pkg-config glslrun, glslrun-scene)
#   python       the Python package (python/CMakeLists.txt)
# Everything is relocatable: the config and .pc files find the prefix from
# where they are. `cmake --build build --target uninstall` removes what the
# last install wrote (install_manifest.txt).
include(CMakePackageConfigHelpers)

set(GLSLRUN_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/glslrun)
install(TARGETS glslrun RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
# The documentation that `glslrun --help` points to.
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime FILES_MATCHING PATTERN "*.md" PATTERN "*.png")
install(TARGETS glslrun_lib glslrun_shared glslrun_scene EXPORT glslrunTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT development
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
glslrun_strip_static_on_install(development
  ${CMAKE_INSTALL_LIBDIR}/$<TARGET_FILE_NAME:glslrun_lib> ${CMAKE_INSTALL_LIBDIR}/$<TARGET_FILE_NAME:glslrun_scene>)
if(TARGET glslrun_jit)
  install(TARGETS glslrun_jit LIBRARY DESTINATION ${glslrun_jit_install_dir} COMPONENT runtime)
endif()
install(DIRECTORY include/glslrun DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT development)
install(FILES ${PROJECT_BINARY_DIR}/include/glslrun/version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/glslrun
  COMPONENT development)
install(FILES LICENSE docs/licenses.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
install(FILES tools/completion/glslrun.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
  RENAME glslrun COMPONENT runtime)
install(FILES tools/completion/_glslrun DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/site-functions COMPONENT runtime)

# The man page from the built command's --help (cmake/man_page.cmake), where
# Debian's help2man is installed.
find_program(GLSLRUN_HELP2MAN help2man)
if(GLSLRUN_HELP2MAN)
  add_custom_command(OUTPUT ${PROJECT_BINARY_DIR}/glslrun.1
    COMMAND ${CMAKE_COMMAND} -DGLSLRUN=$<TARGET_FILE:glslrun> -DHELP2MAN=${GLSLRUN_HELP2MAN}
            -DOUTPUT=${PROJECT_BINARY_DIR}/glslrun.1 -P ${PROJECT_SOURCE_DIR}/cmake/man_page.cmake
    DEPENDS glslrun ${PROJECT_SOURCE_DIR}/cmake/man_page.cmake
    COMMENT "man page glslrun.1 from glslrun --help")
  add_custom_target(glslrun_man ALL DEPENDS ${PROJECT_BINARY_DIR}/glslrun.1)
  install(FILES ${PROJECT_BINARY_DIR}/glslrun.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT runtime)
else()
  message(STATUS "help2man not found: no man page")
endif()

install(EXPORT glslrunTargets NAMESPACE glslrun:: DESTINATION ${GLSLRUN_CMAKE_DIR} COMPONENT development)
# The same targets from the build tree, without installing.
export(EXPORT glslrunTargets NAMESPACE glslrun:: FILE ${PROJECT_BINARY_DIR}/glslrunTargets.cmake)
configure_package_config_file(cmake/glslrunConfig.cmake.in ${PROJECT_BINARY_DIR}/glslrunConfig.cmake
  INSTALL_DESTINATION ${GLSLRUN_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/glslrunConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)  # 0.x: a minor version may change the API
install(FILES ${PROJECT_BINARY_DIR}/glslrunConfig.cmake ${PROJECT_BINARY_DIR}/glslrunConfigVersion.cmake
  DESTINATION ${GLSLRUN_CMAKE_DIR} COMPONENT development)

file(RELATIVE_PATH GLSLRUN_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" GLSLRUN_PC_TO_PREFIX ${GLSLRUN_PC_TO_PREFIX})
foreach(pc glslrun glslrun-scene)
  configure_file(cmake/${pc}.pc.in ${PROJECT_BINARY_DIR}/${pc}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/${pc}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT development)
endforeach()

if(NOT TARGET uninstall)
  add_custom_target(uninstall
    COMMAND ${CMAKE_COMMAND} -DMANIFEST=${PROJECT_BINARY_DIR}/install_manifest.txt -P ${PROJECT_SOURCE_DIR}/cmake/uninstall.cmake
    COMMENT "removing the files of the last `cmake --install` (install_manifest.txt)")
endif()
