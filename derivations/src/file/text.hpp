// SPDX-License-Identifier: GPL-3.0-or-later
// The text of a derivation file: checked once to be UTF-8 text within the reader's limits, and
// every byte offset in it turned into the place a person looks for (line and column).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::derivations::file {

/// @p s without the spaces, tabs and line ends around it.
[[nodiscard]] std::string trimmed(std::string_view s);

/// A place in the file: 1-based line and column (columns count characters, not bytes).
struct Place {
  std::size_t line = 1;
  std::size_t column = 1;
};

/// The file cannot be read: `what()` says what was expected there. The command line prints it
/// as `FILE:LINE:COLUMN: what was expected`.
class ReadError : public std::runtime_error {
 public:
  ReadError(Place place, const std::string& message) : std::runtime_error(message), place_(place) {}
  /// Where the reader stopped.
  [[nodiscard]] Place place() const { return place_; }

 private:
  Place place_;
};

/// The reader's limits: beyond each, the file is refused with the limit in the message (never a
/// hang, a stack overflow or memory exhausted).
struct Limits {
  std::size_t bytes = std::size_t{4} << 20;  ///< 4 MiB: a book of derivations is ~100 KiB
  std::size_t equations = 2000;              ///< display equations per file
  std::size_t equation_characters = 20000;   ///< characters of one display block
  std::size_t nesting = 100;                 ///< groups, fractions, functions inside one another
  std::size_t number_digits = 400;           ///< characters of one number (100! has 158)
  long exponent = 1000;                      ///< largest integer exponent written
};

/// The whole text of the file, with the offsets of its line starts.
class Source {
 public:
  /// Checks the text (size, UTF-8, no NUL or other control characters but tab, CR and LF) and
  /// indexes its lines. Throws ReadError at the first offending byte.
  Source(std::string text, const Limits& limits = {});

  [[nodiscard]] const std::string& text() const { return text_; }
  /// The place of a byte offset (an offset at the end of the text is allowed).
  [[nodiscard]] Place place(std::size_t offset) const;
  /// A ReadError at a byte offset.
  [[nodiscard]] ReadError error(std::size_t offset, const std::string& message) const {
    return {place(offset), message};
  }

 private:
  std::string text_;
  std::vector<std::size_t> line_starts_;
};

}  // namespace impulse::derivations::file
