# The WebAssembly module (emscripten builds only; the `wasm` preset). The page calls the library
# through web/src/bindings.cpp alone: the scene reader (lib/scene_json), the solver, its reports and
# warnings (lib/) are compiled from their own sources, not copied.

# Headers from the machine that the module needs besides Eigen's, each through a folder of links
# of its own, so that /usr/include (the machine's C and C++ library) never enters a compilation
# for WebAssembly.
set(IMPULSELAB_HOST_INCLUDE_DIR "/usr/include"
    CACHE PATH "Where the header-only nlohmann-json is (Debian's package)")
set(web_include "${CMAKE_CURRENT_BINARY_DIR}/include")
file(MAKE_DIRECTORY "${web_include}")
foreach(dir IN ITEMS nlohmann)
  if(NOT EXISTS "${IMPULSELAB_HOST_INCLUDE_DIR}/${dir}")
    message(FATAL_ERROR "${IMPULSELAB_HOST_INCLUDE_DIR}/${dir} not found "
                        "(scripts/install-deps installs nlohmann-json3-dev)")
  endif()
  file(CREATE_LINK "${IMPULSELAB_HOST_INCLUDE_DIR}/${dir}" "${web_include}/${dir}" SYMBOLIC)
endforeach()

# The libc++ of Debian's emscripten (3.1.6) has no std::to_chars for double, which the library's
# messages use: the library is then compiled with a declaration of it forced in, and the module
# links its implementation (web/src/to_chars_shim.cpp).
include(CheckCXXSourceCompiles)
check_cxx_source_compiles([[
#include <charconv>
int main() { char text[32]; return std::to_chars(text, text + 32, 0.5).ptr == text ? 1 : 0; }
]] IMPULSELAB_HAVE_TO_CHARS_DOUBLE)
set(web_shims)
if(NOT IMPULSELAB_HAVE_TO_CHARS_DOUBLE)
  foreach(part IN ITEMS impulse_sections impulse)
    target_compile_options(${part} PRIVATE
      "SHELL:-include ${CMAKE_CURRENT_SOURCE_DIR}/src/to_chars_shim.hpp")
  endforeach()
  set(web_shims src/to_chars_shim.cpp)
endif()

# C++ exceptions carry every refusal of a scene (impulse::InvalidInput): the library must be
# compiled with them too, or a bad scene would abort the module. WebAssembly's own exceptions
# (Debian's emscripten has their libraries prebuilt, "-except"; every browser of the last years
# runs them): against emscripten's JavaScript exceptions (-fexceptions), the module is 18% smaller
# (764 against 937 KB) and a scene of 100 contacts solves 15 to 30% faster, since no call goes
# through a JavaScript trampoline.
target_compile_options(impulse_sections PRIVATE -fwasm-exceptions)
target_compile_options(impulse PRIVATE -fwasm-exceptions)

add_executable(impulselab_web
  src/bindings.cpp
  ${web_shims}
  ${PROJECT_SOURCE_DIR}/lib/scene_json/src/json.cpp)
