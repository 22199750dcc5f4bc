// The rooms of online play (src/web/rooms.hpp), without
// sockets: messages in, effects out.
#include <gtest/gtest.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "breakshot/record_io.hpp"
#include "web/rooms.hpp"
#include "web_api.hpp"

namespace test_rooms {

namespace {

using breakshot::online::ClientId;
using breakshot::online::Effects;
using breakshot::online::RoomLimits;
using breakshot::online::Rooms;
using json = nlohmann::json;

// A fixed source of "randomness" (splitmix64), so that codes and seeds
// are the same every run.
std::function<std::uint64_t()> fixed_random() {
  auto state = std::make_shared<std::uint64_t>(12345);
  return [state] {
    std::uint64_t z = (*state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
}

// The messages of `fx` to client `c`, parsed.
std::vector<json> to(const Effects& fx, ClientId c) {
  std::vector<json> out;
  for (const auto& m : fx.messages) {
    if (m.to == c) out.push_back(json::parse(m.text));
  }
  return out;
}

json first_of(const Effects& fx, ClientId c, const std::string& type) {
  for (const json& m : to(fx, c)) {
    if (m["type"] == type) return m;
  }
  return json();
}

bool closes(const Effects& fx, ClientId c) {
  for (const ClientId x : fx.close) {
    if (x == c) return true;
  }
  return false;
}

const std::string kQuick =
    R"({"type": "create", "game": {"game": "three_cushion", "carom": {"target": 1,
        "innings_limit": 1, "equalizing_inning": false}}})";

std::string shot(double phi, std::size_t index) {
  return R"({"type": "act", "index": )" + std::to_string(index) +
         R"(, "action": {"type": "shoot", "strike": {"speed": 3, "phi": )" + std::to_string(phi) +
         R"(, "theta": 0, "a": 0, "b": 0}, "call": null, "safety": false, "push_out": false}})";
}

class RoomsTest : public ::testing::Test {
 protected:
  RoomsTest() : rooms_(limits(), fixed_random()) {}
  static RoomLimits limits() {
    RoomLimits l;
    l.max_rooms = 3;
    l.max_watchers = 2;
    l.seat_timeout = 120;
    l.room_timeout = 600;
    l.record_prefix = "test";
    return l;
  }
  // Client 1 creates a quick three-cushion room, client 2 joins it.
  json start_game() {
    const Effects made = rooms_.receive(1, kQuick, 0);
    created_ = first_of(made, 1, "joined");
    const Effects joined = rooms_.receive(
        2, R"({"type": "join", "room": ")" + created_["room"].get<std::string>() + "\"}", 1);
    return first_of(joined, 2, "joined");
  }
  Rooms rooms_;
  json created_;
};

TEST_F(RoomsTest, CreateGivesACodeASeatAndAToken) {
  const json friend_joined = start_game();
  ASSERT_TRUE(created_.is_object());
  const std::string code = created_["room"];
  EXPECT_EQ(code.size(), 6u);
  EXPECT_EQ(created_["seat"], 0);
  EXPECT_EQ(created_["token"].get<std::string>().size(), 32u);
  EXPECT_EQ(created_["config"]["players"], json({"human", "human"}));
  EXPECT_TRUE(created_["config"]["seed"].is_string());
  EXPECT_EQ(created_["actions"], json::array());
  EXPECT_EQ(friend_joined["seat"], 1);
  EXPECT_NE(friend_joined["token"], created_["token"]);
  EXPECT_EQ(friend_joined["hash"], created_["hash"]);
  // A third comes in as a watcher, without a token; so does one who asks to.
  const Effects third = rooms_.receive(3, R"({"type": "join", "room": ")" + code + "\"}", 2);
  const json w = first_of(third, 3, "joined");
  EXPECT_TRUE(w["seat"].is_null());
  EXPECT_FALSE(w.contains("token"));
  // Everyone hears who is there.
  EXPECT_EQ(first_of(third, 1, "seats")["watchers"], 1);
  // Codes are read in any case.
  std::string lower = code;
  for (char& c : lower) c = static_cast<char>(std::tolower(c));
  const Effects fourth =
      rooms_.receive(4, R"({"type": "join", "room": ")" + lower + R"(", "watch": true})", 2);
  EXPECT_TRUE(first_of(fourth, 4, "joined")["seat"].is_null());
  // The watchers' limit.
  const Effects fifth = rooms_.receive(5, R"({"type": "join", "room": ")" + code + "\"}", 2);
  EXPECT_NE(first_of(fifth, 5, "refused")["reason"].get<std::string>().find("watchers"),
            std::string::npos);
  EXPECT_EQ(rooms_.rooms(), 1u);
}

