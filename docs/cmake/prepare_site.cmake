# Prepares the Doxygen input of the site (run by the `docs` target with cmake -P):
#
#  - docs/pages/*.md are copied to <build>/docs/pages with their placeholders filled in from the
#    checker's JSON report, so that each check's outcome comes from the run, never from the page:
#      {{check:ID}}    a block under an equation: the verdict linked to the report entry, the
#                      methods, and the corrected form (erratum) or the counterexample (refuted)
#      {{verdict:ID}}  the verdict alone, linked, for a sentence or a table cell
#      {{statement:ID}}  the check's statement as the checker read it from its paper file
#                      (derivations/paper/sectionN.md, or derivations/beyond/NAME.md for the
#                      checks beyond the paper), as a display: the page's copy of the
#                      equation is the file's, never a third one
#      {{errata}}      every erratum and refuted claim of the paper's checks, with its correction
#                      or counterexample (the checks beyond the paper are not the paper's errata)
#      {{labs}}        the labs found in tutorials/NN-name/README.md
#      {{summary}}     the counts of each outcome ("65 verified, 13 errata, ...")
#      {{derivation:NAME}}  the example derivation tutorials/derivations/NAME.md as written (a
#                      code block), then its report as `impulselab check --format markdown`
#                      wrote it during the build (math turned into Doxygen's \f$ … \f$)
#    Every check of the report must appear on some page, and every ID on a page in the report.
#  - the Doxyfile is written from docs/Doxyfile.in, with the labs' folders as images folders.
#
# Variables: SOURCE_DIR, BINARY_DIR (the build tree), DOCS_BINARY_DIR, REPORT_JSON,
# PROJECT_VERSION, HAVE_DOT.
cmake_minimum_required(VERSION 3.25)

foreach(var IN ITEMS SOURCE_DIR BINARY_DIR DOCS_BINARY_DIR REPORT_JSON PROJECT_VERSION HAVE_DOT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "prepare_site.cmake: ${var} is not set")
  endif()
endforeach()

set(pages_out "${DOCS_BINARY_DIR}/pages")
file(REMOVE_RECURSE "${pages_out}")
file(MAKE_DIRECTORY "${pages_out}")

# --- The report: one snippet and one verdict per check -------------------------------------------

file(READ "${REPORT_JSON}" report)
get_filename_component(report_dir "${REPORT_JSON}" DIRECTORY)
file(STRINGS "${report_dir}/check_report.md" report_headings REGEX "^####? ")

