// Match summaries as JSON, and game records written to a folder
// (include/breakshot/match_io.hpp).
#include "breakshot/match_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <limits>
#include <new>
#include <string_view>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/record.hpp"
#include "io/game_json.hpp"
#include "io/json_read.hpp"
#include "breakshot/record_io.hpp"

namespace breakshot {

namespace {

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5);
  return v[std::min(k, v.size() - 1)];
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(errno));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string() + ": write error");
}

}  // namespace

RecordSink record_files(const std::string& dir) {
  const std::filesystem::path folder(dir);
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) throw std::runtime_error("cannot create " + folder.string() + ": " + ec.message());
  return [folder](int game, const GameRecord& record) {
    write_file(folder / record_file_name(game), write_record(record));
  };
}

std::string record_file_name(int game) {
  char name[32];
  // 64 bits: game + 1 of INT_MAX.
  std::snprintf(name, sizeof name, "game-%04lld.json", static_cast<long long>(game) + 1);
  return name;
}

std::string match_summary_json(const MatchSummary& s) {
  using ojson = nlohmann::ordered_json;
  ojson j = ojson::object();
  j["game"] = to_string(s.game);
  j["table_size"] = s.table_size;
  // The physics only when it is not the engine's default, so that a
  // default match's summary reads as it always has.
  if (!(s.physics == GamePhysics{})) j["physics"] = json_io::physics_json(s.physics);
  if (s.game == GameType::three_cushion) {
    // Three-cushion's options, only in three-cushion summaries.
    ojson k = ojson::object();
    k["target"] = s.carom.target;
    k["innings_limit"] = s.carom.innings_limit;
    k["equalizing_inning"] = s.carom.equalizing_inning;
    j["carom"] = std::move(k);
  }
  j["seed"] = json_io::seed_json(s.seed);  // a string, as in records: 64 bits survive any reader
  j["noise"] = to_string(s.noise);
  // The games covered, unless they are 0 .. games_played - 1 (a match from
  // game 0, whose summary reads as it always has).
  const bool from_zero = s.ranges.empty() ||
                         (s.ranges.size() == 1 && s.ranges[0].first == 0 &&
                          s.ranges[0].count == s.games_played);
  if (!from_zero && s.ranges.size() == 1) {
    j["first_game"] = s.ranges[0].first;
  } else if (!from_zero) {
    ojson ranges = ojson::array();
    for (const GameRange& r : s.ranges) {
      ojson o = ojson::object();
      o["first_game"] = r.first;
      o["games"] = r.count;
      ranges.push_back(std::move(o));
    }
    j["game_ranges"] = std::move(ranges);
  }
  j["games_played"] = s.games_played;
  j["draws"] = s.draws;
  ojson players = ojson::array();
  for (const PlayerStats& p : s.players) {
    ojson o = ojson::object();
    o["name"] = p.name;
    o["noise"] = p.noise;
    o["games_won"] = p.games_won;
    o["breaks"] = p.breaks;
    o["break_and_runs"] = p.break_and_runs;
    o["innings"] = p.innings;
    o["shots"] = p.shots;
    o["balls_pocketed"] = p.balls_pocketed;
    o["balls_per_inning"] = p.balls_per_inning();
    o["pot_attempts"] = p.pot_attempts;
    o["pots_made"] = p.pots_made;
    o["pot_rate"] = p.pot_rate();
    if (!p.decision_seconds.empty()) {
      ojson t = ojson::object();
      t["decisions"] = p.decision_seconds.size();
      t["median"] = quantile(p.decision_seconds, 0.5);
      t["p90"] = quantile(p.decision_seconds, 0.9);
      t["max"] = quantile(p.decision_seconds, 1.0);
      o["decision_seconds"] = std::move(t);
    }
    ojson fouls = ojson::object();
    for (const auto& [kind, count] : p.fouls) fouls[kind] = count;
    o["fouls"] = std::move(fouls);
    if (p.snooker) {
      // Snooker's figures, only in snooker summaries.
      const SnookerStats& k = *p.snooker;
      ojson sk = ojson::object();
      sk["points"] = k.points;
      sk["highest_break"] = k.highest_break;
      sk["breaks_50"] = k.breaks_50;
      sk["breaks_100"] = k.breaks_100;
      sk["scoring_visits"] = k.scoring_visits;
      sk["break_points"] = k.break_points;
      sk["mean_break"] = k.mean_break();
      sk["foul_points_given"] = k.foul_points_given;
      sk["misses"] = k.misses;
      o["snooker"] = std::move(sk);
    }
    if (p.carom) {
      // Three-cushion's figures, only in three-cushion summaries.
      const CaromStats& k = *p.carom;
      ojson c = ojson::object();
      c["points"] = k.points;
      c["general_average"] = p.general_average();
      c["highest_run"] = k.highest_run;
      c["scoring_innings"] = k.scoring_innings;
      o["carom"] = std::move(c);
    }
    players.push_back(std::move(o));
  }
  j["players"] = std::move(players);
  return j.dump(2) + "\n";
}

