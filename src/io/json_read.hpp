// Strict JSON reading, shared by the scenario reader (scenario_json.cpp),
// the record reader (record_json.cpp) and the web facade
// (web/api). Internal: not installed, and the only place
// besides those readers that sees nlohmann::json.
//
// Strict on purpose: a repeated key, an unknown field or a wrong type is
// an error, reported with the JSON path of the value ("balls[1].radius",
// "table[\"odd key\"]") and a reason. A value that reads "almost" right
// would give a scenario, a record or a game that looks right and is not.
//
// The reading functions of Reader return false after recording the first
// problem in `error`; the first problem stops a read.

#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "breakshot/vec.hpp"

namespace breakshot::json_io {

using json = nlohmann::json;

/// Path shown for problems with the document as a whole.
inline constexpr const char* kDocumentPath = "(document)";

// ---------------------------------------------------------------------------
// Paths: a.b[3].c

/// Appends the step to member `key`: ".key" for ordinary keys (just "key"
/// at the top), ["odd key"] for keys a reader could not otherwise tell
/// apart.
void append_member(std::string& path, std::string_view key);
void append_index(std::string& path, std::size_t i);
std::string member_path(std::string path, std::string_view key);
std::string index_path(std::string path, std::size_t i);

// ---------------------------------------------------------------------------
// Messages

/// "a number", "a string", "null", ...: what `v` is, for messages.
std::string type_name(const json& v);
/// "expected WHAT, not a string".
std::string expected(std::string_view what, const json& v);
/// "\"a\", \"b\" or \"c\"": the names a value may take.
std::string one_of(const std::string_view* names, std::size_t n);
inline std::string one_of(std::initializer_list<std::string_view> names) {
  return one_of(names.begin(), names.size());
}
/// The cushion models' scenario names as one_of lists them
/// ("\"han_2005_v0\", ... or \"impulse_frictional\""), from kCushionModels.
std::string cushion_model_names();

// ---------------------------------------------------------------------------
// Parsing

struct ReadError {
  std::string path;
  std::string reason;
};

struct ParseOptions {
  /// Objects that are the value of a member with this key are the
  /// user's: their repeated keys are not looked for ("extra" in a
  /// scenario). Empty: every object is checked.
  std::string_view free_key;
  /// The path of the document itself, which the paths of repeated keys
  /// start with ("" for the top: "balls[1].id"; "link": "link.a").
  std::string root_path;
};

struct ParseProblem {
  /// Where: the path of a repeated key, or kDocumentPath for text that
  /// is not JSON.
  ReadError error;
  /// True for text that is not JSON (the reason then has the line and
  /// column), false for a repeated key.
  bool syntax = false;
};

/// Parses `text` into `out`, refusing what nlohmann's own parser lets
/// through without a word: a key repeated within one object (it keeps
/// the last value). Numbers too large for a double (1e400) are syntax
/// errors. Deep nesting cannot overflow the call stack.
std::optional<ParseProblem> parse_strict(std::string_view text, json& out,
                                         const ParseOptions& options = {});

// ---------------------------------------------------------------------------
// Reading values

class Reader {
 public:
  std::optional<ReadError> error;

  Reader() = default;
  /// `free_key`: a member that known_fields(), object() and
  /// exact_object() always allow and never look into ("extra" in a
  /// scenario).
  explicit Reader(std::string_view free_key) : free_key_(free_key) {}
  virtual ~Reader() = default;
  Reader(const Reader&) = default;
  Reader& operator=(const Reader&) = default;

  bool fail(std::string path, std::string reason) {
    error = ReadError{std::move(path), std::move(reason)};
    return false;
  }

  /// The member `key` of the object `obj`, or null.
  static const json* find(const json& obj, std::string_view key) {
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }

  /// `v` must be an object (at path "": the document).
  bool require_object(const json& v, const std::string& path);
  /// Every member of the object `obj` must be in `known` (or be the free
  /// key): "unknown field (known: ...)".
  bool known_fields(const json& obj, const std::string& path,
                    std::initializer_list<std::string_view> known);
  /// An object whose members are all in `known` (each optional).
  bool object(const json& v, const std::string& path,
              std::initializer_list<std::string_view> known);
  /// An object with exactly the members `names`, each required.
  bool exact_object(const json& v, const std::string& path,
                    std::initializer_list<std::string_view> names);
  /// The same with the names in a list built at run time.
  bool exact_object(const json& v, const std::string& path,
                    const std::vector<std::string_view>& names);
  /// The member `key` of the object `obj` at `path`, which must be there.
  bool required(const json& obj, const std::string& path, std::string_view key,
                const json*& out);

  /// An array, of `size` elements if given.
  bool array(const json& v, const std::string& path, std::optional<std::size_t> size = {});
  /// A finite number. Virtual: a reader may narrow what it accepts (the
  /// scenario reader bounds the magnitude).
  virtual bool number(const json& v, const std::string& path, double& out);
  /// An array of exactly n numbers.
  bool numbers(const json& v, const std::string& path, double* out, std::size_t n);
  bool vec2(const json& v, const std::string& path, Vec2& out);
  bool vec3(const json& v, const std::string& path, Vec3& out);
  bool non_negative(double x, const std::string& path);
  bool positive(double x, const std::string& path);
  /// An integer number (not 1.0) in [lo, hi].
  bool integer(const json& v, const std::string& path, std::int64_t lo, std::int64_t hi,
               std::int64_t& out);
  bool integer(const json& v, const std::string& path, int lo, int hi, int& out);
  bool boolean(const json& v, const std::string& path, bool& out);
  bool text(const json& v, const std::string& path, std::string& out);
  /// A string that is one of `names`; `what` names it in the message
  /// ("unknown table size \"10ft\" (expected \"7ft\", \"8ft\" or \"9ft\")").
  bool text_of(const json& v, const std::string& path, std::string_view what,
               std::initializer_list<std::string_view> names, std::string& out);
  /// A 64-bit seed written as a decimal string (64-bit integers do not
  /// survive readers that keep numbers in doubles).
  bool seed(const json& v, const std::string& path, std::uint64_t& out);

  /// An enum by its to_string name: `parse` gives the value of a name,
  /// `all` lists every value for the message.
  template <class E, class Parse, std::size_t N>
  bool name(const json& v, const std::string& path, std::string_view what, Parse parse,
            const E (&all)[N], E& out) {
    if (!v.is_string()) return fail(path, expected("a string", v));
    const std::string& s = v.get_ref<const std::string&>();
    if (const std::optional<E> e = parse(s)) {
      out = *e;
      return true;
    }
    std::vector<std::string_view> names;
    for (const E e : all) names.push_back(to_string(e));
    return fail(path, unknown(what, s, one_of(names.data(), names.size())));
  }

 protected:
  /// "unknown WHAT \"value\" (expected KNOWN)".
  static std::string unknown(std::string_view what, std::string_view value,
                             std::string_view known);

 private:
  std::string_view free_key_;
};

}  // namespace breakshot::json_io
