// SPDX-License-Identifier: GPL-3.0-or-later
#include "typeset.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <regex>
#include <utility>
#include <vector>

namespace impulse::derivations::typeset {

namespace {

// --- Plain words to LaTeX ------------------------------------------------------------------------

bool ascii_letter(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0;
}
bool ascii_digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// The UTF-8 characters a plain formula may hold, with their LaTeX: letters (what a symbol may
// begin with), operators, and the combining accents that follow a letter.
struct Special {
  std::string_view utf8;
  std::string_view latex;
  enum { letter, op, accent } role;
};
constexpr std::array specials{
    Special{"α", "\\alpha", Special::letter},
    Special{"β", "\\beta", Special::letter},
    Special{"γ", "\\gamma", Special::letter},
    Special{"δ", "\\delta", Special::letter},
    Special{"ε", "\\varepsilon", Special::letter},
    Special{"θ", "\\theta", Special::letter},
    Special{"κ", "\\kappa", Special::letter},
    Special{"λ", "\\lambda", Special::letter},
    Special{"μ", "\\mu", Special::letter},
    Special{"ν", "\\nu", Special::letter},
    Special{"ξ", "\\xi", Special::letter},
    Special{"π", "\\pi", Special::letter},
    Special{"ρ", "\\rho", Special::letter},
    Special{"σ", "\\sigma", Special::letter},
    Special{"τ", "\\tau", Special::letter},
    Special{"φ", "\\varphi", Special::letter},
    Special{"χ", "\\chi", Special::letter},
    Special{"ψ", "\\psi", Special::letter},
    Special{"ω", "\\omega", Special::letter},
    Special{"Γ", "\\Gamma", Special::letter},
    Special{"Δ", "\\Delta ", Special::letter},
    Special{"Θ", "\\Theta", Special::letter},
    Special{"Λ", "\\Lambda", Special::letter},
    Special{"Π", "\\Pi", Special::letter},
    Special{"Σ", "\\Sigma", Special::letter},
    Special{"Φ", "\\Phi", Special::letter},
    Special{"Ω", "\\Omega", Special::letter},
    Special{"ℓ", "\\ell", Special::letter},
    Special{"≤", "\\leq", Special::op},
    Special{"≥", "\\geq", Special::op},
    Special{"≠", "\\neq", Special::op},
    Special{"·", "\\cdot", Special::op},
    Special{"⇒", "\\Rightarrow", Special::op},
    Special{"×", "\\times", Special::op},
    Special{"−", "-", Special::op},
    Special{"′", "'", Special::op},
    Special{"\u0304", "\\bar", Special::accent},
    Special{"\u0303", "\\tilde", Special::accent},
    Special{"\u0302", "\\hat", Special::accent},
};

const Special* special_at(std::string_view text, std::size_t at) {
  for (const Special& s : specials) {
    if (text.substr(at, s.utf8.size()) == s.utf8) {
      return &s;
    }
  }
  return nullptr;
}

// A name of several letters: a command when LaTeX has one, else a word in italics.
std::string latex_of_name(const std::string& name) {
  static const std::array commands{"alpha", "beta", "gamma",  "delta", "theta", "lambda", "mu",
                                   "nu",    "xi",   "pi",     "rho",   "sigma", "tau",    "phi",
                                   "chi",   "psi",  "omega",  "Delta", "Gamma", "Theta",  "Lambda",
                                   "Omega", "sum",  "exists", "det",   "cos",   "sin",    "ell"};
  if (name.size() == 1) {
    return name;
  }
  if (std::find(commands.begin(), commands.end(), name) != commands.end()) {
    return "\\" + name;
  }
  // F dt written together: a letter and the duration.
  if (name.size() == 3 && name.ends_with("dt")) {
    return name.substr(0, 1) + "\\,dt";
  }
  if (name == "dt") {
    return "dt";
  }
  return "\\mathit{" + name + "}";
}

// A number as written by the checker ("0.5", "-3", "1.24643e-17"), powers of ten as such.
std::string latex_of_number(const std::string& number) {
  const std::size_t e = number.find_first_of("eE");
  if (e == std::string::npos) {
    return number;
  }
  const std::string mantissa = number.substr(0, e);
  std::string exponent = number.substr(e + 1);
  const bool negative = !exponent.empty() && exponent.front() == '-';
  if (!exponent.empty() && (exponent.front() == '-' || exponent.front() == '+')) {
    exponent.erase(0, 1);
  }
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  const std::string power = "10^{" + std::string(negative ? "-" : "") + exponent + "}";
  return mantissa == "1" ? power : mantissa + " \\times " + power;
}

// A symbol at plain[i] (a name of ASCII letters or one Greek letter, then accents, primes and a
// subscript) in LaTeX; i moves past it.
std::string read_symbol(std::string_view plain, std::size_t& i, const Special* special) {
  std::string name;
  if (special != nullptr) {
    name = std::string(special->latex);
    i += special->utf8.size();
  } else {
    std::string word;
    while (i < plain.size() && ascii_letter(plain[i])) {
      word += plain[i++];
    }
    name = latex_of_name(word);
  }
  while (const Special* accent = i < plain.size() ? special_at(plain, i) : nullptr) {
    if (accent->role != Special::accent) {
      break;
    }
    name = std::string(accent->latex) + "{" + name + "}";
    i += accent->utf8.size();
  }
  std::string primes;
  while (i < plain.size() && plain[i] == '\'') {
    primes += '\'';
    ++i;
  }
  if (i + 1 < plain.size() && plain[i] == '_' &&
      (ascii_letter(plain[i + 1]) || ascii_digit(plain[i + 1]))) {
    std::string sub;
    ++i;
    while (i < plain.size() && (ascii_letter(plain[i]) || ascii_digit(plain[i]))) {
      sub += plain[i++];
    }
    // A parenthesised word right after belongs to the subscript: a_v1(elastic).
    if (i < plain.size() && plain[i] == '(') {
      const std::size_t close = plain.find(')', i);
      if (close != std::string_view::npos &&
          std::all_of(plain.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                      plain.begin() + static_cast<std::ptrdiff_t>(close), ascii_letter)) {
        sub += std::string(plain.substr(i, close + 1 - i));
        i = close + 1;
      }
    }
    name += primes + "_{" + sub + "}";
    primes.clear();
  }
  while (i < plain.size() && plain[i] == '\'') {
    primes += '\'';
    ++i;
  }
  return name + primes;
}

// A number at plain[i] ("0.5", "1.2e-17") in LaTeX; i moves past it.
std::string read_number(std::string_view plain, std::size_t& i) {
  std::string number;
  while (i < plain.size() && (ascii_digit(plain[i]) || plain[i] == '.')) {
    number += plain[i++];
  }
  if (i + 1 < plain.size() && (plain[i] == 'e' || plain[i] == 'E') &&
      (ascii_digit(plain[i + 1]) || ((plain[i + 1] == '-' || plain[i + 1] == '+') &&
                                     i + 2 < plain.size() && ascii_digit(plain[i + 2])))) {
    number += plain[i++];
    number += plain[i++];
    while (i < plain.size() && ascii_digit(plain[i])) {
      number += plain[i++];
    }
  }
  return latex_of_number(number);
}

}  // namespace

std::string latex_of_plain(std::string_view plain) {
  std::string out;
  const auto append = [&](const std::string& piece) {
    if (piece.empty()) {
      return;
    }
    // A command followed by a letter needs a space between them.
    if (!out.empty() && ascii_letter(piece.front())) {
      std::size_t k = out.size();
      while (k > 0 && ascii_letter(out[k - 1])) {
        --k;
      }
      if (k > 0 && out[k - 1] == '\\' && k < out.size()) {
        out += ' ';
      }
    }
    out += piece;
  };
  std::size_t i = 0;
  while (i < plain.size()) {
    const char c = plain[i];
    if (c == ' ') {
      if (!out.empty() && out.back() != ' ') {
        out += ' ';
      }
      ++i;
      continue;
    }
    const Special* special = special_at(plain, i);
    // A symbol: a name (ASCII letters, or one Greek letter), accents, primes, a subscript.
    if (ascii_letter(c) || (special != nullptr && special->role == Special::letter)) {
      append(read_symbol(plain, i, special));
      continue;
    }
    if (special != nullptr) {
      append(std::string(special->latex));
      i += special->utf8.size();
      continue;
    }
    if (ascii_digit(c) || (c == '.' && i + 1 < plain.size() && ascii_digit(plain[i + 1]))) {
      append(read_number(plain, i));
      continue;
    }
    if (c == '^') {
      // A power: its exponent (a signed number or a name) in braces.
      ++i;
      std::string exponent;
      if (i < plain.size() && (plain[i] == '-' || plain[i] == '+')) {
        exponent += plain[i++];
      }
      while (i < plain.size() && (ascii_digit(plain[i]) || ascii_letter(plain[i]))) {
        exponent += plain[i++];
      }
      out += "^{" + exponent + "}";
      continue;
    }
    switch (c) {
      case '{':
      case '}':
      case '#':
      case '%':
      case '&':
      case '$':
      case '_':
        out += std::string("\\") + c;
        break;
      case '|':
        out += "\\vert ";
        break;
      case '\\':
      case '~':
        break;
      default:
        out += c;
    }
    ++i;
  }
  while (!out.empty() && out.back() == ' ') {
    out.pop_back();
  }
  return out;
}

namespace {

std::string inline_math(std::string_view plain) {
  return "\\f$ " + latex_of_plain(plain) + " \\f$";
}

// "m_1 = 1, p = [0, 2]; F = 1.5": one formula per value, split at commas and semicolons outside
// brackets, the separators kept as words.
std::string values_markdown(std::string_view plain) {
  std::string out;
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= plain.size(); ++i) {
    const char c = i < plain.size() ? plain[i] : ',';
    depth += c == '[' || c == '(' ? 1 : c == ']' || c == ')' ? -1 : 0;
    if (depth == 0 && (c == ',' || c == ';') &&
        (i == plain.size() || i + 1 == plain.size() || plain[i + 1] == ' ')) {
      std::string_view item = plain.substr(start, i - start);
      while (!item.empty() && item.front() == ' ') {
        item.remove_prefix(1);
      }
      if (!item.empty()) {
        out += inline_math(item);
        if (i < plain.size()) {
          out += c;
          out += ' ';
        }
      }
      start = i + 1;
    }
  }
  while (!out.empty() && out.back() == ' ') {
    out.pop_back();
  }
  return out;
}

std::string sides_markdown(const std::string& side) {
  return side == "not finite" ? side : inline_math(side);
}

}  // namespace