namespace {

using json_io::json;
using json_io::member_path;
using json_io::index_path;

constexpr int kIntMax = std::numeric_limits<int>::max();

class SummaryReader : public json_io::GameReader {
 public:
  bool read(const json& doc, MatchSummary& s) {
    const std::string top;
    if (!require_object(doc, top)) return false;
    if (!known_fields(doc, top,
                      {"game", "table_size", "physics", "carom", "seed", "noise", "first_game",
                       "game_ranges", "games_played", "draws", "players"})) {
      return false;
    }
    const json* v = nullptr;
    if (!required(doc, top, "game", v)) return false;
    if (!v->is_string()) return fail("game", json_io::expected("a string", *v));
    if (const auto g = parse_game_type(v->get_ref<const std::string&>())) {
      s.game = *g;
    } else {
      const std::vector<std::string> names = game_type_names();
      const std::vector<std::string_view> views(names.begin(), names.end());
      return fail("game", unknown("game", v->get_ref<const std::string&>(),
                                  json_io::one_of(views.data(), views.size())));
    }
    game_ = s.game;
    if (!required(doc, top, "table_size", v) ||
        !(s.game == GameType::snooker
              ? text_of(*v, "table_size", "table size", {"12ft"}, s.table_size)
          : s.game == GameType::three_cushion
              ? text_of(*v, "table_size", "table size", {"10ft"}, s.table_size)
              : text_of(*v, "table_size", "table size", {"7ft", "8ft", "9ft"}, s.table_size))) {
      return false;
    }
    if (s.game == GameType::three_cushion) {
      if (!required(doc, top, "carom", v)) return false;
      const json& k = *v;
      if (!exact_object(k, "carom", {"target", "innings_limit", "equalizing_inning"}) ||
          !integer(k["target"], "carom.target", 1, kIntMax, s.carom.target) ||
          !integer(k["innings_limit"], "carom.innings_limit", 0, kIntMax, s.carom.innings_limit) ||
          !boolean(k["equalizing_inning"], "carom.equalizing_inning", s.carom.equalizing_inning)) {
        return false;
      }
    } else if (find(doc, "carom")) {
      return fail("carom", "only three-cushion summaries have this field");
    }
    if (const json* ph = find(doc, "physics")) {
      if (!physics(*ph, "physics", s.physics)) return false;
      if (s.physics == GamePhysics{}) {
        return fail("physics", "the default physics is not written (leave the field out)");
      }
    }
    if (!required(doc, top, "seed", v) || !seed(*v, "seed", s.seed)) return false;
    std::string spec;
    if (!required(doc, top, "noise", v) || !noise(*v, "noise", spec)) return false;
    s.noise = parse_noise(spec);
    if (!required(doc, top, "games_played", v) ||
        !integer(*v, "games_played", 0, kIntMax, s.games_played)) {
      return false;
    }
    if (!required(doc, top, "draws", v) || !integer(*v, "draws", 0, kIntMax, s.draws)) {
      return false;
    }
    if (!ranges(doc, s)) return false;

    std::vector<Foul> kinds;
    try {
      GameConfig config = s.game == GameType::snooker         ? snooker_config()
                          : s.game == GameType::three_cushion ? three_cushion_config()
                                                              : GameConfig{};
      config.game = s.game;
      config.table_size = s.table_size;
      config.physics = s.physics;  // airborne physics adds ball_off_table
      kinds = Rules(config).foul_kinds();
    } catch (const std::invalid_argument& e) {
      return fail("table_size", e.what());
    }
    if (!required(doc, top, "players", v) || !array(*v, "players", 2)) return false;
    for (std::size_t p = 0; p < 2; ++p) {
      if (!player((*v)[p], index_path("players", p), kinds, s.players[p])) return false;
    }
    const std::int64_t decided = std::int64_t{s.players[0].games_won} +
                                 s.players[1].games_won + s.draws;
    if (decided != s.games_played) {
      return fail("games_played", "must be the games won plus the draws (" +
                                      std::to_string(decided) + "), not " +
                                      std::to_string(s.games_played));
    }
    return true;
  }

