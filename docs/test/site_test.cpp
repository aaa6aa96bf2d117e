// SPDX-License-Identifier: GPL-3.0-or-later
// The documentation site as a reader sees it: its pages opened from disk in headless Chromium, with
// every host name unresolvable, as on a machine without a network. Every formula must have been
// typeset by MathJax (its output present, no raw TeX left in the visible text, each \tag shown),
// no page may request anything from outside the site, and every internal link must land on a file
// and an anchor that exist. The last test case feeds the same detectors a page that is broken on
// purpose, so that they are seen to fail.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

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

// --- A small HTML scanner: tags with their attributes, and the text a reader sees ---------------

struct Tag {
  std::string name;  // lower case; "/a" for a closing tag
  std::map<std::string, std::string> attributes;
};

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool is_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_' || c == ':' ||
         c == '/';
}

// Parses the tag that starts at html[begin] == '<'; returns the index after its '>'.
std::size_t parse_tag(const std::string& html, std::size_t begin, Tag& tag) {
  std::size_t i = begin + 1;
  const std::size_t name_begin = i;
  while (i < html.size() && is_name_char(html[i])) {
    ++i;
  }
  tag.name = lower(html.substr(name_begin, i - name_begin));
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
    const std::string key = lower(html.substr(key_begin, i - key_begin));
    std::string value;
    if (i < html.size() && html[i] == '=') {
      ++i;
      if (i < html.size() && (html[i] == '"' || html[i] == '\'')) {
        const char quote = html[i];
        const std::size_t end = html.find(quote, i + 1);
        value = html.substr(i + 1, end - i - 1);
        i = end == std::string::npos ? html.size() : end + 1;
      } else {
        const std::size_t value_begin = i;
        while (i < html.size() && html[i] != '>' &&
               std::isspace(static_cast<unsigned char>(html[i])) == 0) {
          ++i;
        }
        value = html.substr(value_begin, i - value_begin);
      }
    }
    tag.attributes[key] = value;
  }
  return i < html.size() ? i + 1 : i;
}

struct Scanned {
  std::vector<Tag> tags;
  std::string visible_text;   // text outside tags, scripts, styles and comments
  std::string prose_text;     // the part of it that is not code (<code>, <pre>, Doxygen's
                              // fragments): where LaTeX source shown on purpose cannot be
  std::string unlinked_text;  // the part of it that is not inside a link
  std::vector<std::string> script_texts;
};

Scanned scan(const std::string& html) {
  Scanned result;
  std::size_t i = 0;
  int link_depth = 0;
  int code_depth = 0;
  std::vector<bool> fragment_divs;  // for each open <div>: is it (inside) a code fragment?
  while (i < html.size()) {
    const std::size_t open = html.find('<', i);
    const std::string text =
        html.substr(i, open == std::string::npos ? std::string::npos : open - i);
    result.visible_text += text;
    const bool in_fragment = !fragment_divs.empty() && fragment_divs.back();
    if (code_depth == 0 && !in_fragment) {
      result.prose_text += text;
    }
    if (link_depth == 0) {
      result.unlinked_text += text;
    }
    if (open == std::string::npos) {
      break;
    }
    if (html.compare(open, 4, "<!--") == 0) {
      const std::size_t end = html.find("-->", open + 4);
      i = end == std::string::npos ? html.size() : end + 3;
      continue;
    }
    Tag tag;
    i = parse_tag(html, open, tag);
    if (tag.name == "script" || tag.name == "style") {
      // Browsers and Doxygen write tag names in lower case.
      const std::size_t close = html.find("</" + tag.name, i);
      const std::size_t end = close == std::string::npos ? html.size() : close;
      if (tag.name == "script") {
        result.script_texts.push_back(html.substr(i, end - i));
      }
      i = end;
    }
    link_depth += tag.name == "a" ? 1 : tag.name == "/a" ? -1 : 0;
    const bool code = tag.name == "code" || tag.name == "pre" || tag.name == "tt";
    const bool code_end = tag.name == "/code" || tag.name == "/pre" || tag.name == "/tt";
    code_depth += code ? 1 : code_end && code_depth > 0 ? -1 : 0;
    if (tag.name == "div") {
      const auto cls = tag.attributes.find("class");
      const bool fragment = cls != tag.attributes.end() && cls->second == "fragment";
      fragment_divs.push_back(fragment || (!fragment_divs.empty() && fragment_divs.back()));
    } else if (tag.name == "/div" && !fragment_divs.empty()) {
      fragment_divs.pop_back();
    }
    result.tags.push_back(std::move(tag));
  }
  return result;
}

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

