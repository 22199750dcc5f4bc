// Links. A link is "v2." followed by the base64url (RFC 4648 section 5,
// no padding) of a compact JSON object:
//   {"e": "engine version", "g": game, "t": table,
//    "ph": {"cushion_model", "ball_ball_model",
//           "ball_ball_friction": {"a", "b", "c"} | number,
//           "airborne": true (only when on),
//           "spinning_friction": number (only when not 0.044)},
//    "s": "seed (decimal)", "b": breaker, "p": [seat0, seat1],
//    "n": ai_budget (only when set), "c": three-cushion's rules
//    {"target", "innings_limit", "equalizing_inning"} (three-cushion
//    only), "a": [action, ...]}
// "e" is the library version that wrote the link (version.hpp) and "ph"
// the game's physics, as in a game record (record_json.cpp). A "v1." link
// (before issue 22) has neither and is read as played with the legacy
// physics (kLegacyGamePhysics), on which it replays; a physics name or
// field this build does not know is refused naming the link's engine.
// with each action as chosen (before noise):
//   ["p", X, Y]                                      place the cue ball
//   ["s", SPEED, PHI, THETA, A, B, ball, pocket, f]  shoot; ball and
//        pocket -1 without a call; f = 1 safety + 2 push-out; a snooker
//        shot that nominates a ball has that ball number as a 10th entry,
//        a three-cushion shot that names the ball struck (Shoot::cue_ball)
//        that ball
//   ["d", "choice"]                                  decide
// where the capitals are doubles written as the hexadecimal of their IEEE
// bits, without leading zeros ("0" for +0, "8000000000000000" for -0,
// "3ff0000000000000" for 1.0), so nothing is rounded. The executed strike
// is not stored: it is perturb(intended, seat noise, radius,
// GameSeeds::noise(S, i)), re-derived exactly as the record's replay does, so a
// link holds the same game as the record, at about half the length.
// bs_game_from_link replays the actions through the rules and stops with
// an error naming the first one refused ("a[7]: ...").

#include "page.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "breakshot.h"
#include "breakshot/game.hpp"
#include "breakshot/record.hpp"
#include "breakshot/version.hpp"

namespace capi::page {

namespace {

constexpr std::string_view kLinkPrefix = "v2.";
/// Links written before the engine and the physics were in them.
constexpr std::string_view kLinkPrefixV1 = "v1.";

// ---------------------------------------------------------------------------
// Links: base64url and doubles as bits

constexpr char kB64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

std::string base64url(std::string_view in) {
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= in.size(); i += 3) {
    const std::uint32_t v = (std::uint32_t{static_cast<unsigned char>(in[i])} << 16) |
                            (std::uint32_t{static_cast<unsigned char>(in[i + 1])} << 8) |
                            std::uint32_t{static_cast<unsigned char>(in[i + 2])};
    for (int k = 3; k >= 0; --k) out.push_back(kB64[(v >> (6 * k)) & 63]);
  }
  const std::size_t rest = in.size() - i;
  if (rest > 0) {
    std::uint32_t v = std::uint32_t{static_cast<unsigned char>(in[i])} << 16;
    if (rest == 2) v |= std::uint32_t{static_cast<unsigned char>(in[i + 1])} << 8;
    out.push_back(kB64[(v >> 18) & 63]);
    out.push_back(kB64[(v >> 12) & 63]);
    if (rest == 2) out.push_back(kB64[(v >> 6) & 63]);
  }
  return out;
}

std::optional<std::string> unbase64url(std::string_view in) {
  if (in.size() % 4 == 1) return std::nullopt;
  std::string out;
  out.reserve(in.size() / 4 * 3 + 2);
  std::uint32_t acc = 0;
  int bits = 0;
  for (const char c : in) {
    std::uint32_t v = 0;
    if (c >= 'A' && c <= 'Z') {
      v = static_cast<std::uint32_t>(c - 'A');
    } else if (c >= 'a' && c <= 'z') {
      v = static_cast<std::uint32_t>(c - 'a' + 26);
    } else if (c >= '0' && c <= '9') {
      v = static_cast<std::uint32_t>(c - '0' + 52);
    } else if (c == '-') {
      v = 62;
    } else if (c == '_') {
      v = 63;
    } else {
      return std::nullopt;
    }
    acc = (acc << 6) | v;
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((acc >> bits) & 0xff));
    }
  }
  return out;
}

std::string double_hex(double d) {
  std::uint64_t u = 0;
  std::memcpy(&u, &d, sizeof u);
  if (u == 0) return "0";
  static constexpr char kHex[] = "0123456789abcdef";
  std::string s;
  while (u != 0) {
    s.insert(s.begin(), kHex[u & 15]);
    u >>= 4;
  }
  return s;
}

