# impulselab_warnings: an interface target every ImpulseLab target links privately.
# It is not exported: consumers of the installed library never inherit these flags.
add_library(impulselab_warnings INTERFACE)
target_compile_options(impulselab_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion
  -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual
  -Wnull-dereference -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
# GCC 12's -Wrestrict reports overlapping copies inside libstdc++'s own string concatenation
# ("a" + std::string) that cannot happen (GCC bug 105329); which translation units it hits
# depends on inlining alone. The warning is off for GCC 12 and on elsewhere.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_GREATER_EQUAL 12
   AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(impulselab_warnings INTERFACE -Wno-restrict)
endif()
if(IMPULSELAB_WARNINGS_AS_ERRORS)
  target_compile_options(impulselab_warnings INTERFACE -Werror)
endif()
if(IMPULSELAB_SANITIZE)
  target_compile_options(impulselab_warnings INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(impulselab_warnings INTERFACE -fsanitize=address,undefined)
endif()
if(IMPULSELAB_BUILD_FUZZ)
  # Coverage feedback for libFuzzer in every ImpulseLab target; the harness links the fuzzer's
  # main (fuzz/CMakeLists.txt).
  target_compile_options(impulselab_warnings INTERFACE -fsanitize=fuzzer-no-link)
endif()