std::string counterexample_markdown(std::string_view plain) {
  const std::string text(plain);
  static const std::regex none(R"(^none of (\d+) cases searched satisfies (.*?)(; e\.g\. (.*))?$)");
  static const std::regex gives(R"(^(.*) gives (.*) fails \(its sides: (.*) and (.*)\)$)");
  static const std::regex exact(R"(^(.*) \(exact\)$)");
  std::smatch m;
  if (std::regex_match(text, m, none)) {
    std::string out =
        "none of " + m[1].str() + " cases searched satisfies " + inline_math(m[2].str());
    if (m[3].matched) {
      out += "; e.g. " + counterexample_markdown(m[4].str());
    }
    return out;
  }
  if (std::regex_match(text, m, gives)) {
    return values_markdown(m[1].str()) + " gives " + inline_math(m[2].str()) +
           ", which fails (its sides: " + sides_markdown(m[3].str()) + " and " +
           sides_markdown(m[4].str()) + ")";
  }
  if (std::regex_match(text, m, exact)) {
    return values_markdown(m[1].str()) + " (exact)";
  }
  if (text.find(" = ") != std::string::npos && text.find(" gives ") == std::string::npos) {
    return values_markdown(text);
  }
  return text;
}

bool refuted_by_argument(std::string_view plain) {
  return plain.starts_with("none of ");
}

