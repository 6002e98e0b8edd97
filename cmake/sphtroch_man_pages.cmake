# The tool's manual pages, written by help2man from its own help (run at build time):
#   sphtroch.1                 the top level (`sphtroch --help`, sections of sphtroch_man_include.h2m)
#   sphtroch-COMMAND.1         each command of `sphtroch --help` (`sphtroch COMMAND --help`)
#   sphtroch-COMMAND-SUB.1     each subcommand that a command lists (`sphtroch COMMAND SUB --help`)
# Each page's NAME line is the description `--help` gives the command; the footer carries
# "sphtroch VERSION" (--version-string: the tool's --version line lists its components, which is
# not a version). Called by src/cli/CMakeLists.txt:
#   cmake -DEXE=<tool> -DHELP2MAN=<help2man> -DINCLUDE=<sphtroch_man_include.h2m> -DVERSION=<x.y.z>
#         -DOUT_DIR=<share/man/man1> -DSTAMP=<file written last> -P sphtroch_man_pages.cmake
foreach(var EXE HELP2MAN INCLUDE VERSION OUT_DIR STAMP)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "sphtroch_man_pages.cmake: -D${var}=... is required")
  endif()
endforeach()
file(MAKE_DIRECTORY "${OUT_DIR}")
file(GLOB stale "${OUT_DIR}/sphtroch*.1")  # a command that is gone leaves no page behind
if(stale)
  file(REMOVE ${stale})
endif()

# subcommands(<help text> <out list>): the "name;description" pairs of a help's "Subcommands:" block.
function(subcommands help out)
  set(pairs)
  if(help MATCHES "\nSubcommands:\n(.*)$")
    string(REPLACE "\n" ";" lines "${CMAKE_MATCH_1}")
    foreach(line IN LISTS lines)
      if(line MATCHES "^  ([a-z][a-z0-9-]*)  +(.*)$")
        list(APPEND pairs "${CMAKE_MATCH_1}|${CMAKE_MATCH_2}")
      elseif(NOT line STREQUAL "")
        break()
      endif()
    endforeach()
  endif()
  set(${out} "${pairs}" PARENT_SCOPE)
endfunction()

# page(<words> <page name> <description> <include file>): help2man on `sphtroch WORDS --help`.
function(page words name description include)
  set(help_option "--help")
  if(words)
    string(REPLACE ";" " " help_option "${words} --help")
  endif()
  execute_process(COMMAND "${HELP2MAN}" --no-info --no-discard-stderr --name "${description}"
                          --help-option "${help_option}" --version-string "sphtroch ${VERSION}"
                          --include "${include}" --output "${OUT_DIR}/${name}.1" "${EXE}"
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "man page ${name}.1: help2man failed (${rc}): ${err}")
  endif()
  if(words)  # help2man names the page after the executable: the title and NAME become the page's own
    file(READ "${OUT_DIR}/${name}.1" text)
    string(TOUPPER "${name}" title)
    string(REPLACE "-" "\\-" name_roff "${name}")
    string(REPLACE "\n.TH SPHTROCH \"" "\n.TH ${title} \"" text "${text}")
    string(REPLACE "\n.SH NAME\nsphtroch \\-" "\n.SH NAME\n${name_roff} \\-" text "${text}")
    file(WRITE "${OUT_DIR}/${name}.1" "${text}")
  endif()
endfunction()

# The pages of the commands: a SEE ALSO of their own, naming the top-level page.
set(see_also "${OUT_DIR}/.see_also.h2m")
file(WRITE "${see_also}" "[SEE ALSO]\n\\fBsphtroch\\fR(1), and the manual of every command with examples: docs/cli.md of the source tree.\n")

page("" sphtroch "trajectories of spherical planetary gear trains (Lin & Tsai 1990)" "${INCLUDE}")
execute_process(COMMAND "${EXE}" --help OUTPUT_VARIABLE top)
subcommands("${top}" commands)
foreach(pair IN LISTS commands)
  string(REPLACE "|" ";" pair "${pair}")
  list(GET pair 0 command)
  list(GET pair 1 description)
  page("${command}" "sphtroch-${command}" "${description}" "${see_also}")
  execute_process(COMMAND "${EXE}" ${command} --help OUTPUT_VARIABLE help)
  subcommands("${help}" subs)
  foreach(sub_pair IN LISTS subs)
    string(REPLACE "|" ";" sub_pair "${sub_pair}")
    list(GET sub_pair 0 sub)
    list(GET sub_pair 1 sub_description)
    page("${command};${sub}" "sphtroch-${command}-${sub}" "${sub_description}" "${see_also}")
  endforeach()
endforeach()
file(REMOVE "${see_also}")
file(WRITE "${STAMP}" "")
