// SPDX-License-Identifier: GPL-3.0-or-later
// The mutation test of the paper's files: every equation and step of derivations/paper/ is fed to
// the engine with one change to its printed statement (a sign flipped, a factor 2 dropped or put
// in, a prime dropped, a term dropped) and must not come out verified. A change the engine cannot
// read is not counted (it tests the reader, not the mathematics); a change that leaves the
// mathematics as it was would be listed below with why.
#include <catch2/catch.hpp>
#include <cctype>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "derivations/check.hpp"
#include "derivations/derivation.hpp"

namespace check = impulse::derivations;

namespace {

// The parts of a statement that are names, not mathematics: \tag{…} and \label{…}.
std::vector<bool> in_names(const std::string& s) {
  std::vector<bool> masked(s.size(), false);
  for (const char* command : {"\\tag{", "\\label{", "\\mathit{", "\\begin{", "\\end{"}) {
    for (std::size_t at = s.find(command); at != std::string::npos; at = s.find(command, at + 1)) {
      const std::size_t close = s.find('}', at);
      for (std::size_t i = at; i <= close && i < s.size(); ++i) {
        masked[i] = true;
      }
    }
  }
  return masked;
}

bool symbol_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '_' || c == '^';
}

// A sign flipped: the first binary + becomes -, or else the first - becomes +.
std::optional<std::string> flip_sign(std::string s) {
  const auto masked = in_names(s);
  for (const char from : {'+', '-'}) {
    for (std::size_t i = 1; i < s.size(); ++i) {
      if (s[i] == from && !masked[i]) {
        s[i] = from == '+' ? '-' : '+';
        return s;
      }
    }
  }
  return std::nullopt;
}

// A factor 2 dropped (the first coefficient 2, not an exponent, subscript or part of a name or
// number), or else one put in front of the first right-hand side.
std::optional<std::string> factor_two(std::string s) {
  const auto masked = in_names(s);
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '2' || masked[i]) {
      continue;
    }
    std::size_t before = i;
    while (before > 0 && s[before - 1] == ' ') {
      --before;
    }
    const char prev = before > 0 ? s[before - 1] : ' ';
    const char prev2 = before > 1 ? s[before - 2] : ' ';
    const char next = i + 1 < s.size() ? s[i + 1] : ' ';
    if (symbol_char(prev) || (prev == '{' && (prev2 == '^' || prev2 == '_')) ||
        std::isdigit(static_cast<unsigned char>(next)) != 0 || next == '.' || next == '}') {
      continue;
    }
    s.erase(i, 1);
    return s;
  }
  const std::size_t eq = s.find('=');
  if (eq == std::string::npos) {
    return std::nullopt;
  }
  s.insert(eq + 1, " 2");
  return s;
}

// A prime dropped (the first ' of the statement).
std::optional<std::string> drop_prime(std::string s) {
  const std::size_t at = s.find('\'');
  if (at == std::string::npos) {
    return std::nullopt;
  }
  s.erase(at, 1);
  return s;
}

