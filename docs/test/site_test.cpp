// SPDX-License-Identifier: GPL-3.0-or-later
// The documentation site as its files are: every promised page is there, no page or stylesheet
// refers to anything outside the site, and every internal link lands on a file and an anchor that
// exist. The last test case feeds the same detectors a page broken on purpose, so that they are
// seen to fail. The pages as a browser shows them (formulas typeset, nothing asked of the network,
// the menu, the width on a phone, the links of the finished page) are site_test.mjs's.
#include <unistd.h>  // mkdtemp

#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "html.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path site_dir{IMPULSELAB_SITE_DIR};

// The pages the site promises: the start page, one per paper section, and the rest of the theory.
const std::vector<std::string> promised_pages = {
    "index.html",    "section1.html", "section2.html",     "section3.html", "section4.html",
    "section5.html", "notation.html", "check_report.html", "errata.html",   "labs.html",
    "methods.html",  "accuracy.html", "friction.html"};
const std::vector<std::string> section_pages = {"section1.html", "section2.html", "section3.html",
                                                "section4.html", "section5.html"};

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw std::runtime_error("cannot read " + file.string());
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write(const fs::path& file, std::string_view text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) {
    throw std::runtime_error("cannot write " + file.string());
  }
}

// A scratch folder that is removed with the object.
struct Scratch {
  fs::path path;
  Scratch() {
    std::string pattern = (fs::temp_directory_path() / "impulselab-site-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw std::runtime_error("mkdtemp failed");
    }
    path = pattern;
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
};

// The pages are read by the scanner the site's own tools use (docs/tools/html.hpp).
using impulse::site::lower;
using impulse::site::scan;
using impulse::site::Scanned;
using impulse::site::Tag;

bool has_scheme(std::string_view url) {
  const std::size_t colon = url.find(':');
  if (colon == std::string_view::npos || colon == 0) {
    return false;
  }
  return std::all_of(url.begin(), url.begin() + static_cast<std::ptrdiff_t>(colon), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '+' || c == '-' || c == '.';
  });
}

// A URL that leaves the site: any scheme but file (and data:, which is inline), or "//host".
bool leaves_site(std::string_view url) {
  if (url.substr(0, 2) == "//") {
    return true;
  }
  if (!has_scheme(url)) {
    return false;
  }
  const std::string scheme = lower(std::string(url.substr(0, url.find(':'))));
  return scheme != "file" && scheme != "data" && scheme != "javascript" && scheme != "mailto";
}

// --- The detectors: each returns what is wrong, empty when nothing is --------------------------

// Resources a page loads (scripts, stylesheets, images, frames, fonts) from outside the site.
std::vector<std::string> outside_resources(const Scanned& page) {
  std::vector<std::string> problems;
  for (const Tag& tag : page.tags) {
    for (const char* attribute : {"src", "data", "srcset", "poster"}) {
      if (const auto it = tag.attributes.find(attribute);
          it != tag.attributes.end() && leaves_site(it->second)) {
        problems.push_back("<" + tag.name + " " + attribute + "=\"" + it->second + "\">");
      }
    }
    if (tag.name == "link") {
      if (const auto it = tag.attributes.find("href");
          it != tag.attributes.end() && leaves_site(it->second)) {
        problems.push_back("<link href=\"" + it->second + "\">");
      }
    }
  }
  for (const std::string& style : page.script_texts) {
    if (style.find("@import") != std::string::npos &&
        (style.find("http:") != std::string::npos || style.find("https:") != std::string::npos)) {
      problems.push_back("an @import from outside the site");
    }
  }
  return problems;
}

std::string decode_percent(std::string_view text) {
  std::string decoded;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size()) {
      decoded += static_cast<char>(std::stoi(std::string(text.substr(i + 1, 2)), nullptr, 16));
      i += 2;
    } else {
      decoded += text[i];
    }
  }
  return decoded;
}

bool has_anchor(const std::string& html, const std::string& anchor) {
  return html.find("id=\"" + anchor + "\"") != std::string::npos ||
         html.find("name=\"" + anchor + "\"") != std::string::npos;
}

