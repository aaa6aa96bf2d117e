// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/scene/json.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <set>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/core/normal.hpp"
#include "impulse/core/text.hpp"
#include "impulse/scene/report.hpp"

namespace impulse::scene {

namespace {

using Eigen::Vector2d;
// The scene is read as the reports are written, with the members of an object in the file's
// order: one kind of JSON value in the program (each kind costs collide.html's module 16 KB).
using json = nlohmann::ordered_json;

// What a value is, for "expected …, got …".
std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return value.get<bool>() ? "true" : "false";
    case json::value_t::string: {
      std::string text = value.dump(-1, ' ', true);
      if (text.size() > 40) {
        text = text.substr(0, 36).append("…\"");
      }
      return "the string " + text;
    }
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return "the number " + value.dump();
    case json::value_t::array:
      return "an array of " + std::to_string(value.size()) +
             (value.size() == 1 ? " element" : " elements");
    case json::value_t::object:
      return "an object";
    default:
      return "a value of another type";
  }
}

// Edit distance, for "did you mean" on an unknown key.
std::size_t distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) {
    row[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0U : 1U)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// ---------------------------------------------------------------------------------------------
// Parsing: nlohmann-json builds the document; a callback follows the place being read, so that
// a repeated key and a number out of range can be named (the parser does not say where).

struct Frame {
  bool object = true;
  std::size_t index = 0;  // arrays: the element being read
  std::string key;        // objects: the member being read
  std::set<std::string, std::less<>> keys;
};

class Tracker {
 public:
  Tracker(std::string_view source, const ReadLimits& limits) : source_(source), limits_(limits) {}

  std::string place() const {
    std::string path;
    for (const Frame& f : frames_) {
      path = f.object ? (f.key.empty() ? path : member_place(path, f.key))
                      : element_place(path, f.index);
    }
    return path;
  }

  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
        frames_.push_back({true, 0, {}, {}});
        break;
      case json::parse_event_t::array_start:
        frames_.push_back({false, 0, {}, {}});
        break;
      case json::parse_event_t::key: {
        Frame& top = frames_.back();
        top.key = parsed.get<std::string>();
        if (!top.keys.insert(top.key).second) {
          std::string message(source_);
          message.append(": ").append(place()).append(": key repeated in the same object");
          throw InvalidInput(message);
        }
        if (top.keys.size() > limits_.max_keys) {
          std::string message(source_);
          message.append(": ").append(place()).append(": more than ");
          message.append(std::to_string(limits_.max_keys)).append(" keys in one object");
          message.append(", the most a scene may hold");
          throw InvalidInput(message);
        }
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        frames_.pop_back();
        next_element();
        break;
      case json::parse_event_t::value:
        next_element();
        break;
    }
    return true;
  }

 private:
  void next_element() {
    if (!frames_.empty() && !frames_.back().object) {
      ++frames_.back().index;
      refuse_too_many();
    }
  }

  // The scene's `bodies` and `contacts` are counted as they are read: an array beyond its limit
  // is refused at the first element too many, before the rest of it is parsed.
  void refuse_too_many() const {
    if (frames_.size() != 2 || !frames_[0].object) {
      return;
    }
    const std::string& key = frames_[0].key;
    const std::size_t limit = key == "bodies"     ? limits_.max_bodies
                              : key == "contacts" ? limits_.max_contacts
                                                  : 0;
    if (limit == 0 || frames_[1].index <= limit) {
      return;
    }
    std::string message(source_);
    message.append(": ").append(key).append(": more than ").append(std::to_string(limit));
    message.append(" ").append(key).append(", the most a scene may hold");
    throw InvalidInput(message);
  }

  std::string source_;
  ReadLimits limits_;
  std::vector<Frame> frames_;
};

