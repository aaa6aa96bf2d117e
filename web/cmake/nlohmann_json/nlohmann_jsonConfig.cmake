# nlohmann-json (header-only, Debian's nlohmann-json3-dev) for the WebAssembly build: the package
# config find_package(nlohmann_json) reads there (web/cmake/checker_deps.cmake points at it). The
# target's include folder is a folder of links that holds nlohmann/ alone, so that /usr/include
# (the machine's C and C++ library, which Debian's own config of the package names) never enters
# a compilation for WebAssembly.
if(NOT TARGET nlohmann_json::nlohmann_json)
  set(IMPULSELAB_HOST_INCLUDE_DIR "/usr/include"
      CACHE PATH "Where the header-only nlohmann-json is (Debian's package)")
  set(_links "${CMAKE_BINARY_DIR}/wasm-include/nlohmann_json")
  file(MAKE_DIRECTORY "${_links}")
  file(CREATE_LINK "${IMPULSELAB_HOST_INCLUDE_DIR}/nlohmann" "${_links}/nlohmann" SYMBOLIC)
  add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
  set_target_properties(nlohmann_json::nlohmann_json PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${_links}")
  unset(_links)
endif()
