// The facade's errors and its reading of JSON input (facade.hpp).

#include "facade.hpp"

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/players.hpp"

namespace facade {

[[noreturn]] void bad(const std::string& path, const std::string& what) {
  throw BadInput{path.empty() ? what : path + ": " + what};
}

std::string error_json(const std::string& message) {
  ojson j = ojson::object();
  j["error"] = message;
  // A message may quote the input's bytes (a link's decoded text is any
  // bytes, and the JSON parser's message shows the last ones read): bytes
  // that are not UTF-8 are written as U+FFFD rather than thrown about
  // from inside a catch handler, which would cross the C boundary.
  return j.dump(-1, ' ', false, ojson::error_handler_t::replace);
}

thread_local std::string g_last_error;
thread_local bool g_has_error = false;

const char* last_error() {
  static const std::string none = error_json("no error");
  return g_has_error ? g_last_error.c_str() : none.c_str();
}

const char* keep(std::string& slot, std::string text) {
  slot = std::move(text);
  return slot.c_str();
}

const char* null_handle() {
  static const std::string reply = error_json("handle: a null handle");
  return reply.c_str();
}

char* copy_out(const std::string& s) {
  char* p = static_cast<char*>(std::malloc(s.size() + 1));
  if (p != nullptr) std::memcpy(p, s.c_str(), s.size() + 1);
  return p;
}

// ---------------------------------------------------------------------------
// Reading JSON input: io/json_read.hpp's strict reading, its problems
// thrown as bad inputs

const json* find(const json& obj, std::string_view key) { return Reader::find(obj, key); }

json parse_text(const char* text, const std::string& what, const std::string& root) {
  if (text == nullptr) bad(what, "missing (a null pointer)");
  json doc;
  bs::json_io::ParseOptions options;
  options.root_path = root;
  if (auto problem = bs::json_io::parse_strict(text, doc, options)) {
    if (problem->syntax) bad(what, "not valid JSON: " + problem->error.reason);
    bad(problem->error.path, problem->error.reason);
  }
  return doc;
}

const json& object(const json& v, const std::string& path,
                   std::initializer_list<std::string_view> known) {
  Reader r;
  r.must(r.object(v, path, known));
  return v;
}

const json& required(const json& obj, const std::string& path, std::string_view key) {
  Reader r;
  const json* v = nullptr;
  r.must(r.required(obj, path, key, v));
  return *v;
}

std::int64_t integer(const json& v, const std::string& path, std::int64_t lo, std::int64_t hi) {
  Reader r;
  std::int64_t i = 0;
  r.must(r.integer(v, path, lo, hi, i));
  return i;
}

const std::string& text(const json& v, const std::string& path) {
  Reader r;
  std::string unused;
  r.must(r.text(v, path, unused));
  return v.get_ref<const std::string&>();
}

std::uint64_t seed_value(const json& v, const std::string& path) {
  if (v.is_number_integer()) {
    return static_cast<std::uint64_t>(integer(v, path, 0, std::int64_t{1} << 53));
  }
  Reader r;
  std::uint64_t seed = 0;
  r.must(r.seed(v, path, seed));
  return seed;
}

bs::PlayerName computer_name(const std::string& name, const std::string& path) {
  try {
    return bs::read_player_name(name);
  } catch (const std::invalid_argument& e) {
    bad(path, e.what());
  }
}

std::string seat_name(const json& v, const std::string& path) {
  const std::string& s = text(v, path);
  if (s == kHuman) return s;
  const bs::PlayerName n = computer_name(s, path);
  try {
    (void)bs::ai_level(n.base);
  } catch (const std::invalid_argument& e) {
    bad(path, std::string("\"human\" or ") + e.what());
  }
  return s;
}

std::vector<std::string> computer_players(bs::GameType game) {
  if (game == bs::GameType::three_cushion) {
    // Whoever plays three-cushion (players.hpp): the AI levels that do,
    // then the baseline.
    std::vector<std::string> out;
    for (const std::string& l : bs::ai_level_names()) {
      if (!bs::check_player(l, game)) out.push_back(l);
    }
    out.emplace_back("baseline");
    return out;
  }
  std::vector<std::string> out = bs::ai_level_names();
  if (game == bs::GameType::snooker) out.push_back("baseline");
  return out;
}

bool is_baseline(std::string_view name) {
  return name.substr(0, name.find('@')) == "baseline";
}

std::string seat_name(const json& v, const std::string& path, bs::GameType game) {
  if (game == bs::GameType::three_cushion) {
    const std::string& s = text(v, path);
    if (s == kHuman) return s;
    const std::string base = computer_name(s, path).base;
    const std::vector<std::string> known = computer_players(game);
    for (const std::string& k : known) {
      if (k == base) return s;
    }
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "\"" : ", \"") + k + "\"";
    bad(path, "\"human\" or a player of three_cushion (" + list + "), not \"" + s + "\"");
  }
  if (game == bs::GameType::snooker && is_baseline(text(v, path))) return text(v, path);
  return seat_name(v, path);
}

}  // namespace facade
