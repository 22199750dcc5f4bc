// The rooms of online play (src/web/rooms.hpp); the message
// format is in docs/web.md, "Online play".
//
// A room holds one game (a BsWebGame of the browser facade, both seats
// "human", so no noise: the action played is the action sent), its two
// seats (each with the token that takes it back) and its watchers. Every
// client is in at most one room. Messages that are not what the format
// says (not JSON, not an object, an unknown type, a field of the wrong
// type, too long) close the connection that sent them; requests that are
// well formed but cannot be done (no such room, not your turn, an action
// the rules refuse) are refused with the reason and the connection stays.
#include "web/rooms.hpp"

#include <array>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <utility>
#include <variant>

#include "breakshot/record.hpp"
#include "breakshot/record_io.hpp"
#include "web_api.hpp"

namespace breakshot::online {

using json = nlohmann::json;

std::string state_hash(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

namespace {

// Room codes: no 0/O, 1/I/L, so that a code read aloud is typed right.
constexpr std::string_view kCodeAlphabet = "ABCDEFGHJKMNPQRSTUVWXYZ23456789";
constexpr std::size_t kCodeLength = 6;
constexpr std::size_t kTokenLength = 32;

// A well-formed message the rules or the rooms refuse: answered, not closed.
struct Refused {
  std::string reason;
  /// A rejoin of a seat another connection plays: the reply says so
  /// ("seat_in_use": true), and the page takes the free seat or watches.
  bool seat_in_use = false;
};
// A malformed message: answered with the reason, then the connection closes.
struct Malformed {
  std::string reason;
};

struct GameDeleter {
  void operator()(BsWebGame* g) const { bs_web_game_free(g); }
};

struct Seat {
  std::string token;
  ClientId client = 0;  // 0: empty
  bool taken = false;   // someone has sat here
  double empty_since = 0;
};

struct Room {
  std::string code;
  std::uint64_t serial = 0;
  json config;  // the config the game was made with (seed and players included)
  std::unique_ptr<BsWebGame, GameDeleter> game;
  json actions = json::array();  // as played (the records' form)
  std::string hash;              // of the state now
  std::array<Seat, 2> seats;
  std::set<ClientId> watchers;
  bool over = false;
  int winner = -1;
  std::string result;
  bool forfeit = false;
  double idle_since = 0;  // when the last client left

  bool started() const { return seats[0].taken && seats[1].taken; }
  std::size_t connected() const {
    return watchers.size() + (seats[0].client != 0 ? 1 : 0) + (seats[1].client != 0 ? 1 : 0);
  }
};

struct Member {
  std::string room;
  int seat = -1;  // -1: a watcher
};

const json& field(const json& msg, const char* key) {
  const auto it = msg.find(key);
  if (it == msg.end()) throw Malformed{std::string("missing field '") + key + "'"};
  return *it;
}

const std::string& string_field(const json& msg, const char* key) {
  const json& v = field(msg, key);
  if (!v.is_string()) throw Malformed{std::string("field '") + key + "' must be a string"};
  return v.get_ref<const std::string&>();
}

void only_keys(const json& msg, std::initializer_list<std::string_view> keys) {
  for (const auto& [k, v] : msg.items()) {
    bool known = false;
    for (const std::string_view key : keys) known = known || k == key;
    if (!known)
      throw Malformed{"unknown field '" + k + "' in a '" + msg["type"].get<std::string>() +
                      "' message"};
  }
}

std::string error_text(const char* reply) {
  const json j = json::parse(reply, nullptr, false);
  if (j.is_object() && j.contains("error") && j["error"].is_string()) {
    return j["error"].get<std::string>();
  }
  return "refused";
}

}  // namespace

struct Rooms::Impl {
  RoomLimits limits;
  std::function<std::uint64_t()> random;
  std::map<std::string, Room> rooms;
  std::map<ClientId, Member> members;
  std::uint64_t serial = 0;

  // --- sending ------------------------------------------------------------

  static void send(Effects& fx, ClientId to, const json& msg) {
    fx.messages.push_back({to, msg.dump()});
  }
  static void broadcast(Effects& fx, const Room& r, const json& msg) {
    const std::string text = msg.dump();
    for (const Seat& s : r.seats) {
      if (s.client != 0) fx.messages.push_back({s.client, text});
    }
    for (const ClientId w : r.watchers) fx.messages.push_back({w, text});
  }
  static json presence(const Room& r) {
    return {{"type", "seats"},
            {"connected", {r.seats[0].client != 0, r.seats[1].client != 0}},
            {"taken", {r.seats[0].taken, r.seats[1].taken}},
            {"watchers", r.watchers.size()}};
  }
  static json over_json(const Room& r) {
    return {{"type", "over"}, {"winner", r.winner}, {"result", r.result}, {"forfeit", r.forfeit}};
  }
  /// The room's record, written again whole (the same file each time):
  /// after every action, and with its ending when a forfeit ends the game.
  void record(Effects& fx, const Room& r, const std::optional<GameEnding>& ending = {}) const {
    char serial_text[32];
    std::snprintf(serial_text, sizeof serial_text, "%06llu",
                  static_cast<unsigned long long>(r.serial));
    std::string text = bs_web_game_record(r.game.get());
    if (ending) {
      auto parsed = read_record(text);
      if (const auto* err = std::get_if<RecordError>(&parsed)) {
        // The facade wrote it: not expected. Keep the record as it is.
        std::fprintf(stderr, "breakshot serve: the record of room %s does not read back (%s: %s)\n",
                     r.code.c_str(), err->path.c_str(), err->reason.c_str());
      } else {
        GameRecord& rec = std::get<GameRecord>(parsed);
        rec.ending = ending;
        text = write_record(rec);
      }
    }
    fx.records.push_back(
        {limits.record_prefix + "-" + serial_text + "-" + r.code + ".json", std::move(text)});
  }

  // --- codes and tokens ---------------------------------------------------

  std::string new_code() {
    for (;;) {
      std::string code;
      std::uint64_t bits = random();
      for (std::size_t i = 0; i < kCodeLength; ++i) {
        code.push_back(kCodeAlphabet[bits % kCodeAlphabet.size()]);
        bits /= kCodeAlphabet.size();
      }
      if (!rooms.contains(code)) return code;
    }
  }
  std::string new_token() {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string t;
    while (t.size() < kTokenLength) {
      std::uint64_t bits = random();
      for (int i = 0; i < 16 && t.size() < kTokenLength; ++i, bits >>= 4)
        t.push_back(kHex[bits & 15]);
    }
    return t;
  }

  Room& room_named(const json& msg) {
    std::string code = string_field(msg, "room");
    for (char& c : code) {
      if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    }
    const auto it = rooms.find(code);
    if (it == rooms.end())
      throw Refused{"no room " + (code.size() <= kCodeLength ? code : "of that code")};
    return it->second;
  }

  // --- joining and leaving -----------------------------------------------

  void welcome(Effects& fx, ClientId c, const Room& r, int seat) {
    json msg = {{"type", "joined"},   {"room", r.code},       {"seat", nullptr},
                {"config", r.config}, {"actions", r.actions}, {"hash", r.hash}};
    if (seat >= 0) {
      msg["seat"] = seat;
      msg["token"] = r.seats[static_cast<std::size_t>(seat)].token;
    }
    send(fx, c, msg);
    broadcast(fx, r, presence(r));
    if (r.over) send(fx, c, over_json(r));
  }

  void take_seat(Room& r, ClientId c, int seat) {
    Seat& s = r.seats[static_cast<std::size_t>(seat)];
    s.client = c;
    s.taken = true;
    members[c] = Member{r.code, seat};
  }

  void create(Effects& fx, ClientId c, const json& msg) {
    only_keys(msg, {"type", "game"});
    const json& game = field(msg, "game");
    if (!game.is_object()) throw Malformed{"field 'game' must be an object"};
    if (rooms.size() >= limits.max_rooms) {
      throw Refused{"the server has " + std::to_string(rooms.size()) + " rooms, its limit"};
    }
    json config = json::object();
    for (const auto& [k, v] : game.items()) {
      if (k != "game" && k != "table" && k != "breaker" && k != "carom" && k != "physics") {
        throw Refused{"game." + k + ": not a choice of an online game (game, table, breaker, " +
                      "carom and physics are)"};
      }
      config[k] = v;
    }
    config["players"] = {"human", "human"};
    config["seed"] = std::to_string(random() >> 11);  // up to 2^53, as links keep it
    std::unique_ptr<BsWebGame, GameDeleter> g(bs_web_game_new(config.dump().c_str()));
    if (!g) throw Refused{"game: " + error_text(bs_web_last_error())};
    Room r;
    r.code = new_code();
    r.serial = ++serial;
    r.config = std::move(config);
    r.game = std::move(g);
    r.hash = state_hash(bs_web_game_state(r.game.get()));
    r.seats[0].token = new_token();
    r.seats[1].token = new_token();
    const std::string code = r.code;
    Room& room = rooms.emplace(code, std::move(r)).first->second;
    take_seat(room, c, 0);
    welcome(fx, c, room, 0);
  }

  void join(Effects& fx, ClientId c, const json& msg, double now) {
    only_keys(msg, {"type", "room", "watch"});
    bool watch = false;
    if (const auto it = msg.find("watch"); it != msg.end()) {
      if (!it->is_boolean()) throw Malformed{"field 'watch' must be true or false"};
      watch = it->get<bool>();
    }
    Room& r = room_named(msg);
    if (!watch && !r.seats[1].taken) {
      take_seat(r, c, 1);
      // The game starts now: an empty first seat has waited from here.
      if (r.seats[0].client == 0) r.seats[0].empty_since = now;
      welcome(fx, c, r, 1);
      return;
    }
    if (r.watchers.size() >= limits.max_watchers) {
      throw Refused{"room " + r.code + " has " + std::to_string(r.watchers.size()) +
                    " watchers, its limit"};
    }
    r.watchers.insert(c);
    members[c] = Member{r.code, -1};
    welcome(fx, c, r, -1);
  }

  void rejoin(Effects& fx, ClientId c, const json& msg) {
    only_keys(msg, {"type", "room", "token", "replace"});
    bool replace = false;
    if (const auto it = msg.find("replace"); it != msg.end()) {
      if (!it->is_boolean()) throw Malformed{"field 'replace' must be true or false"};
      replace = it->get<bool>();
    }
    Room& r = room_named(msg);
    const std::string& token = string_field(msg, "token");
    int seat = -1;
    for (int k = 0; k < 2; ++k) {
      const Seat& s = r.seats[static_cast<std::size_t>(k)];
      if (s.taken && s.token.size() == token.size()) {
        unsigned diff = 0;  // compared in constant time
        for (std::size_t i = 0; i < token.size(); ++i)
          diff |= static_cast<unsigned>(s.token[i] ^ token[i]);
        if (diff == 0) seat = k;
      }
    }
    if (seat < 0) throw Refused{"that token holds no seat of room " + r.code};
    Seat& s = r.seats[static_cast<std::size_t>(seat)];
    if (s.client != 0) {
      // Another connection plays the seat: a second tab of the same
      // browser, which has the token too, is refused (it takes the free
      // seat or watches); the seat's own page coming back after its
      // connection broke (replace) takes it, and the old connection, not
      // yet noticed to be gone, is told so and closed.
      if (!replace) {
        throw Refused{"seat " + std::to_string(seat) + " of room " + r.code +
                          " is played by another connection",
                      true};
      }
      send(fx, s.client, {{"type", "replaced"}, {"reason", "the seat was taken back by a rejoin"}});
      fx.close.push_back(s.client);
      members.erase(s.client);
    }
    take_seat(r, c, seat);
    welcome(fx, c, r, seat);
  }

  void leave(Effects& fx, ClientId c, double now) {
    const auto m = members.find(c);
    if (m == members.end()) return;
    const Member member = m->second;
    members.erase(m);
    const auto it = rooms.find(member.room);
    if (it == rooms.end()) return;
    Room& r = it->second;
    if (member.seat >= 0) {
      Seat& s = r.seats[static_cast<std::size_t>(member.seat)];
      if (s.client == c) {
        s.client = 0;
        s.empty_since = now;
      }
    } else {
      r.watchers.erase(c);
    }
    if (r.connected() == 0) r.idle_since = now;
    broadcast(fx, r, presence(r));
  }

  // --- playing ------------------------------------------------------------

  void act(Effects& fx, ClientId c, const json& msg) {
    only_keys(msg, {"type", "index", "action"});
    const json& index = field(msg, "index");
    if (!index.is_number_unsigned()) throw Malformed{"field 'index' must be a whole number"};
    const json& action = field(msg, "action");
    if (!action.is_object()) throw Malformed{"field 'action' must be an object"};
    const auto m = members.find(c);
    if (m == members.end()) throw Refused{"not in a room: create or join one first"};
    Room& r = rooms.at(m->second.room);
    const int seat = m->second.seat;
    if (seat < 0) throw Refused{"a watcher does not play"};
    if (r.over) throw Refused{"the game is over"};
    if (!r.started()) throw Refused{"the other player has not come yet"};
    const std::size_t n = r.actions.size();
    if (index.get<std::uint64_t>() != n) {
      throw Refused{"index " + index.dump() + " is not the next action's (" + std::to_string(n) +
                    ")"};
    }
    const json state = json::parse(bs_web_game_state(r.game.get()));
    if (state.at("player").get<int>() != seat) throw Refused{"not your turn"};
    const json reply =
        json::parse(bs_web_game_act(r.game.get(), action.dump().c_str()), nullptr, false);
    if (!reply.is_object()) throw Refused{"the action could not be played"};
    if (reply.contains("error")) throw Refused{"action: " + reply["error"].get<std::string>()};
    r.actions.push_back(reply.at("executed"));
    const std::string state_text = bs_web_game_state(r.game.get());
    r.hash = state_hash(state_text);
    broadcast(fx, r,
              {{"type", "action"},
               {"index", n},
               {"seat", seat},
               {"action", reply.at("executed")},
               {"hash", r.hash}});
    record(fx, r);
    const json after = json::parse(state_text);
    if (after.at("phase").get<std::string>() == "game_over") {
      r.over = true;
      r.winner = after.at("winner").get<int>();
      r.result = after.at("result").get<std::string>();
      broadcast(fx, r, over_json(r));
    }
  }

  Effects receive(ClientId c, std::string_view text, double now) {
    Effects fx;
    try {
      if (text.size() > limits.max_message) {
        throw Malformed{"a message of " + std::to_string(text.size()) + " bytes (at most " +
                        std::to_string(limits.max_message) + ")"};
      }
      const json msg = json::parse(text, nullptr, false);
      if (msg.is_discarded()) throw Malformed{"not JSON"};
      if (!msg.is_object()) throw Malformed{"not a JSON object"};
      const std::string& type = string_field(msg, "type");
      const bool in_room = members.contains(c);
      if (type == "create" || type == "join" || type == "rejoin") {
        if (in_room) throw Refused{"already in room " + members[c].room};
        if (type == "create") create(fx, c, msg);
        if (type == "join") join(fx, c, msg, now);
        if (type == "rejoin") rejoin(fx, c, msg);
      } else if (type == "act") {
        act(fx, c, msg);
      } else if (type == "ping") {
        only_keys(msg, {"type"});
        send(fx, c, {{"type", "pong"}});
      } else {
        throw Malformed{"unknown message type '" + type + "'"};
      }
    } catch (const Refused& e) {
      json reply = {{"type", "refused"}, {"reason", e.reason}};
      if (e.seat_in_use) reply["seat_in_use"] = true;
      send(fx, c, reply);
    } catch (const Malformed& e) {
      send(fx, c, {{"type", "error"}, {"reason", e.reason}});
      fx.close.push_back(c);
      leave(fx, c, now);
    }
    return fx;
  }

  Effects tick(double now) {
    Effects fx;
    for (auto it = rooms.begin(); it != rooms.end();) {
      Room& r = it->second;
      if (r.started() && !r.over) {
        std::array<bool, 2> gone{};
        for (std::size_t k = 0; k < 2; ++k) {
          gone[k] = r.seats[k].client == 0 && now - r.seats[k].empty_since >= limits.seat_timeout;
        }
        if (gone[0] || gone[1]) {
          r.over = true;
          r.forfeit = true;
          GameEnding ending;
          if (gone[0] && gone[1]) {
            r.winner = -1;
            r.result = "both players left the table: the game is abandoned";
            ending.kind = GameEnding::Kind::abandoned;
          } else {
            const int left = gone[0] ? 0 : 1;
            r.winner = 1 - left;
            r.result = "Player " + std::to_string(left + 1) + " left the table for " +
                       std::to_string(static_cast<long>(limits.seat_timeout)) + " s and forfeits";
            ending.kind = GameEnding::Kind::forfeit;
            ending.player = left;
          }
          ending.winner = r.winner;
          ending.text = r.result;
          broadcast(fx, r, over_json(r));
          record(fx, r, ending);
        }
      }
      const bool waiting = !r.started() || r.over;
      if (waiting && r.connected() == 0 && now - r.idle_since >= limits.room_timeout) {
        it = rooms.erase(it);
      } else {
        ++it;
      }
    }
    return fx;
  }
};

Rooms::Rooms(RoomLimits limits, std::function<std::uint64_t()> random)
    : impl_(std::make_unique<Impl>()) {
  impl_->limits = std::move(limits);
  impl_->random = std::move(random);
}

Rooms::~Rooms() = default;

Effects Rooms::receive(ClientId from, std::string_view text, double now) {
  return impl_->receive(from, text, now);
}

Effects Rooms::disconnect(ClientId client, double now) {
  Effects fx;
  impl_->leave(fx, client, now);
  return fx;
}

Effects Rooms::tick(double now) { return impl_->tick(now); }

std::size_t Rooms::rooms() const { return impl_->rooms.size(); }
std::size_t Rooms::clients() const { return impl_->members.size(); }

}  // namespace breakshot::online
