// SPDX-License-Identifier: GPL-3.0-or-later
// A small HTML scanner for the site's pages as Doxygen and the interactive pages write them: tags
// with their attributes and the text between them, in order. The site's search index
// (docs/tools/site.cpp) and the site's tests (docs/test/site_test.cpp) read pages with it.
#pragma once

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::site {

/// A tag: its name in lower case ("/a" for a closing tag) and its attributes.
struct Tag {
  std::string name;
  std::map<std::string, std::string> attributes;

  /// The value of an attribute, or "" when the tag has none.
  [[nodiscard]] std::string attribute(const std::string& key) const {
    const auto it = attributes.find(key);
    return it == attributes.end() ? std::string() : it->second;
  }
  /// Whether its class attribute names @p cls among its classes.
  [[nodiscard]] bool has_class(std::string_view cls) const {
    const std::string all = attribute("class");
    std::size_t at = 0;
    while (at < all.size()) {
      const std::size_t end = std::min(all.find(' ', at), all.size());
      if (std::string_view(all).substr(at, end - at) == cls) {
        return true;
      }
      at = end + 1;
    }
    return false;
  }
};

inline std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

namespace detail {

inline bool is_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_' || c == ':' ||
         c == '/';
}

// Parses the tag that starts at html[begin] == '<'; returns the index after its '>'.
inline std::size_t parse_tag(std::string_view html, std::size_t begin, Tag& tag) {
  std::size_t i = begin + 1;
  const std::size_t name_begin = i;
  while (i < html.size() && is_name_char(html[i])) {
    ++i;
  }
  tag.name = lower(std::string(html.substr(name_begin, i - name_begin)));
  tag.attributes.clear();
  while (i < html.size() && html[i] != '>') {
    if (std::isspace(static_cast<unsigned char>(html[i])) != 0 || html[i] == '/') {
      ++i;
      continue;
    }
    const std::size_t key_begin = i;
    while (i < html.size() && html[i] != '=' && html[i] != '>' &&
           std::isspace(static_cast<unsigned char>(html[i])) == 0) {
      ++i;
    }
    const std::string key = lower(std::string(html.substr(key_begin, i - key_begin)));
    std::string value;
    if (i < html.size() && html[i] == '=') {
      ++i;
      if (i < html.size() && (html[i] == '"' || html[i] == '\'')) {
        const char quote = html[i];
        const std::size_t end = html.find(quote, i + 1);
        value = std::string(html.substr(i + 1, end - i - 1));
        i = end == std::string_view::npos ? html.size() : end + 1;
      } else {
        const std::size_t value_begin = i;
        while (i < html.size() && html[i] != '>' &&
               std::isspace(static_cast<unsigned char>(html[i])) == 0) {
          ++i;
        }
        value = std::string(html.substr(value_begin, i - value_begin));
      }
    }
    tag.attributes[key] = value;
  }
  return i < html.size() ? i + 1 : i;
}

}  // namespace detail

/// Walks a page in order: @p on_tag for each tag, @p on_text for the text between tags (as
/// written, entities not decoded). Comments are skipped; the contents of <script> and <style>
/// go to @p on_script (with the opening tag), never to @p on_text.
inline void walk(std::string_view html, const std::function<void(const Tag&)>& on_tag,
                 const std::function<void(std::string_view)>& on_text,
                 const std::function<void(const Tag&, std::string_view)>& on_script = {}) {
  std::size_t i = 0;
  while (i < html.size()) {
    const std::size_t open = html.find('<', i);
    const std::string_view text =
        html.substr(i, open == std::string_view::npos ? std::string_view::npos : open - i);
    if (!text.empty()) {
      on_text(text);
    }
    if (open == std::string_view::npos) {
      break;
    }
    if (html.compare(open, 4, "<!--") == 0) {
      const std::size_t end = html.find("-->", open + 4);
      i = end == std::string_view::npos ? html.size() : end + 3;
      continue;
    }
    Tag tag;
    i = detail::parse_tag(html, open, tag);
    if (tag.name == "script" || tag.name == "style") {
      // Browsers and Doxygen write tag names in lower case.
      const std::size_t close = html.find("</" + tag.name, i);
      const std::size_t end = close == std::string_view::npos ? html.size() : close;
      if (on_script) {
        on_script(tag, html.substr(i, end - i));
      }
      i = end;
    }
    on_tag(tag);
  }
}