// --- Terms that differ -----------------------------------------------------------------------

namespace {

struct Token {
  std::size_t begin = 0;
  std::size_t end = 0;
  std::string text;
};

std::vector<Token> tokens_of(std::string_view latex) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < latex.size()) {
    const char c = latex[i];
    if (std::isspace(static_cast<unsigned char>(c)) != 0) {
      ++i;
      continue;
    }
    std::size_t end = i + 1;
    if (c == '\\' && end < latex.size()) {
      if (ascii_letter(latex[end])) {
        while (end < latex.size() && ascii_letter(latex[end])) {
          ++end;
        }
      } else {
        ++end;
      }
    } else if ((static_cast<unsigned char>(c) & 0x80U) != 0) {
      while (end < latex.size() && (static_cast<unsigned char>(latex[end]) & 0xC0U) == 0x80U) {
        ++end;
      }
    }
    tokens.push_back({i, end, std::string(latex.substr(i, end - i))});
    i = end;
  }
  return tokens;
}

// A piece of a formula: a term (marked when it differs) or what stands between terms.
struct Item {
  bool term = false;
  std::size_t begin = 0;  // in the formula's text
  std::size_t end = 0;
  std::string same;  // what two items are compared by
};

// What a term is compared by: no spaces or spacing commands, no \left and \right, a single
// symbol's braces dropped, \operatorname{x} and \mathrm{d} as their letters.
std::string comparable(std::string_view latex) {
  std::string text;
  for (const Token& t : tokens_of(latex)) {
    if (t.text != "\\," && t.text != "\\;" && t.text != "\\!" && t.text != "\\ " &&
        t.text != "\\left" && t.text != "\\right") {
      text += t.text;
    }
  }
  static const std::regex wrapper(R"(\\(operatorname|mathrm)\{([^{}]*)\})");
  static const std::regex single(R"(\{([A-Za-z0-9])\})");
  text = std::regex_replace(text, wrapper, "$2");
  for (std::string before; before != text;) {
    before = text;
    text = std::regex_replace(text, single, "$1");
  }
  return text;
}

