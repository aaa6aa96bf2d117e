// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/core/text.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

namespace impulse {

std::string number_text(double value) {
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.6g", value + 0.0);  // + 0.0: no "-0"
  return buffer.data();
}

std::string rounded_text(double value) {
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.2g", value);
  return buffer.data();
}

std::string chopped(double value, double scale) {
  return number_text(std::abs(value) <= rounding_noise * scale ? 0.0 : value);
}

std::string vector_text(const Eigen::Vector2d& v, int dimension, double scale) {
  if (dimension == 1) {
    return chopped(v.x(), scale);
  }
  std::string text("[");
  text.append(chopped(v.x(), scale)).append(", ").append(chopped(v.y(), scale)).append("]");
  return text;
}

std::string member_place(std::string_view path, std::string_view key) {
  std::string place(path);
  return place.append(path.empty() ? "" : ".").append(key);
}

std::string element_place(std::string_view path, std::size_t index) {
  std::string place(path);
  return place.append("[").append(std::to_string(index)).append("]");
}

std::string in_quotes(std::string_view text) {
  std::string result("\"");
  return result.append(text).append("\"");
}

std::string counted(std::size_t count, std::string_view one, std::string_view many) {
  std::string text = std::to_string(count);
  text.append(" ").append(count == 1 ? one : many);
  return text;
}

std::size_t characters(std::string_view text) {
  // A UTF-8 continuation byte is 10xxxxxx; every other byte starts a character.
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0U) != 0x80U;
  }));
}

TextTable::TextTable(std::vector<std::string> header, std::vector<bool> left)
    : left_(std::move(left)) {
  rows_.push_back(std::move(header));
}

void TextTable::add(std::vector<std::string> row) {
  rows_.push_back(std::move(row));
}

std::string TextTable::render(std::string_view indent) const {
  std::vector<std::size_t> width;
  for (const auto& row : rows_) {
    width.resize(std::max(width.size(), row.size()), 0);
    for (std::size_t c = 0; c < row.size(); ++c) {
      width[c] = std::max(width[c], characters(row[c]));
    }
  }
  std::string text;
  for (const auto& row : rows_) {
    if (row.empty()) {
      continue;  // a table without a header
    }
    std::string line(indent);
    for (std::size_t c = 0; c < row.size(); ++c) {
      const std::string padding(width[c] - characters(row[c]), ' ');
      const bool left = c < left_.size() && left_[c];
      line.append(c == 0 ? "" : "  ");
      line.append(left ? row[c] + padding : padding + row[c]);
    }
    while (!line.empty() && line.back() == ' ') {
      line.pop_back();
    }
    text.append(line).append("\n");
  }
  return text;
}

}  // namespace impulse