// A term dropped: from the first binary + or - at the shallowest bracket depth to the next
// operator, relation, separator or closing bracket at that depth.
std::optional<std::string> drop_term(std::string s) {
  const auto masked = in_names(s);
  std::vector<int> depth(s.size(), 0);
  int d = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '{' || s[i] == '(' || s[i] == '[') {
      ++d;
    }
    depth[i] = d;
    if (s[i] == '}' || s[i] == ')' || s[i] == ']') {
      --d;
    }
  }
  std::optional<std::size_t> start;
  for (std::size_t i = 1; i < s.size(); ++i) {
    if ((s[i] == '+' || s[i] == '-') && !masked[i] && (!start || depth[i] < depth[*start])) {
      std::size_t before = i;
      while (before > 0 && s[before - 1] == ' ') {
        --before;
      }
      const char prev = before > 0 ? s[before - 1] : ' ';
      if (prev == '=' || prev == '(' || prev == '{' || prev == '[' || prev == '&' || prev == ',') {
        continue;  // a unary sign
      }
      start = i;
    }
  }
  if (!start) {
    return std::nullopt;
  }
  const int level = depth[*start];
  std::size_t end = *start + 1;
  for (; end < s.size(); ++end) {
    const char c = s[end];
    const bool closing = (c == '}' || c == ')' || c == ']') && depth[end] == level;
    const bool same = depth[end] == level && c != '{' && c != '(' && c != '[';
    if (closing ||
        (same && (c == '+' || c == '-' || c == '=' || c == ',' || c == '&' || c == '<' ||
                  c == '>' || s.compare(end, 2, "\\\\") == 0 || s.compare(end, 4, "\\tag") == 0 ||
                  s.compare(end, 6, "\\label") == 0 || s.compare(end, 6, "\\quad") == 0 ||
                  s.compare(end, 6, "\\right") == 0 || s.compare(end, 4, "\\end") == 0))) {
      if (end > *start + 1 && !(c == '-' && s[end - 1] == '{')) {
        break;
      }
    }
  }
  s.erase(*start, end - *start);
  return s;
}

struct Mutation {
  const char* name;
  std::optional<std::string> (*apply)(std::string);
};

constexpr Mutation mutations[] = {{"sign flipped", flip_sign},
                                  {"factor 2 <-> 1", factor_two},
                                  {"prime dropped", drop_prime},
                                  {"term dropped", drop_term}};

}  // namespace

TEST_CASE("The mutation test: no changed equation or step of the paper's files is verified",
          "[derivations][mutation]") {
  const auto& files = check::paper_files();
  std::size_t tried = 0, unreadable = 0, caught = 0;
  std::vector<std::string> missed;
  // Every check in an optimised build; every fourth in a Debug build (the asan preset), where the
  // engine is about twenty times slower and the sanitizers, not the count of changes, are the
  // point.
#ifdef NDEBUG
  constexpr std::size_t every = 1;
#else
  constexpr std::size_t every = 4;
#endif
  std::size_t index = 0;
  for (const check::Check& c : check::all_checks()) {
    if (c.file.empty() || c.kind == check::Kind::claim) {
      continue;  // a claim is not a printed derivation; checks not yet in a file are C++
    }
    if (index++ % every != 0) {
      continue;
    }
    std::size_t f = 0;
    while (files[f].name != c.file) {
      ++f;
    }
    // The statement's place: from the start of its line on.
    std::size_t line_start = 0;
    for (std::size_t line = 1; line < c.line; ++line) {
      line_start = files[f].text.find('\n', line_start) + 1;
    }
    const std::size_t at = files[f].text.find(c.statement, line_start);
    REQUIRE(at != std::string::npos);
    for (const Mutation& m : mutations) {
      const auto changed = m.apply(c.statement);
      if (!changed || *changed == c.statement) {
        continue;
      }
      std::vector<check::PaperFile> mutated = files;
      mutated[f].text.replace(at, c.statement.size(), *changed);
      check::Report report;
      try {
        report = check::run(mutated, {"", 200, 5}, c.id);
      } catch (const check::DerivationError& e) {
        ++unreadable;
        std::cout << "  unreadable (not counted): " << c.id << " (" << m.name << "): " << e.what()
                  << "\n";
        continue;
      }
      ++tried;
      REQUIRE(report.results.size() == 1);
      if (report.results.front().outcome.status != check::Status::verified) {
        ++caught;
      } else {
        missed.push_back(c.id + " (" + m.name + "): " + *changed);
      }
    }
  }
  std::cout << "mutation test: " << caught << " of " << tried << " changes caught ("
            << (tried ? 100.0 * static_cast<double>(caught) / static_cast<double>(tried) : 0.0)
            << " %), " << unreadable << " unreadable changes not counted\n";
  for (const auto& m : missed) {
    std::cout << "  not caught: " << m << "\n";
  }
  CHECK(tried > 40 / every);
  CHECK(missed.empty());
}