TEST_F(RoomsTest, TheServerIsTheAuthorityOnEveryAction) {
  Effects fx = rooms_.receive(1, kQuick, 0);
  const std::string code = first_of(fx, 1, "joined")["room"];
  // Before the friend comes, nobody plays.
  fx = rooms_.receive(1, shot(0, 0), 0);
  EXPECT_EQ(first_of(fx, 1, "refused")["reason"], "the other player has not come yet");
  rooms_.receive(2, R"({"type": "join", "room": ")" + code + "\"}", 1);
  rooms_.receive(3, R"({"type": "join", "room": ")" + code + "\"}", 1);
  // Not your turn; a watcher; a stale index; an action the rules refuse.
  fx = rooms_.receive(2, shot(0, 0), 2);
  EXPECT_EQ(first_of(fx, 2, "refused")["reason"], "not your turn");
  fx = rooms_.receive(3, shot(0, 0), 2);
  EXPECT_EQ(first_of(fx, 3, "refused")["reason"], "a watcher does not play");
  fx = rooms_.receive(1, shot(0, 5), 2);
  EXPECT_NE(first_of(fx, 1, "refused")["reason"].get<std::string>().find("index 5"),
            std::string::npos);
  fx = rooms_.receive(
      1, R"({"type": "act", "index": 0, "action": {"type": "place_cue_ball", "position": [0, 0]}})",
      2);
  const std::string why = first_of(fx, 1, "refused")["reason"];
  EXPECT_EQ(why.rfind("action: ", 0), 0u) << why;
  EXPECT_TRUE(fx.records.empty());
  // A shot the rules allow: everyone gets it and the hash after it.
  fx = rooms_.receive(1, shot(90, 0), 3);
  for (const ClientId c : {1, 2, 3}) {
    const json a = first_of(fx, c, "action");
    ASSERT_TRUE(a.is_object()) << c;
    EXPECT_EQ(a["index"], 0);
    EXPECT_EQ(a["seat"], 0);
    EXPECT_EQ(a["hash"].get<std::string>().size(), 16u);
  }
  // Lockstep: a page that plays the action itself gets the same hash.
  BsWebGame* mine = bs_web_game_new(
      first_of(
          rooms_.receive(9, R"({"type": "join", "room": ")" + code + R"(", "watch": true})", 4), 9,
          "joined")["config"]
          .dump()
          .c_str());
  ASSERT_NE(mine, nullptr);
  const json a = first_of(fx, 1, "action");
  const json played = json::parse(bs_web_game_act(mine, a["action"].dump().c_str()));
  ASSERT_FALSE(played.contains("error")) << played;
  EXPECT_EQ(breakshot::online::state_hash(bs_web_game_state(mine)), a["hash"]);
  bs_web_game_free(mine);
  // Each action writes the record, under the rooms' name; it replays.
  ASSERT_EQ(fx.records.size(), 1u);
  EXPECT_EQ(fx.records[0].name, "test-000001-" + code + ".json");
  const auto record = breakshot::read_record(fx.records[0].text);
  ASSERT_TRUE(std::holds_alternative<breakshot::GameRecord>(record));
  EXPECT_TRUE(breakshot::replay(std::get<breakshot::GameRecord>(record)).identical);
}