// Links (and loaded files) of a page, at @p page_file, that lead to no file of the site, or to
// an anchor its target does not have. @p html is the page as scanned (static or from the DOM).
std::vector<std::string> broken_links(const fs::path& page_file, const std::string& html,
                                      const Scanned& page) {
  std::vector<std::string> problems;
  std::map<fs::path, std::string> targets;
  const auto check = [&](const std::string& url) {
    if (url.empty() || has_scheme(url) || url.substr(0, 2) == "//") {
      return;  // outside links are not the site's to resolve; loads are checked elsewhere
    }
    const std::size_t hash = url.find('#');
    const std::string path = decode_percent(url.substr(0, std::min(url.find('?'), hash)));
    const std::string anchor = hash == std::string::npos ? "" : url.substr(hash + 1);
    const fs::path target = path.empty() ? page_file : page_file.parent_path() / path;
    if (!fs::is_regular_file(target)) {
      problems.push_back(url + " (no file " + target.lexically_normal().string() + ")");
      return;
    }
    if (anchor.empty() || target.extension() != ".html") {
      return;
    }
    if ((target.filename() == "collide.html" && anchor.starts_with("scene=")) ||
        (target.filename() == "check.html" &&
         (anchor.starts_with("file=") || anchor.starts_with("example=")))) {
      return;  // an interactive page's state, not an anchor: the web tests open each such link
    }
    auto [it, fresh] = targets.try_emplace(target);
    if (fresh) {
      it->second = target == page_file ? html : read(target);
    }
    if (!has_anchor(it->second, anchor)) {
      problems.push_back(url + " (no anchor " + anchor + " in " + target.filename().string() + ")");
    }
  };
  for (const Tag& tag : page.tags) {
    for (const char* attribute : {"href", "src"}) {
      if (const auto it = tag.attributes.find(attribute); it != tag.attributes.end()) {
        check(it->second);
      }
    }
  }
  return problems;
}

std::vector<fs::path> site_files(std::string_view extension) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(site_dir)) {
    if (entry.is_regular_file() && entry.path().extension() == extension) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

void require_site() {
  INFO("the site is built by `cmake --build --preset docs` (the `docs` target) into " << site_dir);
  REQUIRE(fs::is_regular_file(site_dir / "index.html"));
}

}  // namespace

TEST_CASE("the site has its start page, a page per paper section and the theory pages", "[docs]") {
  require_site();
  for (const std::string& name : promised_pages) {
    CAPTURE(name);
    CHECK(fs::is_regular_file(site_dir / name));
  }
  REQUIRE(fs::is_regular_file(site_dir / "mathjax" / "MathJax.js"));
  // Each section page puts the outcome of each check beside its equation, linked to the report.
  for (const std::string& name : section_pages) {
    CAPTURE(name);
    const std::string html = read(site_dir / name);
    CHECK(html.find("href=\"check_report_" + name.substr(7, 1) + ".html#check-") !=
          std::string::npos);
  }
  // Every name of the library that the theory pages mention leads to its documentation (Doxygen
  // leaves a name it cannot resolve as plain text, silently).
  std::vector<std::string> theory = section_pages;
  theory.insert(theory.end(), {"index.html", "notation.html", "errata.html", "friction.html"});
  for (const std::string& name : theory) {
    CAPTURE(name);
    const std::string unlinked = scan(read(site_dir / name)).unlinked_text;
    const std::size_t at = unlinked.find("impulse::");
    CHECK(unlinked.substr(at == std::string::npos ? unlinked.size() : at, 60) == "");
  }
}

TEST_CASE("no page or stylesheet of the site refers to anything outside it", "[docs]") {
  require_site();
  for (const fs::path& page : site_files(".html")) {
    CAPTURE(page.filename().string());
    CHECK(outside_resources(scan(read(page))) == std::vector<std::string>{});
  }
  for (const fs::path& sheet : site_files(".css")) {
    CAPTURE(sheet.filename().string());
    const std::string css = read(sheet);
    CHECK(css.find("url(http") == std::string::npos);
    CHECK(css.find("url(\"http") == std::string::npos);
    CHECK(css.find("url('http") == std::string::npos);
    CHECK(css.find("@import") == std::string::npos);
  }
}

TEST_CASE("every internal link of the site leads to a file and an anchor that exist", "[docs]") {
  require_site();
  const std::vector<fs::path> pages = site_files(".html");
  REQUIRE(pages.size() > promised_pages.size());
  for (const fs::path& page : pages) {
    CAPTURE(page.filename().string());
    const std::string html = read(page);
    CHECK(broken_links(page, html, scan(html)) == std::vector<std::string>{});
  }
}

TEST_CASE("the detectors find an outside resource and broken links in a page made so", "[docs]") {
  require_site();
  const Scratch scratch;
  // A script from a host outside, and two links that lead nowhere.
  const std::string html =
      "<html><head><script src=\"https://example.invalid/tracker.js\"></script></head><body>"
      "<a href=\"missing.html\">gone</a> <a href=\"broken.html#nowhere\">no anchor</a> "
      "<a href=\"https://example.invalid/\">a link out is not a load</a></body></html>";
  const fs::path page = scratch.path / "broken.html";
  write(page, html);
  const Scanned scanned = scan(html);
  CHECK(outside_resources(scanned).size() == 1);
  const std::vector<std::string> broken = broken_links(page, html, scanned);
  CAPTURE(broken);
  CHECK(broken.size() == 2);
}