// The line and column (both from 1) of the byte nlohmann-json reports: the count of bytes read
// when the error was found, so the offending byte is the one before it.
std::pair<std::size_t, std::size_t> line_and_column(std::string_view text, std::size_t byte) {
  const std::size_t offset = std::min(byte == 0 ? 0 : byte - 1, text.size());
  const std::string_view before = text.substr(0, offset);
  const auto line = static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n')) + 1;
  const std::size_t newline = before.rfind('\n');
  const std::size_t column = newline == std::string_view::npos ? offset + 1 : offset - newline;
  return {line, column};
}

// nlohmann-json's message without its "[json.exception…] parse error at line…, column…: ",
// and with the bytes it quotes from the input that are not printable ASCII written as \xNN
// (it quotes an ill-formed UTF-8 byte as it is).
std::string reason(const json::exception& e) {
  std::string text;
  for (const char c : std::string_view(e.what())) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      text.push_back(c);
    } else {
      std::array<char, 8> escaped{};
      std::snprintf(escaped.data(), escaped.size(), "\\x%02X", byte);
      text.append(escaped.data());
    }
  }
  if (const std::size_t end = text.find("] "); end != std::string::npos) {
    text.erase(0, end + 2);
  }
  if (text.starts_with("parse error")) {
    if (const std::size_t colon = text.find(": "); colon != std::string::npos) {
      text.erase(0, colon + 2);
    }
  }
  return text;
}