TEST_F(RoomsTest, AGameIsPlayedToItsEnd) {
  start_game();
  Effects fx;
  std::size_t i = 0;
  for (; i < 10; ++i) {
    const json state = first_of(fx, 1, "over");
    if (state.is_object()) break;
    // Whoever is to act: try seat 0, then seat 1.
    fx = rooms_.receive(1, shot(90.0 + 7.0 * static_cast<double>(i), i), 3);
    if (first_of(fx, 1, "refused").is_object()) fx = rooms_.receive(2, shot(90, i), 3);
    ASSERT_TRUE(first_of(fx, 2, "action").is_object()) << i;
  }
  const json over = first_of(fx, 2, "over");
  ASSERT_TRUE(over.is_object());
  EXPECT_FALSE(over["forfeit"]);
  fx = rooms_.receive(1, shot(90, i), 4);
  EXPECT_EQ(first_of(fx, 1, "refused")["reason"], "the game is over");
}

TEST_F(RoomsTest, MalformedMessagesCloseThatConnectionOnly) {
  start_game();
  const std::vector<std::string> bad = {
      "not json",
      "[1, 2]",
      R"({"kind": "create"})",
      R"({"type": "launch"})",
      R"({"type": 7})",
      R"({"type": "join", "room": 42})",
      R"({"type": "act", "index": -1, "action": {}})",
      R"({"type": "act", "index": 0, "action": "shoot"})",
      R"({"type": "ping", "extra": 1})",
      std::string(9000, ' '),
      std::string(4000, '[') + std::string(4000, ']'),  // deep, and not an object
  };
  ClientId c = 10;
  for (const std::string& text : bad) {
    const Effects fx = rooms_.receive(c, text, 5);
    EXPECT_TRUE(first_of(fx, c, "error").is_object()) << text;
    EXPECT_TRUE(closes(fx, c)) << text;
    ++c;
  }
  // A player who sends garbage loses the connection, not the seat.
  const Effects fx = rooms_.receive(2, "{", 5);
  EXPECT_TRUE(closes(fx, 2));
  EXPECT_EQ(first_of(fx, 1, "seats")["connected"], json({true, false}));
  // The game goes on.
  EXPECT_EQ(rooms_.rooms(), 1u);
  EXPECT_TRUE(first_of(rooms_.receive(1, shot(90, 0), 6), 1, "action").is_object());
}

TEST_F(RoomsTest, RequestsThatCannotBeDoneAreRefused) {
  EXPECT_NE(first_of(rooms_.receive(1, R"({"type": "join", "room": "ZZZZZZ"})", 0), 1,
                     "refused")["reason"]
                .get<std::string>()
                .find("no room"),
            std::string::npos);
  const json seeded = first_of(
      rooms_.receive(1, R"({"type": "create", "game": {"game": "nine_ball", "seed": 4}})", 0), 1,
      "refused");
  EXPECT_NE(seeded["reason"].get<std::string>().find("game.seed"), std::string::npos) << seeded;
  const json unknown = first_of(
      rooms_.receive(1, R"({"type": "create", "game": {"game": "croquet"}})", 0), 1, "refused");
  EXPECT_NE(unknown["reason"].get<std::string>().find("croquet"), std::string::npos) << unknown;
  // Every game the page offers.
  ClientId c = 20;
  for (const char* g : {"eight_ball", "nine_ball", "snooker"}) {
    const Effects fx =
        rooms_.receive(c, std::string(R"({"type": "create", "game": {"game": ")") + g + "\"}}", 0);
    EXPECT_EQ(first_of(fx, c, "joined")["config"]["game"], g);
    ++c;
  }
  // The rooms' limit (3), and one room per client.
  EXPECT_NE(
      first_of(rooms_.receive(30, kQuick, 0), 30, "refused")["reason"].get<std::string>().find(
          "limit"),
      std::string::npos);
  EXPECT_NE(
      first_of(rooms_.receive(20, kQuick, 0), 20, "refused")["reason"].get<std::string>().find(
          "already in room"),
      std::string::npos);
}