double hex_double(const json& v, const std::string& path) {
  const std::string& s = text(v, path);
  bool ok = !s.empty() && s.size() <= 16;
  std::uint64_t u = 0;
  for (const char c : s) {
    unsigned d = 0;
    if (c >= '0' && c <= '9') {
      d = static_cast<unsigned>(c - '0');
    } else if (c >= 'a' && c <= 'f') {
      d = static_cast<unsigned>(c - 'a' + 10);
    } else {
      ok = false;
      break;
    }
    u = (u << 4) | d;
  }
  if (!ok) bad(path, "expected the hexadecimal bits of a double (1 to 16 digits 0-9a-f)");
  double d = 0.0;
  std::memcpy(&d, &u, sizeof d);
  if (!std::isfinite(d)) bad(path, "not a finite number");
  return d;
}

std::string link_text(const BsGame& g) {
  const bs::GameRecord& record = g.session.record();
  ojson j = ojson::object();
  j["e"] = std::string(bs::kVersion);
  j["g"] = bs::to_string(record.config.game);
  j["t"] = record.config.table_size;
  j["ph"] = bs::json_io::physics_json(record.config.physics);
  j["s"] = bs::json_io::seed_json(record.seed);
  j["b"] = record.start.breaker;
  j["p"] = ojson::array({record.players[0], record.players[1]});
  if (g.ai_budget) j["n"] = *g.ai_budget;
  if (record.config.game == bs::GameType::three_cushion) {
    const bs::CaromRules& c = record.config.carom;
    ojson k = ojson::object();
    k["target"] = c.target;
    k["innings_limit"] = c.innings_limit;
    k["equalizing_inning"] = c.equalizing_inning;
    j["c"] = k;
  }
  ojson actions = ojson::array();
  for (const bs::RecordedAction& ra : record.actions) {
    if (const auto* p = std::get_if<bs::PlaceCueBall>(&ra.action)) {
      actions.push_back(ojson::array({"p", double_hex(p->position.x), double_hex(p->position.y)}));
    } else if (const auto* s = std::get_if<bs::Shoot>(&ra.action)) {
      const bs::CueStrike& k = ra.intended ? *ra.intended : s->strike;
      actions.push_back(ojson::array(
          {"s", double_hex(k.speed), double_hex(k.phi), double_hex(k.theta), double_hex(k.a),
           double_hex(k.b), s->call ? s->call->ball : -1, s->call ? s->call->pocket : -1,
           (s->safety ? 1 : 0) + (s->push_out ? 2 : 0)}));
      if (s->nominate) actions.back().push_back(*s->nominate);
      if (s->cue_ball) actions.back().push_back(*s->cue_ball);
    } else {
      actions.push_back(ojson::array({"d", bs::to_string(std::get<bs::Decide>(ra.action).choice)}));
    }
  }
  j["a"] = actions;
  return std::string(kLinkPrefix) + base64url(j.dump());
}

bs::Action link_action(const json& v, const std::string& path, bs::GameType game) {
  if (!v.is_array() || v.empty() || !v[0].is_string()) bad(path, "expected an action array [\"p\"|\"s\"|\"d\", ...]");
  const std::string& k = v[0].get_ref<const std::string&>();
  if (k == "p") {
    if (v.size() != 3) bad(path, "expected [\"p\", X, Y]");
    return bs::PlaceCueBall{{hex_double(v[1], index_path(path, 1)), hex_double(v[2], index_path(path, 2))}};
  }
  if (k == "s") {
    if (v.size() != 9 && v.size() != 10) {
      bad(path,
          "expected [\"s\", SPEED, PHI, THETA, A, B, ball, pocket, flags] and, in snooker, "
          "the nominated ball (three_cushion: the ball struck)");
    }
    bs::Shoot s;
    s.strike.speed = hex_double(v[1], index_path(path, 1));
    s.strike.phi = hex_double(v[2], index_path(path, 2));
    s.strike.theta = hex_double(v[3], index_path(path, 3));
    s.strike.a = hex_double(v[4], index_path(path, 4));
    s.strike.b = hex_double(v[5], index_path(path, 5));
    const auto ball = integer(v[6], index_path(path, 6), -1, 1000);
    const auto pocket = integer(v[7], index_path(path, 7), -1, 1000);
    if ((ball < 0) != (pocket < 0)) bad(index_path(path, 6), "a call needs both a ball and a pocket");
    if (ball >= 0) s.call = bs::Call{static_cast<int>(ball), static_cast<int>(pocket)};
    const auto flags = integer(v[8], index_path(path, 8), 0, 3);
    s.safety = (flags & 1) != 0;
    s.push_out = (flags & 2) != 0;
    if (v.size() == 10 && game == bs::GameType::three_cushion) {
      s.cue_ball = static_cast<int>(integer(v[9], index_path(path, 9), 0, 2));
    } else if (v.size() == 10) {
      s.nominate = static_cast<int>(integer(v[9], index_path(path, 9), 1, 21));
    }
    return s;
  }
  if (k == "d") {
    if (v.size() != 2) bad(path, "expected [\"d\", \"choice\"]");
    Reader r;
    bs::Decide decide;
    r.must(r.choice(v[1], index_path(path, 1), decide.choice));
    return decide;
  }
  bad(index_path(path, 0), "unknown action kind \"" + k + "\" (known: p, s, d)");
}