 private:
  /// A noise spec that parse_noise reads and to_string writes back as it is.
  bool noise(const json& v, const std::string& path, std::string& out) {
    if (!text(v, path, out)) return false;
    try {
      const std::string canonical = to_string(parse_noise(out));
      if (canonical != out) {
        return fail(path, "expected the noise as a summary writes it (\"" + canonical +
                              "\"), not \"" + out + "\"");
      }
    } catch (const std::invalid_argument& e) {
      return fail(path, e.what());
    }
    return true;
  }

  bool ranges(const json& doc, MatchSummary& s) {
    const json* first = find(doc, "first_game");
    const json* list = find(doc, "game_ranges");
    if (first && list) return fail("game_ranges", "a summary has first_game or game_ranges, not both");
    if (first) {
      int f = 0;
      if (!integer(*first, "first_game", 1, kIntMax - s.games_played, f)) return false;
      if (s.games_played < 1) return fail("first_game", "a summary of no games has no first_game");
      s.ranges = {GameRange{f, s.games_played}};
      return true;
    }
    if (!list) {
      if (s.games_played > 0) s.ranges = {GameRange{0, s.games_played}};
      return true;
    }
    if (!array(*list, "game_ranges")) return false;
    if (list->size() < 2) {
      return fail("game_ranges", "expected two ranges or more (one range is written as first_game)");
    }
    std::int64_t total = 0;
    std::int64_t end = -1;  // of the range before
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string at = index_path("game_ranges", i);
      const json& r = (*list)[i];
      if (!exact_object(r, at, {"first_game", "games"})) return false;
      GameRange g;
      if (!integer(r["first_game"], member_path(at, "first_game"), 0, kIntMax, g.first) ||
          !integer(r["games"], member_path(at, "games"), 1, kIntMax - g.first, g.count)) {
        return false;
      }
      if (g.first <= end) {
        return fail(member_path(at, "first_game"),
                    "the ranges must ascend with a gap between them: " +
                        std::to_string(g.first) + " is not after " + std::to_string(end));
      }
      end = std::int64_t{g.first} + g.count;
      total += g.count;
      s.ranges.push_back(g);
    }
    if (total != s.games_played) {
      return fail("game_ranges", "the ranges hold " + std::to_string(total) +
                                     " games, not games_played = " +
                                     std::to_string(s.games_played));
    }
    return true;
  }

  bool count(const json& obj, const std::string& path, std::string_view key, int& out) {
    const json* v = nullptr;
    return required(obj, path, key, v) && integer(*v, member_path(path, key), 0, kIntMax, out);
  }

  /// A rate written as the summary derives it from its counts.
  bool rate(const json& obj, const std::string& path, std::string_view key, double expected) {
    const json* v = nullptr;
    double x = 0.0;
    if (!required(obj, path, key, v) || !number(*v, member_path(path, key), x)) return false;
    if (x != expected) {
      // Written as the summary writes it, which reads back to the same double.
      return fail(member_path(path, key), "must be " + json(expected).dump() +
                                              " (derived from the counts), not " + v->dump());
    }
    return true;
  }