TEST_F(RoomsTest, ASeatIsTakenBackWithItsTokenOnly) {
  start_game();
  const std::string code = created_["room"];
  EXPECT_TRUE(first_of(rooms_.receive(1, shot(90, 0), 2), 2, "action").is_object());
  rooms_.disconnect(1, 3);
  // The room code alone does not give the seat back.
  const json wrong = first_of(
      rooms_.receive(5, R"({"type": "rejoin", "room": ")" + code + R"(", "token": "00"})", 4), 5,
      "refused");
  EXPECT_TRUE(wrong.is_object());
  const Effects back =
      rooms_.receive(6,
                     R"({"type": "rejoin", "room": ")" + code + R"(", "token": ")" +
                         created_["token"].get<std::string>() + "\"}",
                     5);
  const json j = first_of(back, 6, "joined");
  EXPECT_EQ(j["seat"], 0);
  EXPECT_EQ(j["actions"].size(), 1u);  // the log to continue from
  EXPECT_EQ(first_of(back, 2, "seats")["connected"], json({true, true}));
  // A rejoin while another connection plays the seat (a second tab with
  // the same token) is refused, saying so; nothing changes for the seat.
  const std::string rejoin = R"({"type": "rejoin", "room": ")" + code + R"(", "token": ")" +
                             created_["token"].get<std::string>() + "\"";
  const Effects second = rooms_.receive(7, rejoin + "}", 6);
  const json busy = first_of(second, 7, "refused");
  EXPECT_EQ(busy["seat_in_use"], true) << busy;
  EXPECT_NE(busy["reason"].get<std::string>().find("another connection"), std::string::npos);
  EXPECT_FALSE(closes(second, 6));
  EXPECT_TRUE(to(second, 6).empty());
  // The refused tab then joins: both seats are taken, so it watches.
  const json watching =
      first_of(rooms_.receive(7, R"({"type": "join", "room": ")" + code + "\"}", 6), 7, "joined");
  EXPECT_TRUE(watching["seat"].is_null()) << watching;
  // The seat's own page coming back (replace): the old connection, not yet
  // noticed to be gone, is told it was replaced and closed.
  const Effects again = rooms_.receive(8, rejoin + R"(, "replace": true})", 7);
  EXPECT_TRUE(closes(again, 6));
  EXPECT_EQ(first_of(again, 6, "replaced")["reason"], "the seat was taken back by a rejoin");
  EXPECT_EQ(first_of(again, 8, "joined")["seat"], 0);
  EXPECT_TRUE(
      first_of(rooms_.receive(9, rejoin + R"(, "replace": 1})", 8), 9, "error").is_object());
}

TEST_F(RoomsTest, ASecondTabTakesTheFreeSeat) {
  // The creator's token is in a second tab of the same browser before
  // anyone joined: that tab's rejoin is refused, and it takes seat 1.
  const Effects made = rooms_.receive(1, kQuick, 0);
  const json created = first_of(made, 1, "joined");
  const std::string code = created["room"];
  const Effects second =
      rooms_.receive(2,
                     R"({"type": "rejoin", "room": ")" + code + R"(", "token": ")" +
                         created["token"].get<std::string>() + "\"}",
                     1);
  EXPECT_EQ(first_of(second, 2, "refused")["seat_in_use"], true);
  EXPECT_TRUE(to(second, 1).empty());  // the first tab is left alone
  const json seated =
      first_of(rooms_.receive(2, R"({"type": "join", "room": ")" + code + "\"}", 2), 2, "joined");
  EXPECT_EQ(seated["seat"], 1);
  EXPECT_NE(seated["token"], created["token"]);
}

