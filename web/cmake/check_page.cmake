# The derivation page in a native build with the docs (the `docs` preset): its files, staged by
# the wasm build (web/cmake/checker.cmake), join those the docs site copies (page.cmake); its
# browser tests run the page of the built site against the command line built here, in headless
# Chromium (label web; web/test/check_test.mjs).
include(${CMAKE_CURRENT_SOURCE_DIR}/cmake/check_files.cmake)
set(IMPULSELAB_WEB_SITE_FILES ${IMPULSELAB_WEB_SITE_FILES} ${IMPULSELAB_CHECK_SITE_FILES}
    CACHE INTERNAL "The files of the staged pages that the docs site copies")
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
