// Match summaries as JSON, and game records written to a folder
// (include/breakshot/match_io.hpp).
#include "breakshot/match_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "breakshot/record.hpp"
#include "io/game_json.hpp"
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
    char name[32];
    std::snprintf(name, sizeof name, "game-%04d.json", game + 1);
    write_file(folder / name, write_record(record));
  };
}

std::string match_summary_json(const MatchSummary& s) {
  using ojson = nlohmann::ordered_json;
  ojson j = ojson::object();
  j["game"] = to_string(s.game);
  j["table_size"] = s.table_size;
  j["seed"] = json_io::seed_json(s.seed);  // a string, as in records: 64 bits survive any reader
  j["noise"] = to_string(s.noise);
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
    players.push_back(std::move(o));
  }
  j["players"] = std::move(players);
  return j.dump(2) + "\n";
}

}  // namespace breakshot
