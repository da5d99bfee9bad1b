# The man page, generated at build time from the built command's own help
# (so it follows the options as they change): help2man over `glslrun --help`
# and `--version`, with the subcommands' help as a COMMANDS section.
#   cmake -DGLSLRUN=path/to/glslrun -DHELP2MAN=help2man -DOUTPUT=glslrun.1 -P man_page.cmake
set(include_file ${OUTPUT}.include)
set(text "[NAME]\nglslrun \\- legacy GLSL (1.10/1.20) on the CPU: render scenes, run piglit tests, trace shaders\n\n[COMMANDS]\n")
foreach(command test batch trace serve)
  execute_process(COMMAND ${GLSLRUN} ${command} --help OUTPUT_VARIABLE help ERROR_VARIABLE help
                  RESULT_VARIABLE result)
  if(result)
    message(FATAL_ERROR "${GLSLRUN} ${command} --help failed: ${help}")
  endif()
  # roff: backslashes are \e; a line may not start with . or '.
  string(REPLACE "\\" "\\e" help "${help}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" help "${help}")
  string(APPEND text ".SS \"glslrun ${command}\"\n.nf\n${help}\n.fi\n")
endforeach()
string(APPEND text "\n[SEE ALSO]\nThe documentation in the source tree: README.md, docs/scene-format.md,\ndocs/library.md, docs/ci.md, docs/debugging.md.\n")
file(WRITE ${include_file} "${text}")
execute_process(COMMAND ${HELP2MAN} --no-info --no-discard-stderr --section 1 --include ${include_file}
                        --output ${OUTPUT} ${GLSLRUN}
                RESULT_VARIABLE result ERROR_VARIABLE errors)
if(result)
  message(FATAL_ERROR "help2man failed: ${errors}")
endif()
