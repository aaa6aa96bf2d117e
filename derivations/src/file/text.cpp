// SPDX-License-Identifier: GPL-3.0-or-later
#include "file/text.hpp"

#include <algorithm>
#include <cstdio>

namespace impulse::derivations::file {

namespace {

std::string hex_byte(unsigned char byte) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "0x%02X", static_cast<unsigned>(byte));
  return buffer;
}

// The length of the UTF-8 sequence that starts at text[i], or 0 when it is not well formed
// (overlong forms, surrogates and code points above U+10FFFF are refused too).
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[i + k]); };
  const unsigned char lead = byte(0);
  const auto continuation = [&](std::size_t k) {
    return i + k < text.size() && (byte(k) & 0xC0U) == 0x80U;
  };
  if (lead < 0x80U) {
    return 1;
  }
  if (lead >= 0xC2U && lead <= 0xDFU) {
    return continuation(1) ? 2 : 0;
  }
  if (lead >= 0xE0U && lead <= 0xEFU) {
    if (!continuation(1) || !continuation(2)) {
      return 0;
    }
    const unsigned char second = byte(1);
    if ((lead == 0xE0U && second < 0xA0U) || (lead == 0xEDU && second >= 0xA0U)) {
      return 0;
    }
    return 3;
  }
  if (lead >= 0xF0U && lead <= 0xF4U) {
    if (!continuation(1) || !continuation(2) || !continuation(3)) {
      return 0;
    }
    const unsigned char second = byte(1);
    if ((lead == 0xF0U && second < 0x90U) || (lead == 0xF4U && second >= 0x90U)) {
      return 0;
    }
    return 4;
  }
  return 0;
}

}  // namespace

std::string trimmed(std::string_view s) {
  constexpr std::string_view space = " \t\r\n";
  const std::size_t first = s.find_first_not_of(space);
  return first == std::string_view::npos
             ? std::string()
             : std::string(s.substr(first, s.find_last_not_of(space) + 1 - first));
}

Source::Source(std::string text, const Limits& limits) : text_(std::move(text)) {
  line_starts_.push_back(0);
  if (text_.size() > limits.bytes) {
    throw ReadError({1, 1}, "expected a derivation file of at most " +
                                std::to_string(limits.bytes >> 20) + " MiB, this one holds " +
                                std::to_string(text_.size()) + " bytes or more");
  }
  for (std::size_t i = 0; i < text_.size();) {
    const auto byte = static_cast<unsigned char>(text_[i]);
    if (byte == '\n') {
      line_starts_.push_back(i + 1);
      ++i;
      continue;
    }
    if (byte < 0x20U && byte != '\t' && byte != '\r') {
      throw error(i, "expected text, found the control byte " + hex_byte(byte) +
                         (byte == 0 ? " (NUL): is this a binary file?" : ""));
    }
    const std::size_t length = utf8_length(text_, i);
    if (length == 0) {
      throw error(i, "expected UTF-8 text, found the byte " + hex_byte(byte) +
                         " that starts no UTF-8 character: is this a binary file?");
    }
    i += length;
  }
}

Place Source::place(std::size_t offset) const {
  offset = std::min(offset, text_.size());
  const auto after = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const std::size_t line = static_cast<std::size_t>(after - line_starts_.begin());
  const std::size_t start = line_starts_[line - 1];
  std::size_t column = 1;
  for (std::size_t i = start; i < offset; ++i) {
    if ((static_cast<unsigned char>(text_[i]) & 0xC0U) != 0x80U) {
      ++column;
    }
  }
  return {line, column};
}

}  // namespace impulse::derivations::file
