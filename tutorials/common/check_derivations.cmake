# Checks derivation files with the command line and keeps each report (lab 8, the documentation).
#
#   cmake -DIMPULSELAB=<impulselab> -DOUTPUT_DIR=<folder> -DFILES="<a.md>|<b.md>|..."
#         [-DFORMAT=markdown] -P check_derivations.cmake
#
# Writes <folder>/<name>.md for each file (its report). A derivation with a slip ends with exit
# status 1, which is its report's business, not a failure here; a file that cannot be read
# (status 2) fails the build with the checker's message.
foreach(var IN ITEMS IMPULSELAB OUTPUT_DIR FILES)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "check_derivations.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT DEFINED FORMAT)
  set(FORMAT markdown)
endif()
file(MAKE_DIRECTORY "${OUTPUT_DIR}")
string(REPLACE "|" ";" files "${FILES}")
foreach(file IN LISTS files)
  get_filename_component(name "${file}" NAME_WE)
  execute_process(
    COMMAND "${IMPULSELAB}" check "${file}" --format "${FORMAT}" --output "${OUTPUT_DIR}/${name}.md"
    RESULT_VARIABLE result
    ERROR_VARIABLE errors)
  if(NOT (result EQUAL 0 OR result EQUAL 1))
    message(FATAL_ERROR "impulselab check ${file} (exit ${result}):\n${errors}")
  endif()
endforeach()
