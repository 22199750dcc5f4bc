// Strict JSON reading (json_read.hpp).

#include "io/json_read.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>
#include <utility>
#include <vector>

#include "breakshot/pool.hpp"
#include "io/json_write.hpp"

namespace breakshot::json_io {

namespace {

bool is_identifier(std::string_view key) {
  if (key.empty()) return false;
  for (char c : key) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                    (c >= '0' && c <= '9') || c == '_';
    if (!ok) return false;
  }
  return true;
}

/// nlohmann's messages start with "[json.exception.parse_error.101] ";
/// the user needs the rest (which has the line and column).
std::string strip_exception_id(std::string_view what) {
  if (!what.empty() && what.front() == '[') {
    const auto close = what.find("] ");
    if (close != std::string_view::npos) what.remove_prefix(close + 2);
  }
  return std::string(what);
}

/// Builds the document from the parser's events, and notices the first
/// key that appears twice in one object. (nlohmann's parse callback could
/// watch for repeats too, but that path is several times slower than this
/// on a 10,000-ball scenario.) The builder keeps an explicit stack, so
/// deep nesting cannot overflow the call stack.
class DocumentBuilder {
 public:
  DocumentBuilder(json& root, const ParseOptions& options)
      : root_(root), free_key_(options.free_key), root_path_(options.root_path) {}

  std::optional<std::string> duplicate_path;  ///< first repeated key
  std::optional<std::string> parse_error_text;

  // The SAX interface of nlohmann::json::sax_parse.
  bool null() { return put(json(nullptr)); }
  bool boolean(bool v) { return put(json(v)); }
  bool number_integer(json::number_integer_t v) { return put(json(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return put(json(v)); }
  bool number_float(json::number_float_t v, const json::string_t& /*text*/) {
    return put(json(v));
  }
  bool string(json::string_t& v) { return put(json(std::move(v))); }
  bool binary(json::binary_t& v) { return put(json::binary(std::move(v))); }
  bool start_object(std::size_t /*size*/) { return open(json::object()); }
  bool start_array(std::size_t /*size*/) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(json::string_t& k) {
    Frame& f = frames_.back();
    if (!f.ignored && !duplicate_path && f.value->contains(k)) {
      duplicate_path = member_path(path_of_open_container(), k);
    }
    f.key = std::move(k);
    return true;
  }

  bool parse_error(std::size_t /*position*/, const std::string& /*last_token*/,
                   const json::exception& ex) {
    parse_error_text = strip_exception_id(ex.what());
    return false;
  }

 private:
  struct Frame {
    json* value = nullptr;  // stable: nothing is added to its parent while it is open
    std::string key;        // key of the value being read (objects)
    bool ignored = false;   // inside an object of the free key
    // Where this container sits in its parent, for messages. The whole
    // path is built only when needed: building it for every container
    // would cost O(depth^2) on a deeply nested document.
    std::string key_in_parent;
    std::size_t index_in_parent = 0;
    bool parent_is_object = false;
  };

  bool put(json&& v) {
    add(std::move(v));
    return true;
  }

  /// Puts a value where the parser is: the root, the current key of the
  /// open object, or the end of the open array.
  json* add(json&& v) {
    if (frames_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    Frame& f = frames_.back();
    if (f.value->is_object()) {
      json& slot = (*f.value)[f.key];
      slot = std::move(v);
      return &slot;
    }
    f.value->push_back(std::move(v));
    return &f.value->back();
  }

  bool open(json&& v) {
    Frame child;
    if (!frames_.empty()) {
      const Frame& parent = frames_.back();
      child.ignored = parent.ignored || (!free_key_.empty() && parent.value->is_object() &&
                                         parent.key == free_key_);
      child.parent_is_object = parent.value->is_object();
      if (child.parent_is_object) {
        child.key_in_parent = parent.key;
      } else {
        child.index_in_parent = parent.value->size();
      }
    }
    child.value = add(std::move(v));
    frames_.push_back(std::move(child));
    return true;
  }

  bool close() {
    frames_.pop_back();
    return true;
  }

  std::string path_of_open_container() const {
    std::string path = root_path_;
    for (std::size_t i = 1; i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      if (f.parent_is_object) {
        append_member(path, f.key_in_parent);
      } else {
        append_index(path, f.index_in_parent);
      }
    }
    return path;
  }

  json& root_;
  std::string_view free_key_;
  std::string root_path_;
  std::vector<Frame> frames_;
};

}  // namespace

// ---------------------------------------------------------------------------
// Paths

void append_member(std::string& path, std::string_view key) {
  if (is_identifier(key)) {
    if (!path.empty()) path += '.';
    path += key;
    return;
  }
  path += "[\"";
  for (char c : key) {
    if (c == '"' || c == '\\') path += '\\';
    path += c;
  }
  path += "\"]";
}

void append_index(std::string& path, std::size_t i) {
  path += '[';
  path += std::to_string(i);
  path += ']';
}

std::string member_path(std::string path, std::string_view key) {
  append_member(path, key);
  return path;
}

std::string index_path(std::string path, std::size_t i) {
  append_index(path, i);
  return path;
}

// ---------------------------------------------------------------------------
// Messages

std::string type_name(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::string: return "a string";
    case json::value_t::array: return "an array";
    case json::value_t::object: return "an object";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "a number";
    case json::value_t::binary: return "binary data";
    case json::value_t::discarded: return "nothing";
  }
  return "an unknown value";
}

std::string expected(std::string_view what, const json& v) {
  return "expected " + std::string(what) + ", not " + type_name(v);
}

std::string one_of(const std::string_view* names, std::size_t n) {
  std::string out;
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) out += k + 1 == n ? " or " : ", ";
    out += '"';
    out += names[k];
    out += '"';
  }
  return out;
}

