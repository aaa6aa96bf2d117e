# The derivation page's module (emscripten builds only; the wasm preset), impulselab-check.js: the
# checker of derivations/ compiled from its own target (ImpulseLab::checker, as derivations/
# defines it, every source of it) with GiNaC, CLN and GSL built for WebAssembly
# (web/cmake/checker_deps.cmake), behind one door, web/src/check_bindings.cpp. Included by
# web/CMakeLists.txt after module.cmake, whose compile settings of the library it shares.

# The checker throws C++ exceptions for every refusal of a file and catches GiNaC's (a division by
# zero in a step is a verdict, not a crash): WebAssembly's own exceptions, as for the library.
target_compile_options(impulselab_checker PRIVATE -fwasm-exceptions)
if(NOT IMPULSELAB_HAVE_TO_CHARS_DOUBLE)
  target_compile_options(impulselab_checker PRIVATE
    "SHELL:-include ${CMAKE_CURRENT_SOURCE_DIR}/src/to_chars_shim.hpp")
endif()

add_executable(impulselab_check_web src/check_bindings.cpp ${web_shims})
set_target_properties(impulselab_check_web PROPERTIES
  OUTPUT_NAME impulselab-check
  SUFFIX ".js"
  RUNTIME_OUTPUT_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
target_link_libraries(impulselab_check_web PRIVATE ImpulseLab::checker)
target_compile_options(impulselab_check_web PRIVATE -fwasm-exceptions)
# One classic script with the WebAssembly inside (SINGLE_FILE: it loads from file://) that defines
# createImpulseLabCheck(); in a page, a Web Worker or Node. The whole of emscripten's output is
# wrapped in one function, impulselabCheckModule (check/module_begin.js and module_end.js), whose
# text the page makes into its worker: a worker cannot be started from a file of a page opened
# from disk, but can from a Blob of text the page already holds.
set(module_begin "${CMAKE_CURRENT_SOURCE_DIR}/check/module_begin.js")
set(module_end "${CMAKE_CURRENT_SOURCE_DIR}/check/module_end.js")
target_link_options(impulselab_check_web PRIVATE
  -fwasm-exceptions
  --bind
  -sSINGLE_FILE=1
  -sMODULARIZE=1
  -sEXPORT_NAME=createImpulseLabCheck
  -sENVIRONMENT=web,worker,node
  -sALLOW_MEMORY_GROWTH=1
  -sFILESYSTEM=0
  "SHELL:--extern-pre-js ${module_begin}"
  "SHELL:--extern-post-js ${module_end}")
set_property(TARGET impulselab_check_web APPEND PROPERTY LINK_DEPENDS "${module_begin}" "${module_end}")
if(IS_DIRECTORY "/usr/share/nodejs")
  set_target_properties(impulselab_check_web PROPERTIES CXX_LINKER_LAUNCHER
    "${CMAKE_COMMAND};-E;env;NODE_PATH=/usr/share/nodejs")
endif()

# The page, staged with the module into web/site/ beside collide.html (check_files.cmake lists
# them for the docs site too): check.html, its script and style, the worker's script, what the
# interactive pages share (common/: the address's encoding of a file and downloads, files.js; the
# base style, page.css), and the examples of its menu (examples.js, written from the files).
include(${CMAKE_CURRENT_SOURCE_DIR}/cmake/check_files.cmake)
set(check_staged)
foreach(file IN LISTS IMPULSELAB_CHECK_PAGE_FILES)
  get_filename_component(name "${file}" NAME)
  add_custom_command(OUTPUT "${site_dir}/${name}"
    COMMAND "${CMAKE_COMMAND}" -E copy "${CMAKE_CURRENT_SOURCE_DIR}/${file}" "${site_dir}/${name}"
    DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/${file}"
    VERBATIM)
  list(APPEND check_staged "${site_dir}/${name}")
endforeach()
add_custom_command(OUTPUT "${site_dir}/impulselab-check.js"
  COMMAND "${CMAKE_COMMAND}" -E copy "$<TARGET_FILE:impulselab_check_web>" "${site_dir}/impulselab-check.js"
  DEPENDS impulselab_check_web
  VERBATIM)
list(APPEND check_staged "${site_dir}/impulselab-check.js")
# The menu's examples: the example derivations, the labs' derivation files and the paper's
# sections, each file's text as the command line reads it.
file(GLOB check_examples CONFIGURE_DEPENDS
  "${PROJECT_SOURCE_DIR}/tutorials/derivations/*.md"
  "${PROJECT_SOURCE_DIR}/tutorials/[0-9]*/derivations/*.md"
  "${PROJECT_SOURCE_DIR}/tutorials/[0-9]*/solutions/*.md"
  "${PROJECT_SOURCE_DIR}/derivations/paper/*.md")
find_program(IMPULSELAB_NODE node REQUIRED)
add_custom_command(OUTPUT "${site_dir}/examples.js"
  COMMAND "${IMPULSELAB_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/check/examples.mjs"
    "${site_dir}/examples.js" "${PROJECT_SOURCE_DIR}" ${check_examples}
  DEPENDS ${check_examples} "${CMAKE_CURRENT_SOURCE_DIR}/check/examples.mjs"
  VERBATIM)
list(APPEND check_staged "${site_dir}/examples.js")
add_custom_target(web_check ALL DEPENDS ${check_staged})
add_dependencies(web web_check)

# The module in Node (no browser): it loads, checks a derivation to the verdicts worked out by hand
# and refuses a malformed one with its place; and it stays within its size budget (8 MiB).
add_test(NAME web:check-module
  COMMAND "${IMPULSELAB_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/test/check_module_test.js"
    "$<TARGET_FILE:impulselab_check_web>")
add_test(NAME web:check-size
  COMMAND "${CMAKE_COMMAND}" "-DMODULE=$<TARGET_FILE:impulselab_check_web>" "-DLIMIT=8388608"
    -P "${CMAKE_CURRENT_SOURCE_DIR}/cmake/size_check.cmake")
set_tests_properties(web:check-module web:check-size PROPERTIES LABELS web)
