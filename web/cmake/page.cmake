# The page in a native build with the docs (the `docs` preset): the module comes from the `wasm`
# preset's build folder, configured and built on demand by the target web_module (emscripten is
# a cross-compiler: it cannot share this build); the docs site copies the page staged there. The
# browser tests (label web) run the page of the built site against this build's command line.
set(IMPULSELAB_WASM_DIR "${PROJECT_SOURCE_DIR}/build/wasm"
    CACHE PATH "The build folder of the wasm preset, whose web/site/ holds the page")
set(IMPULSELAB_WEB_SITE_DIR "${IMPULSELAB_WASM_DIR}/web/site" CACHE INTERNAL
    "The page staged by the wasm build, copied into the docs site")
# Its files, with the presets and the module the wasm build writes beside them.
include(${CMAKE_CURRENT_SOURCE_DIR}/cmake/page_files.cmake)
set(IMPULSELAB_WEB_SITE_FILES ${IMPULSELAB_WEB_PAGE_FILES} presets.js impulselab-wasm.js CACHE INTERNAL
    "The files of the staged page that the docs site copies")

add_custom_target(web_module
  COMMAND "${CMAKE_COMMAND}" "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}" "-DWASM_DIR=${IMPULSELAB_WASM_DIR}"
    -P "${CMAKE_CURRENT_SOURCE_DIR}/cmake/build_module.cmake"
  COMMENT "Building the WebAssembly module and the page (the wasm preset, ${IMPULSELAB_WASM_DIR})"
  VERBATIM)

if(IMPULSELAB_BUILD_TESTS AND IMPULSELAB_BUILD_DOCS AND TARGET impulselab)
  # Run after the docs are built (`cmake --build --preset docs && ctest --preset docs`); they need
  # Node and Debian's chromium (scripts/install-deps chromium emscripten); IMPULSELAB_CHROMIUM in
  # the environment names another browser. Screenshots go to screenshots/ here.
  find_program(IMPULSELAB_NODE node REQUIRED)
  # page_test.mjs: the page and its contract; bench_test.mjs: the page as a lab bench (the
  # motion, building on the canvas, side by side and the sweep, what readers found wrong; with
  # screenshots of the editor, the comparison and the sweep; serial collisions a slice per frame).
  foreach(test IN ITEMS page_test:presets page_test:scenes page_test:malformed page_test:interaction
                        page_test:links page_test:friction
                        bench_test:motion bench_test:editor bench_test:compare bench_test:defects
                        bench_test:slices)
    string(REPLACE ":" ";" parts "${test}")
    list(GET parts 0 program)
    list(GET parts 1 group)
    add_test(NAME web:${group}
      COMMAND "${IMPULSELAB_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/test/${program}.mjs" ${group}
        --site "${PROJECT_BINARY_DIR}/docs/html"
        --cli "$<TARGET_FILE:impulselab>"
        --source "${PROJECT_SOURCE_DIR}"
        --screenshots "${CMAKE_CURRENT_BINARY_DIR}/screenshots")
    set_tests_properties(web:${group} PROPERTIES LABELS web TIMEOUT 600)
  endforeach()
endif()
