# Writes the presets of the interactive page (run by the `web` target with cmake -P): every scene
# listed in web/presets.txt, its text as the command line reads it, into one script that defines
# window.impulselabPresets. Refuses a list that leaves out a scene of tutorials/scenes/ or of a
# lab, that names a file twice or a file that does not exist.
#
# Variables: SOURCE_DIR (the repository), OUTPUT (the script to write).
cmake_minimum_required(VERSION 3.25)
foreach(var IN ITEMS SOURCE_DIR OUTPUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "presets.cmake: ${var} is not set")
  endif()
endforeach()

set(list_file "${SOURCE_DIR}/web/presets.txt")
file(STRINGS "${list_file}" lines ENCODING UTF-8)

# A JavaScript string literal of @p text (the labels hold no line breaks).
function(js_string text out)
  string(REPLACE "\\" "\\\\" text "${text}")
  string(REPLACE "\"" "\\\"" text "${text}")
  set(${out} "\"${text}\"" PARENT_SCOPE)
endfunction()

set(entries)
set(listed)
set(ids)
foreach(line IN LISTS lines)
  if(line MATCHES "^#" OR line STREQUAL "")
    continue()
  endif()
  if(NOT line MATCHES "^([^|]+[^ |]) \\| ([^|]+[^ |]) \\| ([^ |]+)$")
    message(FATAL_ERROR "${list_file}: expected \"group | label | file\", got \"${line}\"")
  endif()
  set(group "${CMAKE_MATCH_1}")
  set(label "${CMAKE_MATCH_2}")
  set(file "${CMAKE_MATCH_3}")
  if(NOT EXISTS "${SOURCE_DIR}/${file}")
    message(FATAL_ERROR "${list_file}: ${file} does not exist")
  endif()
  if(file IN_LIST listed)
    message(FATAL_ERROR "${list_file}: ${file} is listed twice")
  endif()
  list(APPEND listed "${file}")
  get_filename_component(id "${file}" NAME_WE)
  if(id IN_LIST ids)
    message(FATAL_ERROR "${list_file}: two scenes are named ${id}")
  endif()
  list(APPEND ids "${id}")
  file(READ "${SOURCE_DIR}/${file}" scene)
  string(JSON ignored ERROR_VARIABLE error TYPE "${scene}")
  if(error)
    message(FATAL_ERROR "${file}: not JSON: ${error}")
  endif()
  string(STRIP "${scene}" scene)
  js_string("${group}" group)
  js_string("${label}" label)
  string(APPEND entries
    "  {\"id\": \"${id}\", \"group\": ${group}, \"label\": ${label}, \"file\": \"${file}\",\n"
    "   \"scene\": ${scene}},\n")
endforeach()

file(GLOB scenes RELATIVE "${SOURCE_DIR}"
  "${SOURCE_DIR}/tutorials/scenes/*.json" "${SOURCE_DIR}/tutorials/[0-9]*/*.json")
foreach(file IN LISTS scenes)
  if(NOT file IN_LIST listed)
    message(FATAL_ERROR "${list_file}: ${file} is not listed; every scene of the tutorials is a "
                        "preset of the page")
  endif()
endforeach()

file(WRITE "${OUTPUT}.tmp"
  "// Generated from web/presets.txt by web/cmake/presets.cmake: the scenes as their files hold "
  "them.\nwindow.impulselabPresets = [\n${entries}];\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