# The anchor of each check is the one the markdown report gives its heading ("### eq-3.5 (3.5)
# {#check-eq-3-5}"; one level deeper beyond the paper), so that a link cannot point beside its
# entry.
function(report_anchor id out)
  foreach(heading IN LISTS report_headings)
    if(heading MATCHES "^####? ([^ ]+) .*\\{#([^}]+)\\}$" AND CMAKE_MATCH_1 STREQUAL id)
      set(${out} "${CMAKE_MATCH_2}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "prepare_site.cmake: check ${id} has no heading in the markdown report")
endfunction()

# An optional string member of a check ("" when absent or null).
function(member check name out)
  string(JSON type ERROR_VARIABLE error TYPE "${check}" ${name})
  if(error OR NOT type STREQUAL "STRING")
    set(${out} "" PARENT_SCOPE)
  else()
    string(JSON value GET "${check}" ${name})
    set(${out} "${value}" PARENT_SCOPE)
  endif()
endfunction()

set(all_ids)
set(errata_list)
# The paper's checks, then those beyond the paper ("beyond_the_paper": placeholders too, but not
# in the paper's errata).
set(parts paper)
string(JSON beyond_type ERROR_VARIABLE no_beyond TYPE "${report}" beyond_the_paper)
if(NOT no_beyond)
  list(APPEND parts beyond)
endif()
foreach(part IN LISTS parts)
  if(part STREQUAL "paper")
    set(path checks)
  else()
    set(path beyond_the_paper checks)
  endif()
  string(JSON count LENGTH "${report}" ${path})
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON check GET "${report}" ${path} ${i})
    string(JSON id GET "${check}" id)
    string(JSON status GET "${check}" status)
    string(JSON kind GET "${check}" kind)
    string(JSON section GET "${check}" section)
    member("${check}" equation equation)
    member("${check}" display display)
    member("${check}" correction correction)
    member("${check}" counterexample counterexample)
    member("${check}" explanation explanation)
    string(JSON method_count LENGTH "${check}" methods)
    set(methods "")
    if(method_count GREATER 0)
      math(EXPR last_method "${method_count} - 1")
      foreach(m RANGE ${last_method})
        string(JSON method GET "${check}" methods ${m})
        if(NOT methods STREQUAL "")
          string(APPEND methods ", ")
        endif()
        string(APPEND methods "${method}")
      endforeach()
    endif()
    report_anchor("${id}" anchor)
    list(APPEND all_ids "${id}")

    set(label "${id}")
    if(NOT equation STREQUAL "")
      set(label "${equation}")
    endif()
    set(verdict_${id} "<span class=\"verdict ${status}\">\\ref ${anchor} \"${status}\"</span>")
    # The statement as the checker read it (derivations/paper/sectionN.md), arranged for MathJax
    # by the checker itself (the report's "display": tag at the end, labels gone, rows gathered).
    set(statement_${id} "\\f[ ${display} \\f]")
    string(CONCAT block "<div class=\"check ${status}\">\n<b>Check</b> <code>${id}</code> (${kind}): "
                       "${verdict_${id}} by ${methods}.")
    if(NOT correction STREQUAL "")
      string(APPEND block " What holds instead:\n\\f[ ${correction} \\f]\n")
    endif()
    if(NOT counterexample STREQUAL "")
      string(APPEND block " Counterexample: ${counterexample}\n")
    endif()
    string(APPEND block "</div>")
    set(check_${id} "${block}")

    if(part STREQUAL "paper" AND (status STREQUAL "erratum" OR status STREQUAL "refuted"))
      string(APPEND errata_list
        "\n### ${label}, section ${section}: ${status}\n\n"
        "As printed (check \\ref ${anchor} \"${id}\", kind: ${kind}):\n\n\\f[ ${display} \\f]\n\n"
        "What goes wrong: ${explanation}\n\n")
      if(NOT correction STREQUAL "")
        string(APPEND errata_list "What holds instead:\n\n\\f[ ${correction} \\f]\n")
      endif()
      if(NOT counterexample STREQUAL "")
        string(APPEND errata_list "Counterexample: ${counterexample}\n")
      endif()
    elseif(status STREQUAL "failed")
      message(FATAL_ERROR "prepare_site.cmake: check ${id} failed; the site shows no failed check")
    endif()
  endforeach()
endforeach()
string(JSON verified GET "${report}" summary verified)
string(JSON errata GET "${report}" summary erratum)
string(JSON refuted GET "${report}" summary refuted)
string(JSON failed GET "${report}" summary failed)
set(summary "${verified} verified, ${errata} errata, ${refuted} refuted, ${failed} failed")

if(errata_list STREQUAL "")
  set(errata_list "The checker found no erratum and no refuted claim.\n")
endif()

# --- The labs ---------------------------------------------------------------------------------

# Each lab is tutorials/NN-name/README.md whose first line is "# Lab N: Title {#lab_N}"; its
# programs write their plots to <build>/tutorials/NN-name/, which the worksheet shows by bare
# file name.
file(GLOB lab_readmes "${SOURCE_DIR}/tutorials/[0-9][0-9]-*/README.md")
list(SORT lab_readmes)
set(labs_list)
set(image_dirs)
foreach(readme IN LISTS lab_readmes)
  file(STRINGS "${readme}" first_line LIMIT_COUNT 1)
  if(NOT first_line MATCHES "^# Lab ([0-9]+): (.+) \\{#(lab_[0-9]+)\\}$")
    message(FATAL_ERROR "${readme}: the first line must read \"# Lab N: Title {#lab_N}\", "
                        "got \"${first_line}\"")
  endif()
  string(APPEND labs_list "- \\subpage ${CMAKE_MATCH_3} \"Lab ${CMAKE_MATCH_1}: ${CMAKE_MATCH_2}\"\n")
  get_filename_component(lab_dir "${readme}" DIRECTORY)
  get_filename_component(lab_name "${lab_dir}" NAME)
  foreach(dir IN ITEMS "${lab_dir}" "${BINARY_DIR}/tutorials/${lab_name}")
    if(IS_DIRECTORY "${dir}")
      list(APPEND image_dirs "\"${dir}\"")
    endif()
  endforeach()
endforeach()
if(labs_list STREQUAL "")
  string(CONCAT labs_list "No lab has been written yet. Each lab will be listed here as soon as "
                          "its folder `tutorials/NN-name/` exists.\n")
endif()

# --- The pages --------------------------------------------------------------------------------