// Refuses arrays and objects nested deeper than the limit before the parser sees them: every
// level costs the parser and the document memory. Brackets inside strings do not count; the
// syntax itself is left to the parser.
void refuse_deep_nesting(std::string_view text, std::string_view source, std::size_t max_depth) {
  std::size_t depth = 0;
  bool in_string = false;
  bool escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) {
        const auto [line, column] = line_and_column(text, i + 1);
        std::string message(source);
        message.append(": line ").append(std::to_string(line));
        message.append(", column ").append(std::to_string(column));
        message.append(": arrays and objects nested more than ").append(std::to_string(max_depth));
        message.append(" deep (a scene needs 4)");
        throw InvalidInput(message);
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

json parse_document(std::string_view text, std::string_view source, const ReadLimits& limits) {
  if (text.size() > limits.max_bytes) {
    throw InvalidInput(too_large_message(source, limits.max_bytes));
  }
  refuse_deep_nesting(text, source, limits.max_depth);
  Tracker tracker(source, limits);
  try {
    // The parser turns a number beyond the range of doubles ("1e999") into its own error, which
    // the reader reports; strtod, which reads the number, raises the overflow exception on the
    // way. A caller that traps floating-point exceptions must get that report, not a SIGFPE.
    const impulse::detail::HeldFloatingPointExceptions held;
    return json::parse(text.begin(), text.end(), std::ref(tracker));
  } catch (const json::parse_error& e) {
    const auto [line, column] = line_and_column(text, e.byte);
    std::string message(source);
    message.append(": line ").append(std::to_string(line));
    message.append(", column ").append(std::to_string(column)).append(": ").append(reason(e));
    throw InvalidInput(message);
  } catch (const json::exception& e) {
    // e.g. out_of_range.406, a number beyond the range of doubles: the tracker knows where.
    std::string message(source);
    const std::string place = tracker.place();
    message.append(": ").append(place.empty() ? "(top level)" : place).append(": ");
    message.append(reason(e));
    throw InvalidInput(message);
  }
}

// ---------------------------------------------------------------------------------------------
// Reading the document into a Scene.

const std::vector<std::string_view> top_keys{"dimension", "elasticity", "bodies",
                                             "contacts",  "solver",     "friction"};
const std::vector<std::string_view> body_keys{"name",
                                              "kind",
                                              "mass",
                                              "inertia",
                                              "position",
                                              "velocity",
                                              "momentum",
                                              "angular_velocity",
                                              "angular_momentum",
                                              "elasticity"};
const std::vector<std::string_view> material_keys{"name",     "kind",     "mass",
                                                  "velocity", "momentum", "elasticity"};
const std::vector<std::string_view> rigid_keys = body_keys;
const std::vector<std::string_view> static_keys{"name", "kind"};
const std::vector<std::string_view> contact_keys{"bumper",       "wedge", "normal",
                                                 "normal_angle", "point", "friction"};
const std::vector<std::string_view> solver_keys{"dependent", "inconsistent", "method",
                                                "max_collisions", "restitution"};

std::string join(const std::vector<std::string_view>& words) {
  std::string text;
  for (const std::string_view word : words) {
    text.append(text.empty() ? "" : ", ").append(word);
  }
  return text;
}

class Reader {
 public:
  Reader(std::string_view source, const ReadLimits& limits) : source_(source), limits_(limits) {}

  Scene scene(const json& document) {
    require_object(document, "", "the scene, an object");
    refuse_unknown_keys(document, "", top_keys, top_keys, "");
    Scene scene;
    scene.dimension = dimension(required(document, "", "dimension", "the scene"));
    dimension_ = scene.dimension;
    if (const json* e = optional(document, "elasticity")) {
      scene.elasticity = number(*e, "elasticity");
    }
    if (const json* f = optional(document, "friction")) {
      scene.friction = number(*f, "friction");  // its range is the library's rule
    }
    const json& bodies = required(document, "", "bodies", "the scene");
    require_array(bodies, "bodies", "an array of bodies");
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      scene.bodies.push_back(body(bodies[i], element_place("bodies", i)));
    }
    try {
      // The library's rule, before the contacts look names up: a repeated name is reported as
      // such, not as an unknown one.
      validate_names(scene.bodies);
    } catch (const InvalidInput& e) {
      throw InvalidInput(source_ + ": " + e.what());
    }
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      names_.emplace(scene.bodies[i].name, i);
      ordered_names_.push_back(scene.bodies[i].name);
    }
    const json& contacts = required(document, "", "contacts", "the scene");
    require_array(contacts, "contacts", "an array of contacts");
    for (std::size_t v = 0; v < contacts.size(); ++v) {
      scene.contacts.push_back(contact(contacts[v], element_place("contacts", v)));
    }
    if (const json* s = optional(document, "solver")) {
      solver(*s, "solver", scene);
    }
    return scene;
  }

 private:
  [[noreturn]] void fail(std::string_view path, std::string_view message) const {
    std::string text(source_);
    text.append(": ").append(path.empty() ? "(top level)" : path).append(": ").append(message);
    throw InvalidInput(text);
  }

  [[noreturn]] void expected(const json& value, std::string_view path,
                             std::string_view what) const {
    std::string message("expected ");
    message.append(what).append(", got ").append(describe(value));
    fail(path, message);
  }

  void require_object(const json& value, std::string_view path, std::string_view what) const {
    if (!value.is_object()) {
      expected(value, path, what);
    }
  }

  void require_array(const json& value, std::string_view path, std::string_view what) const {
    if (!value.is_array()) {
      expected(value, path, what);
    }
  }

  // Keys outside `allowed`: a key of `known` that does not apply here, or a typo.
  void refuse_unknown_keys(const json& object, std::string_view path,
                           const std::vector<std::string_view>& allowed,
                           const std::vector<std::string_view>& known,
                           std::string_view kind) const {
    for (const auto& [key, value] : object.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) {
        continue;
      }
      if (std::find(known.begin(), known.end(), key) != known.end()) {
        std::string message("does not apply to a ");
        message.append(kind).append(" body (its keys are ").append(join(allowed)).append(")");
        fail(member_place(path, key), message);
      }
      std::string message("unknown key");
      std::string_view nearest;
      std::size_t best = 3;  // suggest only close matches
      for (const std::string_view candidate : known) {
        const std::size_t d = distance(key, candidate);
        if (d < best && d < candidate.size()) {
          best = d;
          nearest = candidate;
        }
      }
      if (!nearest.empty()) {
        message.append(" (did you mean ").append(in_quotes(nearest)).append("?)");
      }
      message.append("; expected one of ").append(join(known));
      fail(member_place(path, key), message);
    }
  }

  static const json* optional(const json& object, std::string_view key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  const json& required(const json& object, std::string_view path, std::string_view key,
                       std::string_view owner) const {
    if (const json* value = optional(object, key)) {
      return *value;
    }
    std::string message("missing ");
    message.append(in_quotes(key)).append(", which ").append(owner).append(" needs");
    fail(path, message);
  }

  double number(const json& value, std::string_view path) const {
    if (!value.is_number()) {
      expected(value, path, "a number");
    }
    return value.get<double>();
  }

  std::string string(const json& value, std::string_view path) const {
    if (!value.is_string()) {
      expected(value, path, "a string");
    }
    return value.get<std::string>();
  }

  int dimension(const json& value) const {
    if (value.is_number()) {
      const double d = value.get<double>();
      if (d == 1.0 || d == 2.0) {
        return static_cast<int>(d);
      }
    }
    expected(value, "dimension", "1 or 2");
  }

  // A vector of the scene's dimension: a number in 1D (the x coordinate), [x, y] in 2D.
  Vector2d vector(const json& value, std::string_view path) const {
    if (dimension_ == 1) {
      if (!value.is_number()) {
        expected(value, path, "a number (the scene has dimension 1)");
      }
      return {value.get<double>(), 0.0};
    }
    if (!value.is_array() || value.size() != 2) {
      expected(value, path, "[x, y], an array of 2 numbers (the scene has dimension 2)");
    }
    return {number(value[0], element_place(path, 0)), number(value[1], element_place(path, 1))};
  }

  // A name of the enum's table (impulse::EnumNames), or a refusal that lists them.
  template <typename Enum>
  Enum member_of(const json& value, std::string_view path) const {
    const std::string text = string(value, path);
    if (const auto choice = value_named<Enum>(text)) {
      return *choice;
    }
    fail(path, "expected one of " + quoted_names<Enum>() + ", got " + in_quotes(text));
  }

  Body body(const json& value, const std::string& path) const {
    require_object(value, path, "a body, an object");
    refuse_unknown_keys(value, path, body_keys, body_keys, "");
    Body b;
    b.name = string(required(value, path, "name", "every body"), member_place(path, "name"));
    b.kind = member_of<BodyKind>(required(value, path, "kind", "every body"),
                                 member_place(path, "kind"));
    const std::string kind(name_of(b.kind));
    switch (b.kind) {
      case BodyKind::material:
        refuse_unknown_keys(value, path, material_keys, body_keys, kind);
        break;
      case BodyKind::rigid:
        refuse_unknown_keys(value, path, rigid_keys, body_keys, kind);
        break;
      case BodyKind::static_body:
        refuse_unknown_keys(value, path, static_keys, body_keys, kind);
        return b;  // immovable: nothing more to read
    }
    const std::string owner = "a " + kind + " body";
    b.mass = number(required(value, path, "mass", owner), member_place(path, "mass"));
    const json* velocity = optional(value, "velocity");
    const json* momentum = optional(value, "momentum");
    if (velocity != nullptr && momentum != nullptr) {
      fail(path, "give either \"velocity\" or \"momentum\", not both");
    }
    if (velocity == nullptr && momentum == nullptr) {
      fail(path, "missing \"velocity\" (or \"momentum\"), which " + owner + " needs");
    }
    b.linear_given = velocity != nullptr ? Given::velocity : Given::momentum;
    b.linear = vector(velocity != nullptr ? *velocity : *momentum,
                      member_place(path, velocity != nullptr ? "velocity" : "momentum"));
    if (b.kind == BodyKind::rigid) {
      b.inertia = number(required(value, path, "inertia", owner), member_place(path, "inertia"));
      b.position = vector(required(value, path, "position", owner), member_place(path, "position"));
      const json* omega = optional(value, "angular_velocity");
      const json* L = optional(value, "angular_momentum");
      if (omega != nullptr && L != nullptr) {
        fail(path, "give either \"angular_velocity\" or \"angular_momentum\", not both");
      }
      b.angular_given = L != nullptr ? Given::momentum : Given::velocity;
      if (omega != nullptr) {
        b.angular = number(*omega, member_place(path, "angular_velocity"));
      } else if (L != nullptr) {
        b.angular = number(*L, member_place(path, "angular_momentum"));
      }
    }
    if (const json* e = optional(value, "elasticity")) {
      b.elasticity = number(*e, member_place(path, "elasticity"));
    }
    return b;
  }

  std::size_t body_named(const json& value, const std::string& path) const {
    const std::string name = string(value, path);
    if (const auto it = names_.find(name); it != names_.end()) {
      return it->second;
    }
    std::string known;
    std::size_t listed = 0;
    for (const std::string& other : ordered_names_) {
      if (++listed > 8) {
        known.append(", …");
        break;
      }
      known.append(known.empty() ? "" : ", ").append(in_quotes(other));
    }
    fail(path, "no body is named " + in_quotes(name) + " (the bodies are " + known + ")");
  }

  Contact contact(const json& value, const std::string& path) const {
    require_object(value, path, "a contact, an object");
    refuse_unknown_keys(value, path, contact_keys, contact_keys, "");
    Contact c;
    c.bumper =
        body_named(required(value, path, "bumper", "every contact"), member_place(path, "bumper"));
    c.wedge =
        body_named(required(value, path, "wedge", "every contact"), member_place(path, "wedge"));
    const json* normal = optional(value, "normal");
    const json* angle = optional(value, "normal_angle");
    if (normal != nullptr && angle != nullptr) {
      fail(path, "give either \"normal\" or \"normal_angle\", not both");
    }
    if (normal == nullptr && angle == nullptr) {
      fail(path, "missing \"normal\" (or \"normal_angle\"), which every contact needs");
    }
    if (normal != nullptr) {
      c.normal = vector(*normal, member_place(path, "normal"));
    } else if (dimension_ != 2) {
      fail(member_place(path, "normal_angle"),
           "does not apply in dimension 1 (give \"normal\": +1 or -1)");
    } else {
      // Degrees counter-clockwise from the x axis, exact at multiples of 90 (a finite number:
      // the reader refuses any other).
      c.normal =
          UnitNormal::from_degrees(number(*angle, member_place(path, "normal_angle"))).vector();
    }
    if (const json* point = optional(value, "point")) {
      c.point = vector(*point, member_place(path, "point"));
    }
    if (const json* f = optional(value, "friction")) {
      c.friction = number(*f, member_place(path, "friction"));  // its range is the library's rule
    }
    return c;
  }

  void solver(const json& value, const std::string& path, Scene& scene) const {
    require_object(value, path,
                   "an object with \"dependent\", \"inconsistent\", \"method\", "
                   "\"max_collisions\" and/or \"restitution\"");
    refuse_unknown_keys(value, path, solver_keys, solver_keys, "");
    SolverOptions& options = scene.solver;
    if (const json* d = optional(value, "dependent")) {
      options.dependent = member_of<DependentPolicy>(*d, member_place(path, "dependent"));
    }
    if (const json* i = optional(value, "inconsistent")) {
      options.inconsistent = member_of<InconsistentPolicy>(*i, member_place(path, "inconsistent"));
    }
    if (const json* m = optional(value, "method")) {
      scene.method = member_of<methods::Method>(*m, member_place(path, "method"));
    }
    if (const json* r = optional(value, "restitution")) {
      scene.restitution =
          member_of<friction::RestitutionLaw>(*r, member_place(path, "restitution"));
    }
    if (const json* c = optional(value, "max_collisions")) {
      // The type is a whole number of collisions, at least 1 (0 is not written: a scene without
      // the key gets the default); the bound above is the scene's rule, the same number.
      const std::string where = member_place(path, "max_collisions");
      const double most = static_cast<double>(methods::most_collisions);
      const double bound = c->is_number() ? c->get<double>() : 0.0;
      if (!(bound >= 1.0 && bound <= most && bound == std::floor(bound))) {
        expected(*c, where, "a whole number from 1 to " + std::to_string(methods::most_collisions));
      }
      scene.serial.max_collisions = static_cast<std::int64_t>(bound);
    }
  }

  std::string source_;
  ReadLimits limits_;
  int dimension_ = 2;
  std::unordered_map<std::string, std::size_t> names_;
  std::vector<std::string> ordered_names_;
};

