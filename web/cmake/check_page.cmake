# The derivation page's browser tests in a native build with the docs (the `docs` preset): the
# page of the built site (its module from the wasm preset's build folder, web/cmake/checker.cmake)
# against the command line built here, in headless Chromium (label web; web/test/check_test.mjs).
if(IMPULSELAB_BUILD_TESTS AND IMPULSELAB_BUILD_DOCS AND TARGET impulselab)
  find_program(IMPULSELAB_NODE node REQUIRED)
  foreach(group IN ITEMS files examples editing server links)
    add_test(NAME web:check-${group}
      COMMAND "${IMPULSELAB_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/test/check_test.mjs" ${group}
        --site "${PROJECT_BINARY_DIR}/docs/html"
        --cli "$<TARGET_FILE:impulselab>"
        --source "${PROJECT_SOURCE_DIR}")
    set_tests_properties(web:check-${group} PROPERTIES LABELS web TIMEOUT 900)
  endforeach()
endif()
