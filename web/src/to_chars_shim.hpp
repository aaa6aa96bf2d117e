// SPDX-License-Identifier: GPL-3.0-or-later
// std::to_chars for double, which the libc++ of Debian's emscripten (3.1.6) lacks: forced into the
// library's compilation for WebAssembly (web/cmake/module.cmake) only when the check there finds
// it missing. impulse::format_number() writes the numbers of the library's messages with it.
#pragma once

#include <charconv>

namespace std {  // NOLINT(cert-dcl58-cpp): the declaration the standard library should have made

/// The shortest text that reads back as @p value, fixed or scientific, whichever is shorter
/// (fixed on a tie): what std::to_chars(first, last, value) writes (C++17 [charconv.to.chars]).
/// @param first where the text starts
/// @param last one past the end of the room for it
/// @param value the number
/// @return one past the text's end, or {last, errc::value_too_large} when it does not fit
to_chars_result to_chars(char* first, char* last, double value);

}  // namespace std