// ---------------------------------------------------------------------------------------------
// Writing the report.

double clean(double x) {
  return x + 0.0;  // -0 becomes +0; everything else is unchanged
}

nlohmann::ordered_json vector_json(const Vector2d& v, int dimension) {
  if (dimension == 1) {
    return clean(v.x());
  }
  return nlohmann::ordered_json::array({clean(v.x()), clean(v.y())});
}

}  // namespace

std::string too_large_message(std::string_view source, std::size_t max_bytes) {
  std::string message(source);
  message.append(": holds more than ").append(std::to_string(max_bytes)).append(" bytes");
  if (max_bytes % (std::size_t{1} << 20U) == 0) {
    message.append(" (").append(std::to_string(max_bytes >> 20U)).append(" MiB)");
  }
  message.append(", the most a scene file may hold");
  return message;
}

World parse_world(std::string_view text, std::string_view source, const ReadLimits& limits) {
  const json document = parse_document(text, source, limits);
  Scene scene;
  try {
    scene = Reader(source, limits).scene(document);
  } catch (const json::exception& e) {
    // Not expected (every access is checked first), but never let it escape unexplained.
    std::string message(source);
    message.append(": ").append(reason(e));
    throw InvalidInput(message);
  }
  try {
    return World(std::move(scene));  // the scene format's rules: the library's, with the place
  } catch (const InvalidInput& e) {
    std::string message(source);
    message.append(": ").append(e.what());
    throw InvalidInput(message);
  }
}

