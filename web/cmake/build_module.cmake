# Configures (once) and builds the wasm preset's build folder: the WebAssembly module and the page
# staged beside it (run by the target web_module with cmake -P).
# Variables: SOURCE_DIR (the repository), WASM_DIR (the build folder).
cmake_minimum_required(VERSION 3.25)
find_program(emcc emcc)
if(NOT emcc)
  message(FATAL_ERROR "The page needs Debian's emscripten (emcc not found): "
                      "scripts/install-deps emscripten")
endif()
if(NOT EXISTS "${WASM_DIR}/CMakeCache.txt")
  execute_process(COMMAND "${CMAKE_COMMAND}" --preset wasm -B "${WASM_DIR}"
    WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "configuring ${WASM_DIR} (cmake --preset wasm) failed")
  endif()
endif()
# A build of its own (the outer make's job server does not reach a command's children), on the
# machine's two cores.
execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=MAKEFLAGS --unset=MFLAGS --unset=MAKELEVEL
    "${CMAKE_COMMAND}" --build "${WASM_DIR}" --target web --parallel 2
  WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "building ${WASM_DIR} (the wasm preset) failed")
endif()