bool is_separator(const std::string& t) {
  static const std::array separators{"=",      "<",       ">",    "\\leq",    "\\geq",
                                     "\\neq",  "\\le",    "\\ge", "\\approx", "\\Rightarrow",
                                     "\\quad", "\\qquad", ",",    "&",        "\\\\"};
  return std::find(separators.begin(), separators.end(), t) != separators.end();
}

std::vector<Item> items_of(std::string_view latex) {
  const std::vector<Token> tokens = tokens_of(latex);
  std::vector<Item> items;
  int depth = 0;
  std::size_t term_begin = std::string::npos;
  std::size_t term_end = 0;
  const auto close_term = [&] {
    if (term_begin != std::string::npos) {
      items.push_back({true, term_begin, term_end,
                       comparable(latex.substr(term_begin, term_end - term_begin))});
      term_begin = std::string::npos;
    }
  };
  const auto separator = [&](std::size_t begin, std::size_t end) {
    close_term();
    items.push_back({false, begin, end, comparable(latex.substr(begin, end - begin))});
  };
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    const Token& t = tokens[k];
    // \begin{…}, \end{…} and \tag{…} stand between terms, with their braces.
    if (depth == 0 && (t.text == "\\begin" || t.text == "\\end" || t.text == "\\tag") &&
        k + 1 < tokens.size() && tokens[k + 1].text == "{") {
      std::size_t j = k + 1;
      while (j < tokens.size() && tokens[j].text != "}") {
        ++j;
      }
      const std::size_t end = j < tokens.size() ? tokens[j].end : tokens.back().end;
      separator(t.begin, end);
      k = j;
      continue;
    }
    if (depth == 0 && is_separator(t.text)) {
      separator(t.begin, t.end);
      continue;
    }
    if (depth == 0 && (t.text == "+" || t.text == "-") && term_begin != std::string::npos) {
      close_term();
    }
    if (t.text == "\\left" || t.text == "\\right") {
      depth += t.text == "\\left" ? 1 : -1;
      if (term_begin == std::string::npos) {
        term_begin = t.begin;
      }
      term_end = k + 1 < tokens.size() ? tokens[k + 1].end : t.end;
      ++k;  // the delimiter
      continue;
    }
    if (t.text == "{" || t.text == "(" || t.text == "[") {
      ++depth;
    } else if ((t.text == "}" || t.text == ")" || t.text == "]") && depth > 0) {
      --depth;
    }
    if (term_begin == std::string::npos) {
      term_begin = t.begin;
    }
    term_end = t.end;
  }
  close_term();
  return items;
}

// For each item of a and of b: whether it is in their longest common subsequence.
std::pair<std::vector<bool>, std::vector<bool>> common(const std::vector<Item>& a,
                                                       const std::vector<Item>& b) {
  std::vector<std::vector<std::size_t>> length(a.size() + 1,
                                               std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = a.size(); i-- > 0;) {
    for (std::size_t j = b.size(); j-- > 0;) {
      length[i][j] = a[i].term == b[j].term && a[i].same == b[j].same
                         ? length[i + 1][j + 1] + 1
                         : std::max(length[i + 1][j], length[i][j + 1]);
    }
  }
  std::vector<bool> in_a(a.size()), in_b(b.size());
  for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    if (a[i].term == b[j].term && a[i].same == b[j].same) {
      in_a[i++] = true;
      in_b[j++] = true;
    } else if (length[i + 1][j] >= length[i][j + 1]) {
      ++i;
    } else {
      ++j;
    }
  }
  return {in_a, in_b};
}

std::string boxed(std::string_view latex, const std::vector<Item>& items,
                  const std::vector<bool>& kept, bool& changed) {
  std::string out;
  std::size_t at = 0;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const Item& item = items[k];
    out += latex.substr(at, item.begin - at);
    const std::string_view text = latex.substr(item.begin, item.end - item.begin);
    if (item.term && !kept[k]) {
      out += "\\boxed{" + std::string(text) + "}";
      changed = true;
    } else {
      out += text;
    }
    at = item.end;
  }
  out += latex.substr(at);
  return out;
}

}  // namespace

Marked mark_changes(std::string_view printed, std::string_view corrected) {
  const std::vector<Item> a = items_of(printed);
  const std::vector<Item> b = items_of(corrected);
  const auto [in_a, in_b] = common(a, b);
  Marked marked;
  marked.printed = boxed(printed, a, in_a, marked.changed);
  marked.corrected = boxed(corrected, b, in_b, marked.changed);
  return marked;
}

}  // namespace impulse::derivations::typeset
