# Writes foldkit.1 and foldkit.1.gz with help2man: the program's own --help, one subsection per subcommand with that
# subcommand's --help, and the hand-written sections of foldkit.h2m. Run at build time (cmake -P) so the
# page always says what the built program accepts.
#   cmake -DFOLDKIT=<exe> -DHELP2MAN=<help2man> -DVERSION=<x.y.z> -DSTATIC_INCLUDE=<foldkit.h2m>
#         -DOUT=<foldkit.1> -P man_page.cmake
foreach(var FOLDKIT HELP2MAN VERSION STATIC_INCLUDE OUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "man_page.cmake: ${var} not set")
  endif()
endforeach()

function(help_of out)
  execute_process(COMMAND ${FOLDKIT} ${ARGN} --help OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "man_page.cmake: '${FOLDKIT} ${ARGN} --help' failed (${rc})")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# roff takes a backslash as an escape and a line starting with . or ' as a request.
function(roff_literal out text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

help_of(main_help)
string(REGEX REPLACE ".*\nSubcommands:\n" "" listing "${main_help}")
string(REGEX MATCHALL "(^|\n)  [a-z][a-z0-9-]*" names "${listing}")

set(commands "[COMMANDS]\n")
foreach(name ${names})
  string(STRIP "${name}" name)
  help_of(sub_help ${name})
  # The usage line shows how the program was called here (its build path): name it as a user types it.
  string(REGEX REPLACE "Usage: [^ \n]*foldkit" "Usage: foldkit" sub_help "${sub_help}")
  roff_literal(sub_help "${sub_help}")
  string(APPEND commands ".SS \"foldkit ${name}\"\n.nf\n${sub_help}.fi\n")
endforeach()

get_filename_component(work ${OUT} DIRECTORY)
set(commands_file ${work}/foldkit-commands.h2m)
file(WRITE ${commands_file} "${commands}")
execute_process(
  COMMAND ${HELP2MAN} --no-info --section=1 --manual "User Commands" --source "foldkit ${VERSION}"
          --version-string=${VERSION} --name "unfold 3D meshes into papercraft sheets and cutter jobs"
          --include=${STATIC_INCLUDE} --include=${commands_file} --output=${OUT}.tmp ${FOLDKIT}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "man_page.cmake: help2man failed (${rc})")
endif()
file(RENAME ${OUT}.tmp ${OUT})
# -n: no name or time stamp inside, so an unchanged page gives the same bytes.
execute_process(COMMAND gzip -9 -n -c ${OUT} OUTPUT_FILE ${OUT}.gz.tmp RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "man_page.cmake: gzip failed (${rc})")
endif()
file(RENAME ${OUT}.gz.tmp ${OUT}.gz)
