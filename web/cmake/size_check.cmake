# The size budget of the page's module (test web:size): the WebAssembly and its loader, one file,
# at most LIMIT bytes. Variables: MODULE (the file), LIMIT.
file(SIZE "${MODULE}" size)
math(EXPR kib "${size} / 1024")
message(STATUS "${MODULE}: ${size} bytes (${kib} KiB), budget ${LIMIT} bytes")
if(size GREATER LIMIT)
  message(FATAL_ERROR "the module is larger than its budget of ${LIMIT} bytes")
endif()
