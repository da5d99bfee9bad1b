# The JIT plugin (runtime/jit_plugin.h says why there is one):
# runtime/jit/*.cpp, raster/fused/gen/*.cpp and libLLVM in libglslrun-jit.so, which the library
# loads at its first compile. What the JIT's own code needs of the rest of
# the library (the opcode table, the budgets, the sampler's kernel) the
# linker takes from the static library into the plugin; those copies stay
# the plugin's (--exclude-libs, and a version script that exports the entry
# point alone), so they never meet the host's.
# The build key ties a plugin to the build of the library that loads it:
# made once per build directory.
if(NOT DEFINED GLSLRUN_JIT_BUILD_KEY)
  string(RANDOM LENGTH 16 glslrun_key)
  set(GLSLRUN_JIT_BUILD_KEY "${PROJECT_VERSION}-${GLSLRUN_LANES}-${glslrun_key}" CACHE INTERNAL
    "ties libglslrun-jit.so to the library built beside it")
endif()
set(glslrun_jit_install_dir ${CMAKE_INSTALL_LIBDIR}/glslrun)
file(RELATIVE_PATH glslrun_jit_from_bin /${CMAKE_INSTALL_BINDIR} /${glslrun_jit_install_dir})
# Only the loader knows where to look (the rest of the library is compiled without these).
set_source_files_properties(${PROJECT_SOURCE_DIR}/runtime/jit_plugin.cpp PROPERTIES COMPILE_DEFINITIONS
  "$<$<BOOL:${GLSLRUN_JIT}>:GLSLRUN_HAVE_JIT=1>;GLSLRUN_JIT_BUILD_KEY=\"${GLSLRUN_JIT_BUILD_KEY}\";GLSLRUN_JIT_FROM_BIN=\"${glslrun_jit_from_bin}\";GLSLRUN_JIT_INSTALL_DIR=\"${CMAKE_INSTALL_FULL_LIBDIR}/glslrun\";GLSLRUN_JIT_BUILD_DIR=\"${PROJECT_BINARY_DIR}\"")
if(NOT GLSLRUN_JIT)
  return()
endif()

# The fused fragment functions' emitter (raster/fused/gen/) is LLVM code too.
file(GLOB GLSLRUN_JIT_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/runtime/jit/*.cpp
  ${PROJECT_SOURCE_DIR}/raster/fused/gen/*.cpp)
add_library(glslrun_jit MODULE ${GLSLRUN_JIT_SOURCES})
set_target_properties(glslrun_jit PROPERTIES OUTPUT_NAME glslrun-jit PREFIX lib
  LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR} POSITION_INDEPENDENT_CODE ON)
target_compile_options(glslrun_jit PRIVATE ${GLSLRUN_WARNINGS} -fvisibility=hidden -fvisibility-inlines-hidden)
target_compile_definitions(glslrun_jit PRIVATE GLSLRUN_LANES=${GLSLRUN_LANES})
# The key on its one user only: the plugin's other objects stay the same from one
# build directory to the next, so ccache shares them.
set_property(SOURCE ${PROJECT_SOURCE_DIR}/runtime/jit/entry.cpp APPEND PROPERTY COMPILE_DEFINITIONS
  GLSLRUN_JIT_BUILD_KEY="${GLSLRUN_JIT_BUILD_KEY}")
target_include_directories(glslrun_jit PRIVATE ${PROJECT_SOURCE_DIR})
target_include_directories(glslrun_jit SYSTEM PRIVATE ${GLSLRUN_LLVM_INCLUDE})
target_link_libraries(glslrun_jit PRIVATE glslrun_lib ${GLSLRUN_LLVM_LIB} fmt::fmt)
target_link_options(glslrun_jit PRIVATE "LINKER:--exclude-libs,ALL"
  "LINKER:--version-script=${PROJECT_SOURCE_DIR}/cmake/jit_plugin.map")
set_property(TARGET glslrun_jit APPEND PROPERTY LINK_DEPENDS ${PROJECT_SOURCE_DIR}/cmake/jit_plugin.map)
# What builds a program with the scene library (the command, the tests, the
# Python module) builds the plugin too, so that its JIT runs. (Not on the
# library itself: the plugin links it.)
# Every symbol resolved when the plugin is linked, not at its dlopen (where a
# missing one would leave the interpreter running). Not under the
# sanitizers, whose runtime the executable alone links.
if(NOT GLSLRUN_SANITIZE)
  target_link_options(glslrun_jit PRIVATE "LINKER:--no-undefined")
endif()