std::string cushion_model_names() {
  std::vector<std::string_view> names;
  for (const CushionModel m : kCushionModels) names.push_back(cushion_model_name(m));
  return one_of(names.data(), names.size());
}

// ---------------------------------------------------------------------------
// Parsing

std::optional<ParseProblem> parse_strict(std::string_view text, json& out,
                                         const ParseOptions& options) {
  DocumentBuilder builder(out, options);
  const bool parsed = json::sax_parse(text.begin(), text.end(), &builder);
  if (!parsed || builder.parse_error_text) {
    return ParseProblem{{kDocumentPath, builder.parse_error_text.value_or("not valid JSON")}, true};
  }
  if (builder.duplicate_path) return ParseProblem{{*builder.duplicate_path, "duplicate key"}, false};
  return std::nullopt;
}

// ---------------------------------------------------------------------------
// Reading values

std::string Reader::unknown(std::string_view what, std::string_view value,
                            std::string_view known) {
  return "unknown " + std::string(what) + " \"" + std::string(value) + "\" (expected " +
         std::string(known) + ")";
}

bool Reader::require_object(const json& v, const std::string& path) {
  if (v.is_object()) return true;
  return fail(path.empty() ? kDocumentPath : path, expected("an object", v));
}

bool Reader::known_fields(const json& obj, const std::string& path,
                          std::initializer_list<std::string_view> known) {
  for (const auto& [key, value] : obj.items()) {
    if (!free_key_.empty() && key == free_key_) continue;
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string list;
    for (std::string_view k : known) {
      if (!list.empty()) list += ", ";
      list += k;
    }
    return fail(member_path(path, key), "unknown field (known: " + list + ")");
  }
  return true;
}

bool Reader::object(const json& v, const std::string& path,
                    std::initializer_list<std::string_view> known) {
  return require_object(v, path) && known_fields(v, path, known);
}

bool Reader::exact_object(const json& v, const std::string& path,
                          std::initializer_list<std::string_view> names) {
  if (!object(v, path, names)) return false;
  for (std::string_view name : names) {
    if (!v.contains(name)) return fail(member_path(path, name), "missing required field");
  }
  return true;
}

bool Reader::exact_object(const json& v, const std::string& path,
                          const std::vector<std::string_view>& names) {
  if (!require_object(v, path)) return false;
  for (const auto& [key, value] : v.items()) {
    if (!free_key_.empty() && key == free_key_) continue;
    if (std::find(names.begin(), names.end(), key) != names.end()) continue;
    std::string list;
    for (std::string_view k : names) {
      if (!list.empty()) list += ", ";
      list += k;
    }
    return fail(member_path(path, key), "unknown field (known: " + list + ")");
  }
  for (std::string_view name : names) {
    if (!v.contains(name)) return fail(member_path(path, name), "missing required field");
  }
  return true;
}

bool Reader::required(const json& obj, const std::string& path, std::string_view key,
                      const json*& out) {
  out = find(obj, key);
  return out != nullptr || fail(member_path(path, key), "missing required field");
}

