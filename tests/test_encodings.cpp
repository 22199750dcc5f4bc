// One encoding of each game fact (src/io/game_json.hpp, table_json.hpp):
// the web facade's replies are those functions' JSON, byte for byte, for
// the table and its markings, the legal actions, a shot's facts and the
// snooker and three-cushion figures; the Python binding calls the same
// functions (python/tests/test_encodings.py compares its values with the
// facade's replies).

#include <gtest/gtest.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "breakshot/carom.hpp"
#include "breakshot/game.hpp"
#include "breakshot/record.hpp"
#include "breakshot/record_io.hpp"
#include "breakshot/session.hpp"
#include "breakshot/snooker.hpp"
#include "io/game_json.hpp"
#include "io/table_json.hpp"
#include "web_api.hpp"

namespace test_encodings {

namespace {

namespace bs = breakshot;
namespace io = breakshot::json_io;
using ojson = nlohmann::ordered_json;

struct GameDeleter {
  void operator()(BsWebGame* g) const { bs_web_game_free(g); }
};
using GamePtr = std::unique_ptr<BsWebGame, GameDeleter>;

/// A facade game between two quick computer players (the baseline where
/// it plays, else beginners), played for `actions` actions; every act
/// reply is kept.
GamePtr played(const std::string& game, int actions, std::vector<std::string>& replies) {
  const std::string seat = game == "snooker" || game == "three_cushion" ? "baseline" : "beginner";
  const std::string config = R"({"game": ")" + game + R"(", "seed": "11", "players": [")" + seat +
                             R"(", ")" + seat + R"("], "ai_budget": 30})";
  GamePtr g(bs_web_game_new(config.c_str()));
  EXPECT_NE(g, nullptr) << bs_web_last_error();
  for (int k = 0; k < actions; ++k) {
    if (ojson::parse(bs_web_game_state(g.get()))["phase"] == "game_over") break;
    const ojson a = ojson::parse(bs_web_game_ai_action(g.get(), nullptr));
    replies.emplace_back(bs_web_game_act(g.get(), a["action"].dump().c_str()));
    EXPECT_FALSE(ojson::parse(replies.back()).contains("error")) << replies.back();
  }
  return g;
}

/// The facade's state reply less what is not the state itself.
void check_state_reply(const ojson& reply, const bs::GameSession& session,
                       const std::string& what) {
  const bs::GameState& s = session.state();
  EXPECT_EQ(reply["legal"].dump(),
            io::legal_actions_json(session.rules().legal_actions(s), s.game).dump())
      << what;
  if (s.game == bs::GameType::snooker) {
    EXPECT_EQ(reply["snooker_figures"].dump(), io::snooker_figures_json(s).dump()) << what;
  } else {
    EXPECT_FALSE(reply.contains("snooker_figures")) << what;
  }
  if (s.game == bs::GameType::three_cushion) {
    EXPECT_EQ(reply["carom_figures"].dump(),
              io::carom_figures_json(session.rules(), s, session.record()).dump())
        << what;
  } else {
    EXPECT_FALSE(reply.contains("carom_figures")) << what;
  }
}

// For every game: the table reply is game_table_json; each act reply's
// facts are facts_json of the same shot played again on a session of the
// record, and its state's legal actions and figures are the io functions'.
TEST(Encodings, FacadeRepliesAreTheIoEncodings) {
  for (const std::string game :
       {"eight_ball", "nine_ball", "ten_ball", "snooker", "three_cushion"}) {
    std::vector<std::string> replies;
    GamePtr g = played(game, 4, replies);
    ASSERT_FALSE(replies.empty()) << game;
    const auto read = bs::read_record(bs_web_game_record(g.get()));
    ASSERT_TRUE(std::holds_alternative<bs::GameRecord>(read)) << game;
    const bs::GameRecord& record = std::get<bs::GameRecord>(read);
    bs::GameSession session(record.config, bs::Seats{record.players, record.noise}, record.seed,
                            record.start.rack_seed, record.start.breaker);

    EXPECT_EQ(std::string(bs_web_game_table(g.get())), io::game_table_json(session.rules()).dump())
        << game;
    ASSERT_EQ(replies.size(), record.actions.size()) << game;
    for (std::size_t i = 0; i < record.actions.size(); ++i) {
      const bs::RecordedAction& ra = record.actions[i];
      const bs::Outcome out = session.play_executed(ra.action, ra.intended, ra.noise_seed);
      const ojson reply = ojson::parse(replies[i]);
      const std::string what = game + " action " + std::to_string(i);
      EXPECT_EQ(reply["facts"].dump(), io::facts_json(out.facts).dump()) << what;
      check_state_reply(reply["state"], session, what);
    }
  }
}

