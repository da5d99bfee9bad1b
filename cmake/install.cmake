# `cmake --install build` (default prefix /usr/local): the glslrun command,
# the libraries, the public headers, the CMake package (find_package(glslrun))
# and the pkg-config files (pkg-config glslrun, glslrun-scene). Everything is
# relocatable: the config and .pc files find the prefix from where they are.
include(CMakePackageConfigHelpers)

set(GLSLRUN_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/glslrun)
install(TARGETS glslrun RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The documentation that `glslrun --help` points to.
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} FILES_MATCHING PATTERN "*.md" PATTERN "*.png")
install(TARGETS glslrun_lib glslrun_shared glslrun_scene EXPORT glslrunTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} NAMELINK_COMPONENT Development
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY include/glslrun DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_BINARY_DIR}/include/glslrun/version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/glslrun)

install(EXPORT glslrunTargets NAMESPACE glslrun:: DESTINATION ${GLSLRUN_CMAKE_DIR})
# The same targets from the build tree, without installing.
export(EXPORT glslrunTargets NAMESPACE glslrun:: FILE ${PROJECT_BINARY_DIR}/glslrunTargets.cmake)
configure_package_config_file(cmake/glslrunConfig.cmake.in ${PROJECT_BINARY_DIR}/glslrunConfig.cmake
  INSTALL_DESTINATION ${GLSLRUN_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/glslrunConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)  # 0.x: a minor version may change the API
install(FILES ${PROJECT_BINARY_DIR}/glslrunConfig.cmake ${PROJECT_BINARY_DIR}/glslrunConfigVersion.cmake
  DESTINATION ${GLSLRUN_CMAKE_DIR})

file(RELATIVE_PATH GLSLRUN_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" GLSLRUN_PC_TO_PREFIX ${GLSLRUN_PC_TO_PREFIX})
foreach(pc glslrun glslrun-scene)
  configure_file(cmake/${pc}.pc.in ${PROJECT_BINARY_DIR}/${pc}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/${pc}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endforeach()