// What a page shows as TeX instead of typeset math, and formulas MathJax did not typeset.
std::vector<std::string> untypeset_math(const Scanned& page) {
  std::vector<std::string> problems;
  std::set<std::string> frames;
  std::size_t formulas = 0;
  std::vector<std::string> tags;
  for (const Tag& tag : page.tags) {
    const auto id = tag.attributes.find("id");
    const auto type = tag.attributes.find("type");
    const auto cls = tag.attributes.find("class");
    if (id != tag.attributes.end() && id->second.ends_with("-Frame")) {
      frames.insert(id->second);
    }
    if (cls != tag.attributes.end() &&
        (cls->second == "merror" || cls->second.find("MathJax_Error") != std::string::npos)) {
      problems.push_back("MathJax reports an error (class " + cls->second + ")");
    }
    if (tag.name == "script" && type != tag.attributes.end() &&
        type->second.starts_with("math/tex")) {
      ++formulas;
      const std::string element = id == tag.attributes.end() ? "" : id->second;
      if (!frames.contains(element + "-Frame")) {
        // MathJax puts the output (the frame) just before the script that keeps the source.
        problems.push_back("formula " + element + " has no typeset output");
      }
    }
  }
  if (formulas == 0) {
    problems.push_back("no formula was handed to MathJax (no math/tex script in the page)");
  }
  for (const std::string& script : page.script_texts) {
    for (std::size_t at = script.find("\\tag{"); at != std::string::npos;
         at = script.find("\\tag{", at + 1)) {
      const std::size_t end = script.find('}', at);
      tags.push_back(script.substr(at + 5, end - at - 5));
    }
  }
  for (const std::string& tag : tags) {
    bool shown = false;
    for (const Tag& t : page.tags) {
      const auto id = t.attributes.find("id");
      shown = shown || (id != t.attributes.end() && id->second == "mjx-eqn-" + tag);
    }
    if (!shown) {
      problems.push_back("the equation number (" + tag + ") is not shown");
    }
  }
  for (const char* raw : {"\\f$", "\\f[", "\\f]", "\\(", "\\)", "\\[", "\\]", "\\frac", "\\tag",
                          "\\vec", "\\det", "\\sum", "\\left", "\\mathrm", "\\begin"}) {
    const std::size_t at = page.prose_text.find(raw);
    if (at != std::string::npos) {
      const std::size_t from = at > 40 ? at - 40 : 0;
      problems.push_back("raw TeX in the visible text: \"" + page.prose_text.substr(from, 100) +
                         "\"");
    }
  }
  if (page.visible_text.find("Math Processing Error") != std::string::npos) {
    problems.push_back("MathJax shows \"Math Processing Error\"");
  }
  return problems;
}

// --- Chromium ------------------------------------------------------------------------------------

struct Opened {
  std::string dom;                   // the document after its scripts ran
  std::vector<std::string> outside;  // URLs the page asked the network for
};

std::string chromium() {
  const char* chosen = std::getenv("IMPULSELAB_CHROMIUM");
  return chosen != nullptr && *chosen != '\0' ? chosen : "chromium";
}

