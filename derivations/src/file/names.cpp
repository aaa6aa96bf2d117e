// SPDX-License-Identifier: GPL-3.0-or-later
// The names of symbols: as LaTeX (the key under which a file's symbols are known) and as plain
// text.
#include "file/latex.hpp"

namespace impulse::derivations::file {

std::string SymbolName::latex() const {
  std::string out = delta ? "\\Delta " : differential ? "\\mathrm{d}" : "";
  out += arrow ? "\\vec{" + base + "}" : base;
  if (!subscript.empty()) {
    out += subscript.size() == 1 ? "_" + subscript : "_{" + subscript + "}";
  }
  out += std::string(static_cast<std::size_t>(primes), '\'');
  return out;
}

std::string SymbolName::plain() const {
  std::string out = delta ? "Delta " : differential ? "d" : "";
  if (arrow) {
    out += "vec ";
  }
  const auto strip = [](const std::string& s) {
    std::string r;
    for (const char c : s) {
      if (c != '\\' && c != '{' && c != '}') {
        r += c;
      }
    }
    return r;
  };
  out += strip(base);
  if (!subscript.empty()) {
    out += "_" + strip(subscript);
  }
  out += std::string(static_cast<std::size_t>(primes), '\'');
  return out;
}

SymbolName SymbolName::unprimed() const {
  SymbolName name = *this;
  name.primes = 0;
  return name;
}

}  // namespace impulse::derivations::file
