# Included before any install() rule, so that it runs first in every
# component's install: binaries are stripped by default (the unstripped
# RelWithDebInfo install was 355 MB, stripped under 20 MB).
# -DGLSLRUN_INSTALL_DEBUG=ON installs them with their debug info instead;
# `cmake --install --strip` strips either way.
option(GLSLRUN_INSTALL_DEBUG "install binaries and libraries with their debug info (unstripped)" OFF)
if(NOT GLSLRUN_INSTALL_DEBUG)
  install(CODE "if(NOT CMAKE_INSTALL_DO_STRIP)\n  set(CMAKE_INSTALL_DO_STRIP 1)\nendif()" ALL_COMPONENTS)
endif()

# CMake strips executables and shared libraries; the static libraries'
# debug sections (over 80% of libglslrun.a) go with strip --strip-debug.
function(glslrun_strip_static_on_install component)
  if(NOT CMAKE_STRIP)
    return()
  endif()
  foreach(file IN LISTS ARGN)
    install(CODE "if(CMAKE_INSTALL_DO_STRIP)
  execute_process(COMMAND \"${CMAKE_STRIP}\" --strip-debug \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${file}\"
                  RESULT_VARIABLE glslrun_strip_result)
  if(glslrun_strip_result)
    message(FATAL_ERROR \"strip --strip-debug ${file} failed\")
  endif()
endif()" COMPONENT ${component})
  endforeach()
endfunction()