Scene parse_scene(std::string_view text, std::string_view source, const ReadLimits& limits) {
  return parse_world(text, source, limits).scene();
}

namespace {
nlohmann::ordered_json value_json(const methods::Value& value) {
  return std::visit(
      [](const auto& v) -> nlohmann::ordered_json {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, double>) {
          return clean(v);
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          nlohmann::ordered_json list = nlohmann::ordered_json::array();
          for (const double x : v) {
            list.push_back(clean(x));
          }
          return list;
        } else {
          return v;
        }
      },
      value);
}
}  // namespace

nlohmann::ordered_json to_json(const Result& result) {
  using ojson = nlohmann::ordered_json;
  const int d = result.dimension;
  const methods::Outcome& o = result.outcome;
  ojson out = ojson::object();

  ojson impulses = ojson::array();
  for (std::size_t v = 0; v < result.impulses.size(); ++v) {
    const ImpulseReport& i = result.impulses[v];
    ojson entry = {{"contact", i.contact},
                   {"bumper", i.bumper},
                   {"wedge", i.wedge},
                   {"magnitude", clean(i.magnitude)},
                   {"on_bumper", vector_json(i.on_bumper, d)}};
    for (const methods::ContactColumn& column : o.per_contact) {
      std::visit(
          [&](const auto& values) {
            if (v < values.size()) {
              entry[column.key] = value_json(methods::Value(values[v]));
            }
          },
          column.values);
    }
    impulses.push_back(std::move(entry));
  }
  out["impulses"] = std::move(impulses);

  ojson bodies = ojson::array();
  for (const BodyReport& b : result.bodies) {
    ojson body = {{"name", b.name},
                  {"velocity", vector_json(b.after.velocity, d)},
                  {"momentum", vector_json(b.after.momentum, d)}};
    if (b.kind == BodyKind::rigid) {
      body["angular_velocity"] = clean(b.after.angular_velocity);
      body["angular_momentum"] = clean(b.after.angular_momentum);
    }
    bodies.push_back(std::move(body));
  }
  out["bodies"] = std::move(bodies);

  out["energy"] = {{"before", clean(result.energy_before)},
                   {"after", clean(result.energy_after)},
                   {"change", clean(result.energy_change)}};
  out["momentum"] = {{"before", vector_json(result.momentum_before, d)},
                     {"after", vector_json(result.momentum_after, d)}};

  ojson contacts = ojson::array();
  for (const ContactReport& c : result.contacts) {
    contacts.push_back({{"contact", c.contact},
                        {"approach_before", clean(c.approach_before)},
                        {"approach_after", clean(c.approach_after)}});
  }
  out["contacts"] = std::move(contacts);

  const Solution& s = result.system;
  ojson system = ojson::object();
  if (s.A.rows() == s.B.size() && s.A.cols() == s.B.size() && s.A.size() > 0) {
    ojson A = ojson::array();
    for (Eigen::Index r = 0; r < s.A.rows(); ++r) {
      ojson row = ojson::array();
      for (Eigen::Index c = 0; c < s.A.cols(); ++c) {
        row.push_back(clean(s.A(r, c)));
      }
      A.push_back(std::move(row));
    }
    system["A"] = std::move(A);
  } else {
    system["A"] = nullptr;  // not formed by the solver
  }
  ojson B = ojson::array();
  for (Eigen::Index r = 0; r < s.B.size(); ++r) {
    B.push_back(clean(s.B(r)));
  }
  system["B"] = std::move(B);
  system["rank"] = s.rank;
  system["residual"] = clean(o.residual);  // of the impulses reported
  system["dependent"] = s.dependent;
  system["consistent"] = s.consistent;
  system["policy"] = std::string(name_of(s.options.dependent));
  system["condition_estimate"] = s.condition_estimate;
  out["system"] = std::move(system);

  // The method's own diagnostics, after the keys the scene format specifies; the paper's method
  // has none, so that its report is exactly the specified one.
  if (!o.diagnostics.empty()) {
    const std::string name(name_of(result.method));
    out["method"] = name;
    ojson block = ojson::object();
    for (const methods::Field& field : o.diagnostics) {
      block[field.key] = value_json(field.value);
    }
    out[name] = std::move(block);
  }
  if (!result.notes.empty()) {
    out["notes"] = result.notes;
  }
  return out;
}