  bool player(const json& v, const std::string& path, const std::vector<Foul>& kinds,
              PlayerStats& p) {
    if (!require_object(v, path)) return false;
    if (find(v, "decision_seconds")) {
      return fail(member_path(path, "decision_seconds"),
                  "a summary with decision times (--timing) cannot be read: it keeps only "
                  "their quantiles, which do not add up");
    }
    const bool snooker = game_ == GameType::snooker;
    const bool carom = game_ == GameType::three_cushion;
    std::vector<std::string_view> keys{
        "name",      "noise",    "games_won",      "breaks",           "break_and_runs",
        "innings",   "shots",    "balls_pocketed", "balls_per_inning", "pot_attempts",
        "pots_made", "pot_rate", "fouls"};
    if (snooker) keys.push_back("snooker");
    if (carom) keys.push_back("carom");
    if (!exact_object(v, path, keys)) return false;
    if (snooker && !snooker_stats(v["snooker"], member_path(path, "snooker"), p)) return false;
    if (!text(v["name"], member_path(path, "name"), p.name)) return false;
    if (p.name.empty()) return fail(member_path(path, "name"), "must not be empty");
    if (!noise(v["noise"], member_path(path, "noise"), p.noise)) return false;
    if (!count(v, path, "games_won", p.games_won) || !count(v, path, "breaks", p.breaks) ||
        !count(v, path, "break_and_runs", p.break_and_runs) ||
        !count(v, path, "innings", p.innings) || !count(v, path, "shots", p.shots) ||
        !count(v, path, "balls_pocketed", p.balls_pocketed) ||
        !count(v, path, "pot_attempts", p.pot_attempts) ||
        !count(v, path, "pots_made", p.pots_made)) {
      return false;
    }
    if (!rate(v, path, "balls_per_inning", p.balls_per_inning()) ||
        !rate(v, path, "pot_rate", p.pot_rate())) {
      return false;
    }
    if (carom && !carom_stats(v["carom"], member_path(path, "carom"), p)) return false;
    const std::string at = member_path(path, "fouls");
    const json& fouls = v["fouls"];
    if (!require_object(fouls, at)) return false;
    for (const Foul f : kinds) {
      const std::string name(to_string(f));
      const json* c = find(fouls, name);
      if (c == nullptr) return fail(member_path(at, name), "missing foul kind (every kind of the game is listed)");
      if (!integer(*c, member_path(at, name), 0, kIntMax, p.fouls[name])) return false;
    }
    if (fouls.size() != kinds.size()) {
      for (const auto& [key, value] : fouls.items()) {
        if (p.fouls.count(key) == 0) {
          return fail(member_path(at, key), "not a foul kind of " + std::string(to_string(game_)) +
                                                " (or not a foul)");
        }
      }
    }
    return true;
  }

  bool snooker_stats(const json& v, const std::string& path, PlayerStats& p) {
    if (!exact_object(v, path,
                      {"points", "highest_break", "breaks_50", "breaks_100", "scoring_visits",
                       "break_points", "mean_break", "foul_points_given", "misses"})) {
      return false;
    }
    SnookerStats k;
    if (!count(v, path, "points", k.points) || !count(v, path, "highest_break", k.highest_break) ||
        !count(v, path, "breaks_50", k.breaks_50) || !count(v, path, "breaks_100", k.breaks_100) ||
        !count(v, path, "scoring_visits", k.scoring_visits) ||
        !count(v, path, "break_points", k.break_points) ||
        !count(v, path, "foul_points_given", k.foul_points_given) ||
        !count(v, path, "misses", k.misses) || !rate(v, path, "mean_break", k.mean_break())) {
      return false;
    }
    p.snooker = k;
    return true;
  }

  /// Three-cushion's figures; read after the innings, from which the
  /// general average is derived.
  bool carom_stats(const json& v, const std::string& path, PlayerStats& p) {
    if (!exact_object(v, path, {"points", "general_average", "highest_run", "scoring_innings"})) {
      return false;
    }
    CaromStats k;
    if (!count(v, path, "points", k.points) || !count(v, path, "highest_run", k.highest_run) ||
        !count(v, path, "scoring_innings", k.scoring_innings)) {
      return false;
    }
    p.carom = k;
    return rate(v, path, "general_average", p.general_average());
  }

  GameType game_ = GameType::eight_ball;
};

}  // namespace

MatchSummary read_match_summary(std::string_view json_text) {
  try {
    json doc;
    if (auto problem = json_io::parse_strict(json_text, doc)) {
      throw std::invalid_argument(problem->error.path + ": " + problem->error.reason);
    }
    MatchSummary s;
    SummaryReader reader;
    if (!reader.read(doc, s)) {
      throw std::invalid_argument(reader.error->path + ": " + reader.error->reason);
    }
    return s;
  } catch (const std::bad_alloc&) {
    throw std::invalid_argument(std::string(json_io::kDocumentPath) +
                                ": out of memory while reading the summary");
  }
}

}  // namespace breakshot