set_target_properties(impulselab_web PROPERTIES
  OUTPUT_NAME impulselab-wasm
  SUFFIX ".js"
  RUNTIME_OUTPUT_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
target_include_directories(impulselab_web PRIVATE
  ${PROJECT_SOURCE_DIR}/lib/scene_json/include)
target_include_directories(impulselab_web SYSTEM PRIVATE "${web_include}")
target_link_libraries(impulselab_web PRIVATE ImpulseLab::impulse)
target_compile_options(impulselab_web PRIVATE -fwasm-exceptions)
# One classic script with the WebAssembly inside (SINGLE_FILE: no fetch, so it loads from
# file://), defining createImpulseLab(), which resolves to the module; no file system, memory
# that grows with the scene. The last four keep it within 1 MiB (web:size; web/README.md weighs
# them): a small allocator, and no loader code for options, eval or a missing TextDecoder.
target_link_options(impulselab_web PRIVATE
  -fwasm-exceptions
  --bind
  -sSINGLE_FILE=1
  -sMODULARIZE=1
  -sEXPORT_NAME=createImpulseLab
  -sENVIRONMENT=web,node
  -sALLOW_MEMORY_GROWTH=1
  -sFILESYSTEM=0
  -sMALLOC=emmalloc
  -sINCOMING_MODULE_JS_API=[]
  -sDYNAMIC_EXECUTION=0
  -sTEXTDECODER=2)
# Emscripten's JavaScript optimiser needs Debian's acorn (node-acorn, in /usr/share/nodejs),
# which a Node not installed from Debian does not look for.
if(IS_DIRECTORY "/usr/share/nodejs")
  set_target_properties(impulselab_web PROPERTIES CXX_LINKER_LAUNCHER
    "${CMAKE_COMMAND};-E;env;NODE_PATH=/usr/share/nodejs")
endif()

# The page, staged with the module into web/site/ of the build folder (the docs site copies that
# folder): the page itself, and the presets made from the scene files of the tutorials.
set(site_dir "${CMAKE_CURRENT_BINARY_DIR}/site")
# The page's files: web/page/ as it is (the html, the css, its scripts; page.cmake lists them for
# the docs site too).
include(${CMAKE_CURRENT_SOURCE_DIR}/cmake/page_files.cmake)
set(page_files ${IMPULSELAB_WEB_PAGE_FILES})
set(staged)
foreach(file IN LISTS page_files)
  add_custom_command(OUTPUT "${site_dir}/${file}"
    COMMAND "${CMAKE_COMMAND}" -E copy "${CMAKE_CURRENT_SOURCE_DIR}/page/${file}" "${site_dir}/${file}"
    DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/page/${file}"
    VERBATIM)
  list(APPEND staged "${site_dir}/${file}")
endforeach()
add_custom_command(OUTPUT "${site_dir}/impulselab-wasm.js"
  COMMAND "${CMAKE_COMMAND}" -E copy "$<TARGET_FILE:impulselab_web>" "${site_dir}/impulselab-wasm.js"
  DEPENDS impulselab_web
  VERBATIM)
list(APPEND staged "${site_dir}/impulselab-wasm.js")
file(GLOB preset_scenes CONFIGURE_DEPENDS
  "${PROJECT_SOURCE_DIR}/tutorials/scenes/*.json" "${PROJECT_SOURCE_DIR}/tutorials/[0-9]*/*.json")
add_custom_command(OUTPUT "${site_dir}/presets.js"
  COMMAND "${CMAKE_COMMAND}" "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
    "-DOUTPUT=${site_dir}/presets.js" -P "${CMAKE_CURRENT_SOURCE_DIR}/cmake/presets.cmake"
  DEPENDS ${preset_scenes} "${CMAKE_CURRENT_SOURCE_DIR}/cmake/presets.cmake"
    "${CMAKE_CURRENT_SOURCE_DIR}/presets.txt"
  VERBATIM)
list(APPEND staged "${site_dir}/presets.js")
add_custom_target(web ALL DEPENDS ${staged})
# MathJax beside the staged page, so that it also opens complete from the build folder (the docs
# site has its own copy).
set(IMPULSELAB_MATHJAX_DIR "/usr/share/javascript/mathjax"
    CACHE PATH "MathJax 2.7 (Debian's libjs-mathjax), linked beside the staged page")
if(EXISTS "${IMPULSELAB_MATHJAX_DIR}/MathJax.js")
  file(MAKE_DIRECTORY "${site_dir}")
  file(CREATE_LINK "${IMPULSELAB_MATHJAX_DIR}" "${site_dir}/mathjax" SYMBOLIC)
endif()

# The module in Node (no browser): it loads, solves and refuses as the library does; and it stays
# within its size budget.
find_program(IMPULSELAB_NODE node REQUIRED)
add_test(NAME web:module
  COMMAND "${IMPULSELAB_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/test/module_test.js"
    "$<TARGET_FILE:impulselab_web>")
add_test(NAME web:size
  COMMAND "${CMAKE_COMMAND}" "-DMODULE=$<TARGET_FILE:impulselab_web>" "-DLIMIT=1048576"
    -P "${CMAKE_CURRENT_SOURCE_DIR}/cmake/size_check.cmake")
set_tests_properties(web:module web:size PROPERTIES LABELS web)
