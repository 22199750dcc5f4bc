// web_api_probe: the native half of the identity test (docs/web.md, "Bit
// identity"). It runs the steps of web/tests/probe_script.json through
// the facade (web/api/web_api.hpp) and prints every reply on a line of
// its own: "LABEL<TAB>REPLY", the reply's newlines written as the two
// characters \n. web/tests/identity.mjs runs the same steps through the
// wasm build and compares the lines byte for byte, so the two
// interpreters must do exactly the same calls; keep them in step.
//
//   web_api_probe [--root DIR] [--script FILE]
//
// DIR is the repository (default: the source tree this was built from);
// FILE defaults to DIR/web/tests/probe_script.json.
//
// Steps ({"do": KIND, ...}); handles are named by "as" and referred to by
// "pb" (playbacks) and "game":
//   version                          bs_web_version
//   players {game}                   bs_web_game_players(game; null: NULL)
//   simulate_dir {dir}               bs_web_simulate of every DIR/*.json, by name
//   simulate_text {text}             bs_web_simulate of the text
//   playback_new {as, file}          bs_web_playback_new; {"ok":true} or bs_web_last_error
//   playback_new_text {as, text}
//   frames {pb, count, dt}           bs_web_playback_frame at k * dt, k = 0..count-1
//   frame {pb, t}
//   frames_data {pb, count, dt}      at k * dt, k = 0..count-1: bs_web_playback_frame_data
//                                    ("frame_data k") then bs_web_playback_frame at the same t
//                                    ("frame k")
//   frame_data {pb, t}               bs_web_playback_frame_data; "pb": null for a NULL handle
//   The doubles of bs_web_playback_frame_data are printed as the hexadecimal of
//   their bits, 16 digits each, separated by spaces (the header and the
//   balls, and the flight block when its flag is 1); NULL as bs_web_last_error.
//   events {pb, from}
//   playback_free {pb}               (prints nothing)
//   game_new {as, config}            bs_web_game_new(config as JSON text); the state or bs_web_last_error
//   game_new_text {as, text}
//   table / state / link / record / turns {game}
//   check_placement {game, x, y}
//   act {game, action}               bs_web_game_act(action as JSON text)
//   ai {game, level, play}           bs_web_game_ai_action(level or NULL); with play,
//                                    bs_web_game_act of the reply's action (its exact text)
//   ai_until {game, count, level}    up to count times, while the game is not over:
//                                    ai + act for the seat to act (its own level for an AI
//                                    seat, `level` for a human seat)
//   shot_playback {game, index, count, dt}   bs_web_game_shot_playback, frames as above,
//                                    events from 0, free
//   carom_playback {game, index, count, dt}  bs_web_game_shot_playback; at k * dt, k =
//                                    0..count-1: bs_web_playback_frame ("frame k") then
//                                    bs_web_playback_carom_count ("carom_count k"); free
//   from_link {game, as}             bs_web_game_from_link(link of game); the state or error
//   from_link_text {as, text}
//   undo {game, n}
//   game_free {game}                 (prints nothing)

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "web_api.hpp"

#ifndef BREAKSHOT_SOURCE_DIR
#define BREAKSHOT_SOURCE_DIR "."
#endif

namespace {

using json = nlohmann::json;

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + p.string());
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void print(const std::string& label, const std::string& reply) {
  std::string line = label;
  line += '\t';
  for (const char c : reply) {
    if (c == '\n') {
      line += "\\n";
    } else {
      line += c;
    }
  }
  line += '\n';
  std::fwrite(line.data(), 1, line.size(), stdout);
}

class Probe {
 public:
  explicit Probe(std::filesystem::path root) : root_(std::move(root)) {}
  ~Probe() {
    for (auto& [name, pb] : playbacks_) bs_web_playback_free(pb);
    for (auto& [name, g] : games_) bs_web_game_free(g);
  }
  Probe(const Probe&) = delete;
  Probe& operator=(const Probe&) = delete;