TEST_F(RoomsTest, ASeatLeftEmptyForfeitsAndEmptyRoomsExpire) {
  start_game();
  rooms_.disconnect(2, 10);
  EXPECT_TRUE(rooms_.tick(129).messages.empty());
  const Effects fx = rooms_.tick(130);
  const json over = first_of(fx, 1, "over");
  ASSERT_TRUE(over.is_object());
  EXPECT_EQ(over["winner"], 0);
  EXPECT_TRUE(over["forfeit"]);
  EXPECT_NE(over["result"].get<std::string>().find("Player 2"), std::string::npos);
  rooms_.disconnect(1, 140);
  rooms_.disconnect(1, 140);  // harmless twice
  rooms_.tick(739);
  EXPECT_EQ(rooms_.rooms(), 1u);
  rooms_.tick(740);
  EXPECT_EQ(rooms_.rooms(), 0u);
  EXPECT_EQ(rooms_.clients(), 0u);
}

TEST_F(RoomsTest, AForfeitEndsTheRecord) {
  start_game();
  const std::string code = created_["room"];
  ASSERT_TRUE(first_of(rooms_.receive(1, shot(90, 0), 2), 2, "action").is_object());
  rooms_.disconnect(1, 10);
  EXPECT_TRUE(rooms_.tick(129).records.empty());
  const Effects fx = rooms_.tick(130);
  // The record is written again, with its ending: Player 1 left.
  ASSERT_EQ(fx.records.size(), 1u);
  EXPECT_EQ(fx.records[0].name, "test-000001-" + code + ".json");
  EXPECT_NE(fx.records[0].text.find("\"version\": 3,"), std::string::npos);
  const auto read = breakshot::read_record(fx.records[0].text);
  ASSERT_TRUE(std::holds_alternative<breakshot::GameRecord>(read));
  const auto& record = std::get<breakshot::GameRecord>(read);
  EXPECT_EQ(record.actions.size(), 1u);
  ASSERT_TRUE(record.ending.has_value());
  EXPECT_EQ(record.ending->kind, breakshot::GameEnding::Kind::forfeit);
  EXPECT_EQ(record.ending->player, 0);
  EXPECT_EQ(record.ending->winner, 1);
  EXPECT_EQ(record.ending->text, first_of(fx, 2, "over")["result"]);
  const breakshot::ReplayReport rep = breakshot::replay(record);
  EXPECT_TRUE(rep.identical) << rep.message;
  // Once over, nothing more is written.
  EXPECT_TRUE(rooms_.tick(200).records.empty());
}

TEST_F(RoomsTest, BothSeatsLeftEmptyAbandonTheGameInTheRecord) {
  start_game();
  rooms_.disconnect(1, 10);
  rooms_.disconnect(2, 11);
  const Effects fx = rooms_.tick(131);
  EXPECT_EQ(first_of(fx, 1, "over"), json());  // nobody is there to be told
  ASSERT_EQ(fx.records.size(), 1u);
  const auto read = breakshot::read_record(fx.records[0].text);
  ASSERT_TRUE(std::holds_alternative<breakshot::GameRecord>(read));
  const auto& record = std::get<breakshot::GameRecord>(read);
  EXPECT_TRUE(record.actions.empty());
  ASSERT_TRUE(record.ending.has_value());
  EXPECT_EQ(record.ending->kind, breakshot::GameEnding::Kind::abandoned);
  EXPECT_EQ(record.ending->player, -1);
  EXPECT_EQ(record.ending->winner, -1);
  EXPECT_TRUE(breakshot::replay(record).identical);
}

TEST(StateHash, IsFnv1a64) {
  EXPECT_EQ(breakshot::online::state_hash(""), "cbf29ce484222325");
  EXPECT_EQ(breakshot::online::state_hash("a"), "af63dc4c8601ec8c");
}

}  // namespace

}  // namespace test_rooms