// The table's fields, each game's markings only in its own game, and the
// points where the physics layer puts them.
TEST(Encodings, TableCarriesItsGamesMarkings) {
  bs::GameConfig pool;
  pool.game = bs::GameType::nine_ball;
  const ojson nine = io::game_table_json(bs::Rules(pool));
  const char* keys[] = {"size",       "length",      "width",     "ball_radius",
                        "ball_count", "head_string", "head_spot", "foot_spot",
                        "outline",    "walls",       "pockets"};
  std::size_t k = 0;
  for (const auto& [key, value] : nine.items()) {
    ASSERT_LT(k, std::size(keys)) << key;
    EXPECT_EQ(key, keys[k++]);
  }
  EXPECT_EQ(k, std::size(keys));
  EXPECT_EQ(nine["ball_count"], 10);
  EXPECT_EQ(nine["pockets"].size(), 6u);

  const ojson snooker = io::game_table_json(bs::Rules(bs::snooker_config()));
  const bs::SnookerMarks sm = bs::snooker_marks();
  EXPECT_EQ(snooker["snooker"]["spots"]["pink"], ojson::array({sm.pink.x, sm.pink.y}));
  EXPECT_EQ(snooker["snooker"]["baulk_line"], sm.baulk_x);
  EXPECT_FALSE(snooker.contains("carom"));
  EXPECT_EQ(snooker["ball_count"], 22);

  const ojson carom = io::game_table_json(bs::Rules(bs::three_cushion_config()));
  const bs::CaromMarks cm = bs::carom_marks();
  EXPECT_EQ(carom["carom"]["diamonds"].size(), cm.diamonds.size());
  EXPECT_EQ(carom["carom"]["starting_spots"][1],
            ojson::array({cm.starting_spots[1].x, cm.starting_spots[1].y}));
  EXPECT_FALSE(carom.contains("snooker"));
  EXPECT_TRUE(carom["pockets"].empty());
}

// A game shot's events: ball numbers, a pocket by index and name, a
// cushion by name, null where the index names nothing.
TEST(Encodings, GameEventsNameCushionsAndPockets) {
  bs::GameConfig pool;
  const bs::Table table = bs::Rules(pool).table();
  bs::Event hit;
  hit.time = 0.5;
  hit.type = bs::EventType::ball_ball;
  hit.ball = 0;
  hit.other = 3;
  EXPECT_EQ(io::game_event_json(table, hit).dump(),
            R"({"time":0.5,"type":"ball_ball","balls":[0,3]})");
  bs::Event pocket;
  pocket.type = bs::EventType::ball_pocket;
  pocket.ball = 3;
  pocket.pocket = 2;
  const ojson p = io::game_event_json(table, pocket);
  EXPECT_EQ(p["pocket"], 2);
  EXPECT_EQ(p["pocket_name"], table.pockets[2].name);
  pocket.pocket = 99;
  EXPECT_TRUE(io::game_event_json(table, pocket)["pocket_name"].is_null());
  bs::Event cushion;
  cushion.type = bs::EventType::ball_cushion;
  cushion.ball = 1;
  cushion.wall = 0;
  EXPECT_EQ(io::game_event_json(table, cushion)["cushion"], table.walls[0].name);
  cushion.wall = -1;
  EXPECT_TRUE(io::game_event_json(table, cushion)["cushion"].is_null());
}

}  // namespace

}  // namespace test_encodings