std::string report_json(const Result& result) {
  return to_json(result).dump(2) + "\n";
}

std::string report_json(const Run& run, std::string_view source) {
  const Result& first = run.results.front();
  if (run.request.compare == Request::Compare::nothing) {
    return first.outcome.finished ? report_json(first) : "";
  }
  // A comparison: one member per method (or law), each naming it, even the paper's method,
  // whose own report names none.
  const bool laws = run.request.compare == Request::Compare::laws;
  const std::string key = laws ? "restitution" : "method";
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < run.results.size(); ++k) {
    const Result& r = run.results[k];
    const std::string name(laws ? EnumNames<friction::RestitutionLaw>::table[k].name
                                : name_of(r.method));
    if (!r.outcome.finished) {
      out[name] = {{key, name}, {"error", unfinished_message(r, source)}};
      continue;
    }
    out[name] = to_json(r);
    if (!out[name].contains(key)) {
      out[name][key] = name;
    }
  }
  return out.dump(2) + "\n";
}

JsonRun solve_to_json(std::string_view text, std::string_view source, const Request& request,
                      const ReadLimits& limits) {
  JsonRun out{run(parse_world(text, source, limits), source, request), {}};
  out.report = report_json(out.run, source);
  return out;
}

}  // namespace impulse::scene
