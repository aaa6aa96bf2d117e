# The checker's libraries in an emscripten build (the wasm preset), found before derivations/ is
# added, so that its own find_package and pkg_check_modules calls find the WebAssembly builds of
# GiNaC, CLN and GSL that scripts/build-wasm-deps keeps in its cache (outside the source tree),
# and never the machine's: derivations/CMakeLists.txt is the same for both builds.
#
# IMPULSELAB_WASM_DEPS_PREFIX names another folder holding include/ and lib/ of the three; by
# default the script names its folder for the versions installed.
set(IMPULSELAB_WASM_DEPS_PREFIX "" CACHE PATH
    "GiNaC, CLN and GSL built for WebAssembly (default: the folder scripts/build-wasm-deps names)")
set(wasm_deps_script "${PROJECT_SOURCE_DIR}/scripts/build-wasm-deps")
if(IMPULSELAB_WASM_DEPS_PREFIX)
  set(wasm_deps "${IMPULSELAB_WASM_DEPS_PREFIX}")
else()
  # The folder's name holds a digest of the script and of web/deps/: configure again when they
  # change, so that a changed patch is never built against the libraries of the old one.
  file(GLOB_RECURSE wasm_deps_recipe "${PROJECT_SOURCE_DIR}/web/deps/*")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
               "${wasm_deps_script}" ${wasm_deps_recipe})
  execute_process(COMMAND "${wasm_deps_script}" --prefix
    OUTPUT_VARIABLE wasm_deps OUTPUT_STRIP_TRAILING_WHITESPACE
    ERROR_VARIABLE wasm_deps_error RESULT_VARIABLE wasm_deps_status)
  if(NOT wasm_deps_status EQUAL 0)
    message(FATAL_ERROR "The derivation page's module needs GiNaC, CLN and GSL built for "
                        "WebAssembly, which are not built yet: run scripts/build-wasm-deps (once "
                        "per machine, some 15 minutes of processor time, web/README.md; its cache "
                        "serves every later build). ${wasm_deps_error}"
                        "Expected in: ${wasm_deps}")
  endif()
endif()
foreach(file IN ITEMS include/ginac/ginac.h include/cln/cln.h include/gsl/gsl_math.h
                      lib/libginac.a lib/libcln.a lib/libgsl.a lib/pkgconfig/ginac.pc)
  if(NOT EXISTS "${wasm_deps}/${file}")
    message(FATAL_ERROR "${wasm_deps}/${file} not found: not a build of scripts/build-wasm-deps")
  endif()
endforeach()
message(STATUS "GiNaC, CLN and GSL for WebAssembly: ${wasm_deps}")
# A build folder configured before with another folder (another version, a changed recipe)
# forgets what it found there: find_library and pkg-config keep their answers in the cache.
if(DEFINED CACHE{IMPULSELAB_WASM_DEPS_USED} AND NOT IMPULSELAB_WASM_DEPS_USED STREQUAL wasm_deps)
  get_cmake_property(cached CACHE_VARIABLES)
  foreach(var IN LISTS cached)
    if(var MATCHES "^(GSL_|pkgcfg_lib_GINAC_|__pkg_config_checked_GINAC$)")
      unset(${var} CACHE)
    endif()
  endforeach()
endif()
set(IMPULSELAB_WASM_DEPS_USED "${wasm_deps}" CACHE INTERNAL "The folder the libraries were found in")

# Emscripten's toolchain searches its own sysroot only; the folder joins it.
list(APPEND CMAKE_FIND_ROOT_PATH "${wasm_deps}")
# pkg-config (GiNaC and CLN): their .pc files only, never the machine's.
set(ENV{PKG_CONFIG_LIBDIR} "${wasm_deps}/lib/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "")
# FindGSL.
set(GSL_ROOT_DIR "${wasm_deps}")
# nlohmann-json is header-only: its package is defined here through a folder of links that holds
# it alone, so that /usr/include (the machine's C and C++ library, which its own package config
# would name) never enters a compilation for WebAssembly.
set(nlohmann_json_DIR "${CMAKE_CURRENT_LIST_DIR}/nlohmann_json" CACHE PATH
    "nlohmann-json for the WebAssembly build (web/cmake/nlohmann_json)" FORCE)