  void run(const json& step) {
    const std::string kind = step.at("do").get<std::string>();
    if (kind == "version") {
      print("version", bs_web_version());
    } else if (kind == "players") {
      const json& game = step.at("game");
      print("players", bs_web_game_players(game.is_null() ? nullptr : game.get<std::string>().c_str()));
    } else if (kind == "simulate_dir") {
      const std::string dir = step.at("dir").get<std::string>();
      std::vector<std::string> names;
      for (const auto& e : std::filesystem::directory_iterator(root_ / dir)) {
        const std::string n = e.path().filename().string();
        if (n.size() > 5 && n.substr(n.size() - 5) == ".json") names.push_back(n);
      }
      std::sort(names.begin(), names.end());
      for (const std::string& n : names) simulate("simulate " + dir + "/" + n, read_file(root_ / dir / n));
    } else if (kind == "simulate_text") {
      simulate("simulate_text", step.at("text").get<std::string>());
    } else if (kind == "playback_new" || kind == "playback_new_text") {
      const std::string text = kind == "playback_new" ? read_file(root_ / step.at("file").get<std::string>())
                                                      : step.at("text").get<std::string>();
      new_playback(kind + " " + step.at("as").get<std::string>(), step.at("as").get<std::string>(),
                   bs_web_playback_new(text.c_str()));
    } else if (kind == "frames") {
      frames(playback(step), step.at("count").get<int>(), step.at("dt").get<double>());
    } else if (kind == "frame") {
      print("frame", bs_web_playback_frame(playback(step), step.at("t").get<double>()));
    } else if (kind == "frames_data") {
      BsWebPlayback* pb = playback(step);
      const int count = step.at("count").get<int>();
      const double dt = step.at("dt").get<double>();
      for (int k = 0; k < count; ++k) {
        const double t = static_cast<double>(k) * dt;
        print("frame_data " + std::to_string(k), frame_data(bs_web_playback_frame_data(pb, t)));
        print("frame " + std::to_string(k), bs_web_playback_frame(pb, t));
      }
    } else if (kind == "frame_data") {
      BsWebPlayback* pb = step.at("pb").is_null() ? nullptr : playback(step);
      print("frame_data", frame_data(bs_web_playback_frame_data(pb, step.at("t").get<double>())));
    } else if (kind == "events") {
      const int from = step.at("from").get<int>();
      print("events " + std::to_string(from), bs_web_playback_events(playback(step), from));
    } else if (kind == "playback_free") {
      const std::string name = step.at("pb").get<std::string>();
      bs_web_playback_free(playback(step));
      playbacks_.erase(name);
    } else if (kind == "game_new" || kind == "game_new_text") {
      const std::string text = kind == "game_new" ? step.at("config").dump() : step.at("text").get<std::string>();
      new_game(kind + " " + step.at("as").get<std::string>(), step.at("as").get<std::string>(),
               bs_web_game_new(text.c_str()));
    } else if (kind == "table") {
      print("table " + name_of(step), bs_web_game_table(game(step)));
    } else if (kind == "state") {
      print("state " + name_of(step), bs_web_game_state(game(step)));
    } else if (kind == "link") {
      print("link " + name_of(step), bs_web_game_link(game(step)));
    } else if (kind == "record") {
      print("record " + name_of(step), bs_web_game_record(game(step)));
    } else if (kind == "turns") {
      print("turns " + name_of(step), bs_web_game_turns(game(step)));
    } else if (kind == "check_placement") {
      print("check_placement " + name_of(step),
            bs_web_game_check_placement(game(step), step.at("x").get<double>(), step.at("y").get<double>()));
    } else if (kind == "act") {
      print("act " + name_of(step), bs_web_game_act(game(step), step.at("action").dump().c_str()));
    } else if (kind == "ai") {
      const json& level = step.at("level");
      ai(step, level.is_null() ? std::string() : level.get<std::string>(), step.at("play").get<bool>());
    } else if (kind == "ai_until") {
      const int count = step.at("count").get<int>();
      for (int k = 0; k < count; ++k) {
        const json state = json::parse(bs_web_game_state(game(step)));
        if (state.at("phase") == "game_over") break;
        const std::string seat = state.at("players").at(state.at("player").get<std::size_t>()).get<std::string>();
        ai(step, seat == "human" ? step.at("level").get<std::string>() : std::string(), true);
      }
    } else if (kind == "shot_playback") {
      const int index = step.at("index").get<int>();
      BsWebPlayback* pb = bs_web_game_shot_playback(game(step), index);
      print("shot_playback " + name_of(step) + " " + std::to_string(index),
            pb != nullptr ? std::string("{\"ok\":true}") : std::string(bs_web_last_error()));
      if (pb != nullptr) {
        frames(pb, step.at("count").get<int>(), step.at("dt").get<double>());
        print("events 0", bs_web_playback_events(pb, 0));
        bs_web_playback_free(pb);
      }
    } else if (kind == "carom_playback") {
      const int index = step.at("index").get<int>();
      BsWebPlayback* pb = bs_web_game_shot_playback(game(step), index);
      print("carom_playback " + name_of(step) + " " + std::to_string(index),
            pb != nullptr ? std::string("{\"ok\":true}") : std::string(bs_web_last_error()));
      if (pb != nullptr) {
        const int count = step.at("count").get<int>();
        const double dt = step.at("dt").get<double>();
        for (int k = 0; k < count; ++k) {
          print("frame " + std::to_string(k), bs_web_playback_frame(pb, static_cast<double>(k) * dt));
          print("carom_count " + std::to_string(k), bs_web_playback_carom_count(pb));
        }
        bs_web_playback_free(pb);
      }
    } else if (kind == "from_link") {
      const json link = json::parse(bs_web_game_link(game(step)));
      const std::string text = link.at("link").get<std::string>();
      new_game("from_link " + step.at("as").get<std::string>(), step.at("as").get<std::string>(),
               bs_web_game_from_link(text.c_str()));
    } else if (kind == "from_link_text") {
      const std::string text = step.at("text").get<std::string>();
      new_game("from_link_text " + step.at("as").get<std::string>(), step.at("as").get<std::string>(),
               bs_web_game_from_link(text.c_str()));
    } else if (kind == "undo") {
      print("undo " + name_of(step), bs_web_game_undo_to(game(step), step.at("n").get<int>()));
    } else if (kind == "game_free") {
      const std::string name = name_of(step);
      bs_web_game_free(game(step));
      games_.erase(name);
    } else {
      throw std::runtime_error("unknown step \"" + kind + "\"");
    }
  }