# tutorials/README.md becomes the labs index once it carries the label {#labs}; until then
# docs/pages/labs.md is the index.
set(labs_index_in_tutorials FALSE)
if(EXISTS "${SOURCE_DIR}/tutorials/README.md")
  file(STRINGS "${SOURCE_DIR}/tutorials/README.md" labs_label REGEX "\\{#labs\\}")
  if(NOT labs_label STREQUAL "")
    set(labs_index_in_tutorials TRUE)
  endif()
endif()

file(GLOB pages "${SOURCE_DIR}/docs/pages/*.md")
set(used_ids)
foreach(page IN LISTS pages)
  get_filename_component(name "${page}" NAME)
  if(name STREQUAL "labs.md" AND labs_index_in_tutorials)
    continue()
  endif()
  file(READ "${page}" text)
  # All placeholders are taken from the page as written, so that text put in (a statement in
  # LaTeX, say) is never read as one.
  string(REGEX MATCHALL "{{[a-z]+(:[^}]*)?}}" placeholders "${text}")
  list(REMOVE_DUPLICATES placeholders)
  foreach(placeholder IN LISTS placeholders)
    string(REGEX MATCH "^{{([a-z]+)(:(.*))?}}$" parts "${placeholder}")
    set(what "${CMAKE_MATCH_1}")
    set(id "${CMAKE_MATCH_3}")
    if((what STREQUAL "check" OR what STREQUAL "verdict" OR what STREQUAL "statement")
       AND DEFINED ${what}_${id})
      set(replacement "${${what}_${id}}")
      list(APPEND used_ids "${id}")
    elseif(what STREQUAL "errata" AND id STREQUAL "")
      set(replacement "${errata_list}")
    elseif(what STREQUAL "labs" AND id STREQUAL "")
      set(replacement "${labs_list}")
    elseif(what STREQUAL "summary" AND id STREQUAL "")
      set(replacement "${summary}")
    elseif(what STREQUAL "derivation" AND EXISTS "${SOURCE_DIR}/tutorials/derivations/${id}.md"
           AND EXISTS "${DOCS_BINARY_DIR}/derivation-reports/${id}.md")
      file(READ "${SOURCE_DIR}/tutorials/derivations/${id}.md" source)
      string(FIND "${source}" "<!-- expect" pins)  # the test's pins are not for readers
      if(pins GREATER -1)
        string(SUBSTRING "${source}" 0 ${pins} source)
      endif()
      string(STRIP "${source}" source)
      file(READ "${DOCS_BINARY_DIR}/derivation-reports/${id}.md" checked)
      string(REGEX REPLACE "\\$([^$]+)\\$" "\\\\f$\\1\\\\f$" checked "${checked}")
      # \verbatim (a <pre> in the page): neither Doxygen's commands nor MathJax's $$ are read
      # inside it, so the file shows as written.
      string(CONCAT replacement "The file `tutorials/derivations/${id}.md`:\n\n\\verbatim\n"
                                "${source}\n\\endverbatim\n\nWhat `impulselab check` reports "
                                "for it:\n\n${checked}\n")
    else()
      message(FATAL_ERROR "${page}: ${placeholder} names no check of the report (or no "
                          "placeholder: {{check:ID}}, {{verdict:ID}}, {{statement:ID}}, {{errata}}, {{labs}}, "
                          "{{summary}}, {{derivation:NAME}})")
    endif()
    string(REPLACE "${placeholder}" "${replacement}" text "${text}")
  endforeach()
  file(WRITE "${pages_out}/${name}" "${text}")
endforeach()

set(missing ${all_ids})
if(used_ids)
  list(REMOVE_ITEM missing ${used_ids})
endif()
if(missing)
  list(JOIN missing ", " missing)
  message(FATAL_ERROR "prepare_site.cmake: no page of docs/pages shows these checks: ${missing}")
endif()

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

set(DOCS_PAGES "\"${pages_out}\" \"${report_dir}\"")
set(DOCS_TUTORIALS "")
if(IS_DIRECTORY "${SOURCE_DIR}/tutorials")
  set(DOCS_TUTORIALS "\"${SOURCE_DIR}/tutorials\"")
endif()
list(JOIN image_dirs " " DOCS_IMAGE_PATH)
set(DOCS_HAVE_DOT "${HAVE_DOT}")
configure_file("${SOURCE_DIR}/docs/Doxyfile.in" "${DOCS_BINARY_DIR}/Doxyfile" @ONLY)