/// bs_game_from_link's game: the link's actions replayed through the
/// rules; a bad input naming the first action refused.
std::unique_ptr<BsGame> game_from_link(std::string_view text_view) {
  // A link pasted with its URL fragment around it.
  if (const auto at = text_view.find("game="); at != std::string_view::npos) {
    text_view.remove_prefix(at + 5);
    text_view = text_view.substr(0, text_view.find('&'));
  }
  const bool v1 = text_view.substr(0, kLinkPrefixV1.size()) == kLinkPrefixV1;
  if (!v1 && text_view.substr(0, kLinkPrefix.size()) != kLinkPrefix) {
    std::string_view head = text_view.substr(0, text_view.find('.'));
    if (head.size() > 8) head = head.substr(0, 8);
    bad("link", "expected a link starting with \"v2.\" or \"v1.\" (this breakshot, " +
                    std::string(bs::kVersion) + ", reads those), not \"" + std::string(head) +
                    "\"");
  }
  const std::string_view prefix = v1 ? kLinkPrefixV1 : kLinkPrefix;
  const std::optional<std::string> decoded = unbase64url(text_view.substr(prefix.size()));
  if (!decoded) bad("link", "not base64url text after \"" + std::string(prefix) + "\"");
  const json doc = parse_text(decoded->data(), decoded->size(), "link", "link");
  GameInput in;
  if (v1) {
    object(doc, "link", {"g", "t", "s", "b", "p", "n", "a"});
    in.config.physics = bs::kLegacyGamePhysics;
  } else {
    // "c" is a key of three-cushion's links only: the other games'
    // messages keep their list of keys.
    const json* g = doc.is_object() ? find(doc, "g") : nullptr;
    if (g != nullptr && g->is_string() && g->get_ref<const std::string&>() == "three_cushion") {
      object(doc, "link", {"e", "g", "t", "ph", "s", "b", "p", "n", "c", "a"});
    } else {
      object(doc, "link", {"e", "g", "t", "ph", "s", "b", "p", "n", "a"});
    }
    const std::string engine = text(required(doc, "link", "e"), "link.e");
    Reader r;
    if (!r.physics(required(doc, "link", "ph"), "link.ph", in.config.physics)) {
      bad(r.error->path, r.error->reason + "; this breakshot (" + std::string(bs::kVersion) +
                             ") cannot replay this v2 link made by breakshot " + engine);
    }
  }
  {
    const bs::GamePhysics physics = in.config.physics;
    in.config = game_config(game_type(required(doc, "link", "g"), "link.g"));
    in.config.physics = physics;
  }
  if (const json* c = find(doc, "c")) in.config.carom = carom_rules(*c, "link.c", in.config.game);
  in.config.table_size = table_size(required(doc, "link", "t"), "link.t", in.config.game);
  {
    Reader r;
    r.must(r.seed(required(doc, "link", "s"), "link.s", in.seed));
  }
  in.breaker = static_cast<int>(integer(required(doc, "link", "b"), "link.b", 0, 1));
  const json& players = required(doc, "link", "p");
  if (!players.is_array() || players.size() != 2) bad("link.p", "expected two seats");
  for (std::size_t k = 0; k < 2; ++k) {
    in.seats[k] = seat_name(players[k], index_path("link.p", k), in.config.game);
  }
  if (const json* n = find(doc, "n")) in.ai_budget = integer(*n, "link.n", 1, kMaxBudget);
  const json& actions = required(doc, "link", "a");
  if (!actions.is_array()) bad("link.a", "expected an array of actions");
  std::unique_ptr<BsGame> g = make_game(in);
  for (std::size_t i = 0; i < actions.size(); ++i) {
    const std::string path = index_path("link.a", i);
    const bs::Action a = link_action(actions[i], path, in.config.game);
    std::string why;
    if (!play(*g, a, why)) bad(path, "refused: " + why);
  }
  return g;
}

}  // namespace

}  // namespace capi::page

using namespace capi;
using namespace capi::page;

extern "C" {

BsStatus bs_game_link(const BsGame* game, char** out) {
  if (out != nullptr) *out = nullptr;
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    *out = copy_out(link_text(g));
  });
}

BsStatus bs_game_from_link(const char* link, std::size_t len, BsGame** out) {
  return on_thread([&] {
    need(out, "out");
    *out = nullptr;
    if (link == nullptr) fail(BS_ERROR_NULL, "link: missing (a null pointer)");
    *out = game_from_link(std::string_view(link, len)).release();
  });
}

}  // extern "C"