 private:
  static std::string name_of(const json& step) { return step.at("game").get<std::string>(); }

  BsWebPlayback* playback(const json& step) {
    const auto it = playbacks_.find(step.at("pb").get<std::string>());
    if (it == playbacks_.end()) throw std::runtime_error("no playback " + step.at("pb").dump());
    return it->second;
  }

  BsWebGame* game(const json& step) {
    const auto it = games_.find(name_of(step));
    if (it == games_.end()) throw std::runtime_error("no game " + step.at("game").dump());
    return it->second;
  }

  void simulate(const std::string& label, const std::string& text) {
    char* reply = bs_web_simulate(text.c_str());
    print(label, reply);
    bs_web_free(reply);
  }

  void new_playback(const std::string& label, const std::string& name, BsWebPlayback* pb) {
    print(label, pb != nullptr ? std::string("{\"ok\":true}") : std::string(bs_web_last_error()));
    if (pb != nullptr) {
      if (playbacks_.count(name)) bs_web_playback_free(playbacks_[name]);
      playbacks_[name] = pb;
    }
  }

  void new_game(const std::string& label, const std::string& name, BsWebGame* g) {
    print(label, g != nullptr ? std::string(bs_web_game_state(g)) : std::string(bs_web_last_error()));
    if (g != nullptr) {
      if (games_.count(name)) bs_web_game_free(games_[name]);
      games_[name] = g;
    }
  }

  /// bs_web_playback_frame_data's doubles as the hex of their bits, or bs_web_last_error.
  static std::string frame_data(const double* d) {
    if (d == nullptr) return bs_web_last_error();
    // The header and the balls, and the flight block when its flag is 1.
    const auto balls = static_cast<std::size_t>(d[7]);
    const std::size_t head = 8 + 8 * balls;
    const std::size_t n = d[head] != 0.0 ? head + 1 + 2 * balls : head;
    std::string out;
    out.reserve(17 * n);
    char buf[17];
    for (std::size_t i = 0; i < n; ++i) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &d[i], sizeof bits);
      std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(bits));
      if (i > 0) out += ' ';
      out += buf;
    }
    return out;
  }

  static void frames(BsWebPlayback* pb, int count, double dt) {
    for (int k = 0; k < count; ++k) {
      print("frame " + std::to_string(k), bs_web_playback_frame(pb, static_cast<double>(k) * dt));
    }
  }

  /// The AI's action for the game of `step` and, with `play`, acting it
  /// with the reply's action text as it is (no re-encoding).
  void ai(const json& step, const std::string& level, bool play) {
    BsWebGame* g = game(step);
    const std::string reply = bs_web_game_ai_action(g, level.empty() ? nullptr : level.c_str());
    print("ai " + name_of(step), reply);
    const std::string head = "{\"action\":";
    if (play && reply.compare(0, head.size(), head) == 0) {
      const std::string action = reply.substr(head.size(), reply.size() - head.size() - 1);
      print("act " + name_of(step), bs_web_game_act(g, action.c_str()));
    }
  }

  std::filesystem::path root_;
  std::map<std::string, BsWebPlayback*> playbacks_;
  std::map<std::string, BsWebGame*> games_;
};

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path root = BREAKSHOT_SOURCE_DIR;
  std::filesystem::path script;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--root" || a == "--script") && i + 1 < argc) {
      (a == "--root" ? root : script) = argv[++i];
    } else {
      std::cerr << "usage: web_api_probe [--root DIR] [--script FILE]\n";
      return 2;
    }
  }
  if (script.empty()) script = root / "web" / "tests" / "probe_script.json";
  try {
    const json doc = json::parse(read_file(script));
    Probe probe(root);
    for (const json& step : doc.at("steps")) probe.run(step);
  } catch (const std::exception& e) {
    std::cerr << "web_api_probe: " << e.what() << '\n';
    return 1;
  }
  std::fflush(stdout);
  return 0;
}
