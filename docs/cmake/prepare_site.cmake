# Writes the Doxyfile of the site (run by the `docs` target with cmake -P, after
# `impulselab-site pages` has written the pages: docs/tools/site.cpp):
#
#  - for every preset of the interactive page, a Doxygen alias \tryit_ID (see below);
#  - docs/Doxyfile.in with the folders of the pages, of the labs' plots and of the menu filled in.
#
# Variables: SOURCE_DIR, BINARY_DIR (the build tree), DOCS_BINARY_DIR, REPORT_DIR,
# PROJECT_VERSION, HAVE_DOT.
cmake_minimum_required(VERSION 3.25)

foreach(var IN ITEMS SOURCE_DIR BINARY_DIR DOCS_BINARY_DIR REPORT_DIR PROJECT_VERSION HAVE_DOT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "prepare_site.cmake: ${var} is not set")
  endif()
endforeach()

# The labs' plots: each lab's programs write them to <build>/tutorials/NN-name/, which its
# worksheet shows by bare file name.
file(GLOB lab_dirs LIST_DIRECTORIES true "${SOURCE_DIR}/tutorials/[0-9][0-9]-*")
list(SORT lab_dirs)
set(image_dirs)
foreach(lab_dir IN LISTS lab_dirs)
  get_filename_component(lab_name "${lab_dir}" NAME)
  foreach(dir IN ITEMS "${lab_dir}" "${BINARY_DIR}/tutorials/${lab_name}")
    if(IS_DIRECTORY "${dir}")
      list(APPEND image_dirs "\"${dir}\"")
    endif()
  endforeach()
endforeach()

# --- "Try it": links to the interactive page with a scene filled in ------------------------------

# For every preset of the page (web/presets.txt), a Doxygen alias \tryit_ID (the scene file's
# name, - as _) that a page or a lab's worksheet writes where the reader should try the scene:
# a link to collide.html#scene= and the scene's JSON, compact and percent-encoded as
# encodeURIComponent writes it (the page's contract).
function(scene_fragment file out)
  file(READ "${file}" text)
  string(LENGTH "${text}" length)
  set(encoded "")
  set(in_string FALSE)
  set(escaped FALSE)
  math(EXPR last "${length} - 1")
  foreach(i RANGE ${last})
    string(SUBSTRING "${text}" ${i} 1 c)
    if(in_string)
      if(escaped)
        set(escaped FALSE)
      elseif(c STREQUAL "\\")
        set(escaped TRUE)
      elseif(c STREQUAL "\"")
        set(in_string FALSE)
      endif()
    elseif(c STREQUAL "\"")
      set(in_string TRUE)
    elseif(c MATCHES "^[ \t\r\n]$")
      continue()  # whitespace between tokens: the file's text, compact
    endif()
    if(c MATCHES "^[A-Za-z0-9_.!~*'()-]$")
      string(APPEND encoded "${c}")
    else()
      string(HEX "${c}" hex)
      string(TOUPPER "${hex}" hex)
      string(REGEX REPLACE "(..)" "%\\1" hex "${hex}")
      string(APPEND encoded "${hex}")
    endif()
  endforeach()
  set(${out} "${encoded}" PARENT_SCOPE)
endfunction()

set(DOCS_ALIASES "")
file(STRINGS "${SOURCE_DIR}/web/presets.txt" preset_lines ENCODING UTF-8)
foreach(line IN LISTS preset_lines)
  if(line MATCHES "^#" OR NOT line MATCHES "^[^|]+ \\| ([^|]+[^ |]) \\| ([^ |]+)$")
    continue()
  endif()
  set(label "${CMAKE_MATCH_1}")
  set(scene_file "${CMAKE_MATCH_2}")
  get_filename_component(id "${scene_file}" NAME_WE)
  string(REPLACE "-" "_" id "${id}")
  scene_fragment("${SOURCE_DIR}/${scene_file}" fragment)
  string(REPLACE "&" "&amp;" label "${label}")
  string(REPLACE "<" "&lt;" label "${label}")
  string(REPLACE "\"" "&quot;" label "${label}")
  string(APPEND DOCS_ALIASES
    "ALIASES += \"tryit_${id}=\\htmlonly<a class=\\\"tryit\\\" "
    "href=\\\"collide.html#scene=${fragment}\\\">Try it: ${label}</a>\\endhtmlonly\"\n")
endforeach()

# --- The Doxyfile -----------------------------------------------------------------------------

set(DOCS_PAGES "\"${DOCS_BINARY_DIR}/pages\" \"${REPORT_DIR}\"")
set(DOCS_TUTORIALS "")
if(IS_DIRECTORY "${DOCS_BINARY_DIR}/tutorials")
  set(DOCS_TUTORIALS "\"${DOCS_BINARY_DIR}/tutorials\"")
endif()
list(JOIN image_dirs " " DOCS_IMAGE_PATH)
set(DOCS_HAVE_DOT "${HAVE_DOT}")
configure_file("${SOURCE_DIR}/docs/Doxyfile.in" "${DOCS_BINARY_DIR}/Doxyfile" @ONLY)