/// Text with its character references decoded (&amp; &lt; &gt; &quot; &apos; &nbsp; and numeric
/// ones, the latter as UTF-8).
inline std::string decode_entities(std::string_view text) {
  static const std::map<std::string, std::string, std::less<>> named{
      {"amp", "&"},         {"lt", "<"},         {"gt", ">"},          {"quot", "\""},
      {"apos", "'"},        {"nbsp", "\u00a0"},  {"ndash", "\u2013"},  {"mdash", "\u2014"},
      {"hellip", "\u2026"}, {"times", "\u00d7"}, {"middot", "\u00b7"}, {"rarr", "\u2192"},
      {"larr", "\u2190"},   {"laquo", "\u00ab"}, {"raquo", "\u00bb"},  {"rsaquo", "\u203a"},
      {"lsaquo", "\u2039"}};
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const std::size_t semicolon = text[i] == '&' ? text.find(';', i) : std::string_view::npos;
    if (semicolon == std::string_view::npos || semicolon - i > 10) {
      out += text[i];
      continue;
    }
    const std::string_view name = text.substr(i + 1, semicolon - i - 1);
    std::uint32_t code = 0;
    bool numeric = name.size() > 1 && name[0] == '#';
    if (numeric) {
      const bool hex = name[1] == 'x' || name[1] == 'X';
      for (const char c : name.substr(hex ? 2 : 1)) {
        const int digit = std::isdigit(static_cast<unsigned char>(c)) != 0 ? c - '0'
                          : hex && std::isxdigit(static_cast<unsigned char>(c)) != 0
                              ? std::tolower(static_cast<unsigned char>(c)) - 'a' + 10
                              : -1;
        if (digit < 0) {
          numeric = false;
          break;
        }
        code = code * (hex ? 16U : 10U) + static_cast<std::uint32_t>(digit);
      }
    }
    if (numeric && code > 0 && code < 0x110000) {
      if (code < 0x80) {
        out += static_cast<char>(code);
      } else if (code < 0x800) {
        out += static_cast<char>(0xC0 | (code >> 6));
        out += static_cast<char>(0x80 | (code & 0x3F));
      } else if (code < 0x10000) {
        out += static_cast<char>(0xE0 | (code >> 12));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
      } else {
        out += static_cast<char>(0xF0 | (code >> 18));
        out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
      }
      i = semicolon;
    } else if (const auto it = named.find(name); it != named.end()) {
      out += it->second;
      i = semicolon;
    } else {
      out += text[i];
    }
  }
  return out;
}

/// A page as scanned: its tags, and its text in three cuts.
struct Scanned {
  std::vector<Tag> tags;
  std::string visible_text;   ///< text outside tags, scripts, styles and comments
  std::string prose_text;     ///< the part of it that is not code (<code>, <pre>, <tt>,
                              ///< Doxygen's fragments): where LaTeX shown on purpose cannot be
  std::string unlinked_text;  ///< the part of it that is not inside a link
  std::vector<std::string> script_texts;
};

inline Scanned scan(std::string_view html) {
  Scanned result;
  int link_depth = 0;
  int code_depth = 0;
  std::vector<bool> fragment_divs;  // for each open <div>: is it (inside) a code fragment?
  walk(
      html,
      [&](const Tag& tag) {
        link_depth += tag.name == "a" ? 1 : tag.name == "/a" ? -1 : 0;
        const bool code = tag.name == "code" || tag.name == "pre" || tag.name == "tt";
        const bool code_end = tag.name == "/code" || tag.name == "/pre" || tag.name == "/tt";
        code_depth += code ? 1 : code_end && code_depth > 0 ? -1 : 0;
        if (tag.name == "div") {
          const bool fragment = tag.attribute("class") == "fragment";
          fragment_divs.push_back(fragment || (!fragment_divs.empty() && fragment_divs.back()));
        } else if (tag.name == "/div" && !fragment_divs.empty()) {
          fragment_divs.pop_back();
        }
        result.tags.push_back(tag);
      },
      [&](std::string_view text) {
        result.visible_text += text;
        const bool in_fragment = !fragment_divs.empty() && fragment_divs.back();
        if (code_depth == 0 && !in_fragment) {
          result.prose_text += text;
        }
        if (link_depth == 0) {
          result.unlinked_text += text;
        }
      },
      [&](const Tag& tag, std::string_view text) {
        if (tag.name == "script") {
          result.script_texts.emplace_back(text);
        }
      });
  return result;
}

}  // namespace impulse::site
