# Checks derivation files with the command line and keeps each report (lab 8, the documentation).
#
#   cmake -DIMPULSELAB=<impulselab> -DOUTPUT_DIR=<folder> -DFILES="<a.md>|<b.md>|..."
#         [-DFORMAT=markdown] [-DBASE_DIR=<folder>] -P check_derivations.cmake
#
# With BASE_DIR, each file is checked from that folder by its path relative to it, so that the
# report names it as a reader finds it in the repository (tutorials/derivations/…).
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
if(NOT DEFINED BASE_DIR)
  set(BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
endif()
foreach(file IN LISTS files)
  get_filename_component(name "${file}" NAME_WE)
  file(RELATIVE_PATH shown "${BASE_DIR}" "${file}")
  execute_process(
    COMMAND "${IMPULSELAB}" check "${shown}" --format "${FORMAT}" --output "${OUTPUT_DIR}/${name}.md"
    WORKING_DIRECTORY "${BASE_DIR}"
    RESULT_VARIABLE result
    ERROR_VARIABLE errors)
  if(NOT (result EQUAL 0 OR result EQUAL 1))
    message(FATAL_ERROR "impulselab check ${file} (exit ${result}):\n${errors}")
  endif()
endforeach()
