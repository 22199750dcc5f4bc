// Helpers for the rules tests (test_rules_*.cpp): hand-placed tables and
// shots aimed at a point. Every outcome in those tests comes from a shot
// that Rules::apply simulates; these helpers only set up the table.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "breakshot/game.hpp"

namespace rules_fixtures {

using namespace breakshot;

inline constexpr double kR = 0.028575;  // GameConfig's default ball radius
inline constexpr double kPi = 3.14159265358979323846;

// The hand-placed tables and strokes of the rules', the AI's and the shot
// generator's tests were found on breakshot 0.1's physics
// (kLegacyGamePhysics), and they are played on it: what they test (a
// ruling, a choice) does not depend on the physics, but the stroke that
// brings a given case about does. Games on the default physics are tested
// whole (test_match.cpp, test_games_long.cpp, test_ai.cpp's AiJump).
inline Rules eight_ball_rules(int max_shots = 400) {
  GameConfig c;
  c.game = GameType::eight_ball;
  c.max_shots = max_shots;
  c.physics = kLegacyGamePhysics;
  return Rules(c);
}

inline Rules nine_ball_rules(int max_shots = 400) {
  GameConfig c;
  c.game = GameType::nine_ball;
  c.max_shots = max_shots;
  c.physics = kLegacyGamePhysics;
  return Rules(c);
}

/// A game in progress with only the cue ball on the table (at `cue`):
/// `player` to shoot, no ball in hand, open table, no fouls.
inline GameState bare_table(const Rules& rules, Vec2 cue, int player = 0) {
  GameState s = rules.start(7, player);
  std::fill(s.on_table.begin(), s.on_table.end(), std::uint8_t{0});
  s.on_table[0] = 1;
  s.position[0] = cue;
  s.phase = Phase::shot;
  s.ball_in_hand = BallInHand::none;
  s.player = player;
  s.breaker = player;
  s.shots = 1;
  return s;
}

inline void put(GameState& s, int ball, Vec2 p) {
  s.position[static_cast<std::size_t>(ball)] = p;
  s.on_table[static_cast<std::size_t>(ball)] = 1;
}

inline bool on(const GameState& s, int ball) {
  return s.on_table[static_cast<std::size_t>(ball)] != 0;
}

inline Vec2 unit(Vec2 v) { return v / norm(v); }

/// Direction from `from` to `to` in degrees counter-clockwise from +x.
inline double aim_deg(Vec2 from, Vec2 to) {
  return std::atan2(to.y - from.y, to.x - from.x) * 180.0 / kPi;
}

/// A level strike of the cue ball at `cue` toward the point `to`; b > 0 is
/// follow, b < 0 draw (fractions of the radius).
inline Shoot shot_at(Vec2 cue, Vec2 to, double speed, double b = 0.0) {
  Shoot sh;
  sh.strike.speed = speed;
  sh.strike.phi = aim_deg(cue, to);
  sh.strike.b = b;
  return sh;
}

inline Shoot with_call(Shoot sh, int ball, int pocket) {
  sh.call = Call{ball, pocket};
  return sh;
}

inline int pocket_index(const Rules& rules, const std::string& name) {
  const auto& p = rules.table().pockets;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i].name == name) return static_cast<int>(i);
  }
  ADD_FAILURE() << "no pocket named " << name;
  return -1;
}

inline Vec2 pocket_centre(const Rules& rules, int pocket) {
  return rules.table().pockets[static_cast<std::size_t>(pocket)].centre;
}

/// A straight-in set-up: the object ball `d_obj` from the pocket's centre
/// on the line from the pocket through `toward`, the cue ball `d_cue`
/// further back on the same line.
struct StraightIn {
  Vec2 object;
  Vec2 cue;
};

inline StraightIn straight_in(const Rules& rules, int pocket, Vec2 toward, double d_obj,
                              double d_cue) {
  const Vec2 c = pocket_centre(rules, pocket);
  const Vec2 u = unit(toward - c);
  return {c + u * d_obj, c + u * (d_obj + d_cue)};
}

/// A straight combination: `target` `d_obj` from the pocket's centre on the
/// line from the pocket through `toward`, the `carrier` ball behind it
/// (a 2 mm gap between them) and the cue ball `d_cue` behind the carrier.
struct Combination {
  Vec2 target;
  Vec2 carrier;
  Vec2 cue;
};

inline Combination combination(const Rules& rules, int pocket, Vec2 toward, double d_obj,
                               double d_cue) {
  const Vec2 c = pocket_centre(rules, pocket);
  const Vec2 u = unit(toward - c);
  const double carrier = d_obj + 2.0 * kR + 0.002;
  return {c + u * d_obj, c + u * carrier, c + u * (carrier + d_cue)};
}

/// An event of a hand-made event list (ball fields are ball numbers).
inline Event ev(double t, EventType type, int ball, int other = -1, int wall = -1,
                int pocket = -1) {
  Event e;
  e.time = t;
  e.type = type;
  e.ball = ball;
  e.other = other;
  e.wall = wall;
  e.pocket = pocket;
  return e;
}

/// A ball in flight landing on the slate (EventType::ball_slate), `to`
/// the state after the landing.
inline Event slate(double t, int ball, MotionState to) {
  Event e = ev(t, EventType::ball_slate, ball);
  e.from = MotionState::airborne;
  e.to = to;
  return e;
}

/// The rules of `game` with balls that may leave the cloth.
// The legacy physics with balls that may leave the cloth: the strokes of
// the off-table tests were found on it (see eight_ball_rules).
inline Rules airborne_rules(GameType game) {
  GameConfig c;
  c.game = game;
  c.physics = kLegacyGamePhysics;
  c.physics.airborne = true;
  return Rules(c);
}

inline bool has_foul(const Ruling& r, Foul f) {
  return std::find(r.fouls.begin(), r.fouls.end(), f) != r.fouls.end();
}

inline bool includes(const std::vector<int>& v, int x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

/// The pocket ball `ball` fell into on this shot, -1 if it did not.
inline int pocket_of(const ShotFacts& f, int ball) {
  for (std::size_t k = 0; k < f.pocketed.size(); ++k) {
    if (f.pocketed[k] == ball) return f.pocket_of[k];
  }
  return -1;
}

/// The shot's facts, ruling and resulting state in words, for failure
/// messages.
inline std::string describe(const Outcome& o) {
  std::ostringstream out;
  const ShotFacts& f = o.facts;
  out << "first_hit " << f.first_hit << ", pocketed [";
  for (std::size_t k = 0; k < f.pocketed.size(); ++k) {
    out << (k ? " " : "") << f.pocketed[k] << "@" << f.pocket_of[k];
  }
  out << "], cushion_after_contact " << f.cushion_after_contact << ", object_balls_to_cushion "
      << f.object_balls_to_cushion << "; fouls [";
  for (std::size_t k = 0; k < o.ruling.fouls.size(); ++k) {
    out << (k ? " " : "") << to_string(o.ruling.fouls[k]);
  }
  out << "]; \"" << o.ruling.text << "\"; phase " << to_string(o.state.phase) << ", player "
      << o.state.player << "; on the table:";
  for (std::size_t b = 0; b < o.state.on_table.size(); ++b) {
    if (o.state.on_table[b]) {
      out << " " << b << "(" << o.state.position[b].x << ", " << o.state.position[b].y << ")";
    }
  }
  return out.str();
}

}  // namespace rules_fixtures