bool Reader::array(const json& v, const std::string& path, std::optional<std::size_t> size) {
  if (!v.is_array()) return fail(path, expected("an array", v));
  if (size && v.size() != *size) {
    return fail(path, "expected an array of " + std::to_string(*size) + ", not an array of " +
                          std::to_string(v.size()));
  }
  return true;
}

bool Reader::number(const json& v, const std::string& path, double& out) {
  if (!v.is_number()) return fail(path, expected("a number", v));
  const double x = v.get<double>();
  if (!std::isfinite(x)) return fail(path, "expected a finite number");
  out = x;
  return true;
}

bool Reader::numbers(const json& v, const std::string& path, double* out, std::size_t n) {
  if (!v.is_array() || v.size() != n) {
    const std::string what = "an array of " + std::to_string(n) + " numbers";
    if (v.is_array()) {
      return fail(path, "expected " + what + ", not an array of " + std::to_string(v.size()));
    }
    return fail(path, expected(what, v));
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!number(v[i], index_path(path, i), out[i])) return false;
  }
  return true;
}

bool Reader::vec2(const json& v, const std::string& path, Vec2& out) {
  double c[2] = {0.0, 0.0};
  if (!numbers(v, path, c, 2)) return false;
  out = {c[0], c[1]};
  return true;
}

bool Reader::vec3(const json& v, const std::string& path, Vec3& out) {
  double c[3] = {0.0, 0.0, 0.0};
  if (!numbers(v, path, c, 3)) return false;
  out = {c[0], c[1], c[2]};
  return true;
}

bool Reader::non_negative(double x, const std::string& path) {
  if (x >= 0.0) return true;
  return fail(path, "must be >= 0, not " + format_number(x));
}

bool Reader::positive(double x, const std::string& path) {
  if (x > 0.0) return true;
  return fail(path, "must be positive, not " + format_number(x));
}

bool Reader::integer(const json& v, const std::string& path, std::int64_t lo, std::int64_t hi,
                     std::int64_t& out) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!v.is_number_integer()) return fail(path, expected("an integer in " + range, v));
  const bool in_range =
      v.is_number_unsigned()
          ? hi >= 0 && v.get<std::uint64_t>() <= static_cast<std::uint64_t>(hi) &&
                (lo <= 0 || v.get<std::uint64_t>() >= static_cast<std::uint64_t>(lo))
          : v.get<std::int64_t>() >= lo && v.get<std::int64_t>() <= hi;
  if (!in_range) return fail(path, "must be an integer in " + range + ", not " + v.dump());
  out = v.get<std::int64_t>();
  return true;
}

bool Reader::integer(const json& v, const std::string& path, int lo, int hi, int& out) {
  std::int64_t i = 0;
  if (!integer(v, path, std::int64_t{lo}, std::int64_t{hi}, i)) return false;
  out = static_cast<int>(i);
  return true;
}

bool Reader::boolean(const json& v, const std::string& path, bool& out) {
  if (!v.is_boolean()) return fail(path, expected("true or false", v));
  out = v.get<bool>();
  return true;
}

bool Reader::text(const json& v, const std::string& path, std::string& out) {
  if (!v.is_string()) return fail(path, expected("a string", v));
  out = v.get<std::string>();
  return true;
}

bool Reader::text_of(const json& v, const std::string& path, std::string_view what,
                     std::initializer_list<std::string_view> names, std::string& out) {
  if (!v.is_string()) return fail(path, expected("a string", v));
  const std::string& s = v.get_ref<const std::string&>();
  if (std::find(names.begin(), names.end(), s) == names.end()) {
    return fail(path, unknown(what, s, one_of(names)));
  }
  out = s;
  return true;
}

bool Reader::seed(const json& v, const std::string& path, std::uint64_t& out) {
  if (!v.is_string()) return fail(path, expected("a seed (a decimal string)", v));
  const std::string& s = v.get_ref<const std::string&>();
  const char* last = s.data() + s.size();
  const auto r = std::from_chars(s.data(), last, out);
  // from_chars takes no sign and no spaces, so the digits alone remain.
  if (s.empty() || r.ec != std::errc() || r.ptr != last) {
    return fail(path, "expected a seed: a decimal integer in [0, 2^64), not \"" + s + "\"");
  }
  return true;
}

}  // namespace breakshot::json_io
