# `cmake --build build --target uninstall`: removes every file the last
# `cmake --install` wrote, as its install_manifest.txt lists them (absolute
# paths; DESTDIR, if set now, is prefixed as it was for the install), then the
# directories this emptied under glslrun's own names.
#   cmake -DMANIFEST=build/install_manifest.txt -P uninstall.cmake
if(NOT EXISTS "${MANIFEST}")
  message(FATAL_ERROR "${MANIFEST} does not exist: nothing was installed from this build (or it was by component: "
                      "install without --component first)")
endif()
file(STRINGS "${MANIFEST}" files)
set(dirs)
foreach(file IN LISTS files)
  set(path "$ENV{DESTDIR}${file}")
  if(IS_SYMLINK "${path}" OR EXISTS "${path}")
    message(STATUS "Removing ${path}")
    file(REMOVE "${path}")
  else()
    message(STATUS "Already gone: ${path}")
  endif()
  get_filename_component(dir "${path}" DIRECTORY)
  list(APPEND dirs "${dir}")
endforeach()
# glslrun's own directories (include/glslrun, lib/cmake/glslrun, the Python
# package, share/doc/glslrun), once empty; never a shared one such as bin.
list(REMOVE_DUPLICATES dirs)
foreach(dir IN LISTS dirs)
  get_filename_component(parent "${dir}" DIRECTORY)
  foreach(candidate "${dir}" "${parent}")
    get_filename_component(candidate_name "${candidate}" NAME)
    if(candidate_name STREQUAL "glslrun" AND IS_DIRECTORY "${candidate}")
      file(GLOB_RECURSE left "${candidate}/*")
      if(NOT left)
        file(REMOVE_RECURSE "${candidate}")
      endif()
    endif()
  endforeach()
endforeach()