std::string quoted(const std::string& text) {
  std::string result = "'";
  for (const char c : text) {
    result += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return result + "'";
}

// Requests made on behalf of a file:// page. The network log also holds the browser's own
// requests (updates, accounts), which run in no page's network partition.
std::vector<std::string> page_requests(const fs::path& net_log) {
  std::string text = read(net_log);
  nlohmann::json log = nlohmann::json::parse(text, nullptr, false);
  if (log.is_discarded()) {
    log = nlohmann::json::parse(text + "]}", nullptr, false);  // a log cut short at exit
  }
  if (log.is_discarded() || !log.contains("constants") || !log.contains("events")) {
    throw std::runtime_error("cannot read Chromium's network log " + net_log.string());
  }
  const auto& types = log["constants"]["logEventTypes"];
  if (!types.contains("URL_REQUEST_START_JOB")) {
    throw std::runtime_error("Chromium's network log names no URL_REQUEST_START_JOB events");
  }
  const int start_job = types["URL_REQUEST_START_JOB"].get<int>();
  std::vector<std::string> urls;
  for (const auto& event : log["events"]) {
    if (event.value("type", -1) != start_job || !event.contains("params")) {
      continue;
    }
    const auto& params = event["params"];
    const std::string partition = params.value("network_isolation_key", "");
    const std::string site = params.value("site_for_cookies", "");
    const std::string initiator = params.value("initiator", "");
    if (partition.find("file://") != std::string::npos ||
        site.find("file://") != std::string::npos || initiator == "null") {
      urls.push_back(params.value("url", "?"));
    }
  }
  return urls;
}

Opened open_in_chromium(const fs::path& page) {
  const Scratch scratch;
  const fs::path dom = scratch.path / "dom.html";
  const fs::path log = scratch.path / "net-log.json";
  const std::string command =
      quoted(chromium()) +
      " --headless --no-sandbox --disable-gpu --disable-background-networking"
      " --disable-component-update --disable-sync --no-first-run --virtual-time-budget=10000"
      " '--host-resolver-rules=MAP * ~NOTFOUND'" +
      " --user-data-dir=" + quoted((scratch.path / "profile").string()) +
      " --log-net-log=" + quoted(log.string()) + " --dump-dom " +
      quoted("file://" + fs::absolute(page).string()) + " > " + quoted(dom.string()) + " 2> " +
      quoted((scratch.path / "stderr.txt").string());
  const int status = std::system(command.c_str());
  if (status != 0 || !fs::exists(dom) || fs::file_size(dom) == 0) {
    std::string error = fs::exists(scratch.path / "stderr.txt")
                            ? read(scratch.path / "stderr.txt").substr(0, 2000)
                            : std::string();
    throw std::runtime_error("Chromium did not open " + page.string() + " (status " +
                             std::to_string(status) + "; is `chromium` installed? " +
                             "scripts/install-deps chromium):\n" + error);
  }
  return {read(dom), page_requests(log)};
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

// Pages that hand formulas to MathJax; the header sources Doxygen lists verbatim are code.
std::vector<fs::path> pages_with_math() {
  std::vector<fs::path> pages;
  for (const fs::path& page : site_files(".html")) {
    const std::string name = page.filename().string();
    const std::string html = read(page);
    if (!name.ends_with("_source.html") &&
        (html.find("\\(") != std::string::npos || html.find("\\[") != std::string::npos)) {
      pages.push_back(page);
    }
  }
  return pages;
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
    CHECK(html.find("href=\"check_report.html#check-") != std::string::npos);
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

TEST_CASE("in Chromium every formula is typeset by MathJax and no page asks for anything outside",
          "[docs]") {
  require_site();
  std::vector<fs::path> pages = pages_with_math();
  for (const std::string& name : promised_pages) {
    if (std::find(pages.begin(), pages.end(), site_dir / name) == pages.end() &&
        name != "labs.html") {  // the labs index has formulas only once labs exist
      pages.push_back(site_dir / name);
    }
  }
  for (const fs::path& page : pages) {
    CAPTURE(page.filename().string());
    const Opened opened = open_in_chromium(page);
    const Scanned dom = scan(opened.dom);
    CHECK(untypeset_math(dom) == std::vector<std::string>{});
    CHECK(opened.outside == std::vector<std::string>{});
    CHECK(outside_resources(dom) == std::vector<std::string>{});
    CHECK(broken_links(page, opened.dom, dom) == std::vector<std::string>{});
  }
  // Every section page but section 2 (which has no numbered equation) shows its numbers.
  for (const std::string& name : section_pages) {
    CAPTURE(name);
    const std::string html = read(site_dir / name);
    CHECK((name == "section2.html" || html.find("\\tag{") != std::string::npos));
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

TEST_CASE("the detectors find raw TeX, an outside request and broken links in a page made so",
          "[docs]") {
  require_site();
  const Scratch scratch;
  fs::create_directory_symlink(fs::absolute(site_dir / "mathjax"), scratch.path / "mathjax");
  // MathJax configured as the site configures it; one formula typesets, one \frac is left raw in
  // the text, a script comes from a host outside, and two links lead nowhere.
  const std::string head =
      "<html><head><script type=\"text/x-mathjax-config\">MathJax.Hub.Config({extensions: "
      "[\"tex2jax.js\", \"TeX/AMSmath.js\"], jax: [\"input/TeX\", \"output/HTML-CSS\"]});"
      "</script><script type=\"text/javascript\" async=\"async\" src=\"mathjax/MathJax.js\">"
      "</script>";
  const std::string body =
      "<body><p>\\[ a = b \\tag{9.9} \\]</p><p>Raw: \\frac{1}{2}</p>"
      "<a href=\"missing.html\">gone</a> <a href=\"broken.html#nowhere\">no anchor</a></body>"
      "</html>";
  write(scratch.path / "broken.html",
        head + "<script src=\"https://example.invalid/tracker.js\"></script></head>" + body);

  const fs::path page = scratch.path / "broken.html";
  const Opened opened = open_in_chromium(page);
  const Scanned dom = scan(opened.dom);
  const std::vector<std::string> math = untypeset_math(dom);
  CAPTURE(math);
  REQUIRE(math.size() == 1);  // only the raw \frac: the formula and its tag did typeset
  CHECK(math[0].find("\\frac{1}{2}") != std::string::npos);
  CHECK(opened.outside == std::vector<std::string>{"https://example.invalid/tracker.js"});
  CHECK(outside_resources(dom).size() == 1);
  CHECK(broken_links(page, opened.dom, dom).size() == 2);

  // Without MathJax nothing is typeset at all.
  write(page, "<html><head></head>" + body);
  const std::vector<std::string> untypeset = untypeset_math(scan(open_in_chromium(page).dom));
  CAPTURE(untypeset);
  CHECK(untypeset.size() >= 3);  // no formula handed over, no (9.9), raw \[ and \frac
}
