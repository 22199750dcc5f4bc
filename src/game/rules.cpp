// The rules of 8-ball and 9-ball (WPA); docs/rules.md lists the clauses
// and the options chosen.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"

namespace breakshot {

namespace {

bool has(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

std::string player_name(int p) { return "Player " + std::to_string(p + 1); }

Group group_of(int ball) { return ball < 8 ? Group::solids : Group::stripes; }

Group other(Group g) { return g == Group::solids ? Group::stripes : Group::solids; }

std::string join_balls(const std::vector<int>& balls) {
  std::string out;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (i > 0) out += i + 1 == balls.size() ? " and " : ", ";
    out += balls[i] == 0 ? "the cue ball" : std::to_string(balls[i]);
  }
  return out;
}

std::string join_fouls(const std::vector<Foul>& fouls) {
  std::string out;
  for (std::size_t i = 0; i < fouls.size(); ++i) {
    if (i > 0) out += ", ";
    out += to_string(fouls[i]);
  }
  return out;
}

}  // namespace

Rules::Rules(GameConfig config) : config_(std::move(config)) {
  if (!std::isfinite(config_.ball_radius) || config_.ball_radius <= 0.0) {
    throw std::invalid_argument("ball_radius must be a positive number of metres");
  }
  if (!std::isfinite(config_.ball_mass) || config_.ball_mass <= 0.0) {
    throw std::invalid_argument("ball_mass must be a positive number of kilograms");
  }
  if (config_.max_shots < 0) throw std::invalid_argument("max_shots must be 0 or more");
  // make_pool_table names the table size in its error.
  base_ = make_break_scenario(config_.game == GameType::eight_ball ? "eight_ball" : "nine_ball",
                              config_.table_size, 0, 1.0);
  table_ = base_.table;
  if (4.0 * config_.ball_radius >= table_.width) {
    throw std::invalid_argument("ball_radius is too large for a " + config_.table_size +
                                " table");
  }
  base_.cue.reset();
  base_.balls.clear();
  base_.start.clear();
  const double e = CushionParams{}.restitution;
  for (int n = 0; n < ball_count(); ++n) {
    base_.balls.push_back(
        {n == 0 ? "cue" : std::to_string(n), config_.ball_radius, config_.ball_mass, e});
  }
}

int Rules::ball_count() const { return config_.game == GameType::eight_ball ? 16 : 10; }

double Rules::head_string() const { return table_.head_spot.x; }

GameState Rules::start(std::uint64_t rack_seed, int breaker) const {
  if (breaker != 0 && breaker != 1) throw std::invalid_argument("breaker must be 0 or 1");
  GameState s;
  s.game = config_.game;
  s.position.assign(static_cast<std::size_t>(ball_count()), Vec2{});
  s.on_table.assign(static_cast<std::size_t>(ball_count()), 0);
  const std::string game = config_.game == GameType::eight_ball ? "eight_ball" : "nine_ball";
  for (const RackedBall& b : make_rack(game, table_, config_.ball_radius, rack_seed)) {
    const auto n = static_cast<std::size_t>(std::stoi(b.id));
    s.position[n] = b.position;
    s.on_table[n] = 1;
  }
  s.position[0] = table_.head_spot;
  s.on_table[0] = 1;
  s.phase = Phase::break_shot;
  s.player = breaker;
  s.breaker = breaker;
  s.ball_in_hand = BallInHand::kitchen;
  s.rack_seed = rack_seed;
  s.innings = 1;
  return s;
}

// ---------------------------------------------------------------------------
// What may be done

namespace {

// Balls the shooter may legally hit first.
std::vector<int> targets_of(const GameState& s) {
  std::vector<int> out;
  const auto n = static_cast<int>(s.on_table.size());
  if (s.game == GameType::nine_ball) {
    for (int b = 1; b < n; ++b) {
      if (s.on_table[static_cast<std::size_t>(b)]) return {b};
    }
    return out;
  }
  if (s.phase == Phase::break_shot) {
    for (int b = 1; b < n; ++b) {
      if (s.on_table[static_cast<std::size_t>(b)]) out.push_back(b);
    }
    return out;
  }
  const Group g = s.group[static_cast<std::size_t>(s.player)];
  for (int b = 1; b < n; ++b) {
    if (b == 8 || !s.on_table[static_cast<std::size_t>(b)]) continue;
    if (g == Group::none || group_of(b) == g) out.push_back(b);
  }
  // The 8 is the target once the shooter's group is cleared (never on an
  // open table: WPA 8-ball, open table).
  if (out.empty() && g != Group::none && s.on_table[8]) out.push_back(8);
  return out;
}

}  // namespace

LegalActions Rules::legal_actions(const GameState& s) const {
  LegalActions la;
  switch (s.phase) {
    case Phase::game_over:
      return la;
    case Phase::push_out_choice:
      la.choices = {Choice::shoot, Choice::pass_back};
      return la;
    case Phase::illegal_break_choice:
      la.choices = {Choice::accept_table, Choice::rerack_and_break,
                    Choice::rerack_opponent_breaks};
      return la;
    case Phase::eight_on_break_choice:
      la.choices = {Choice::respot_eight, Choice::rerack_and_break};
      return la;
    case Phase::break_shot:
    case Phase::shot:
      break;
  }
  la.place = s.ball_in_hand;
  la.must_place = !s.on_table[0];
  la.shoot = !la.must_place;
  la.push_out = s.game == GameType::nine_ball && s.phase == Phase::shot && s.push_out_allowed;
  la.call = s.game == GameType::eight_ball && s.phase == Phase::shot;
  la.targets = targets_of(s);
  return la;
}

std::optional<std::string> Rules::check_placement(const GameState& s, Vec2 p) const {
  if (s.phase != Phase::break_shot && s.phase != Phase::shot) {
    return "the cue ball can only be placed before a shot, not in phase " +
           std::string(to_string(s.phase));
  }
  if (s.ball_in_hand == BallInHand::none) {
    return "the cue ball is not in hand: it is played from where it lies";
  }
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return "the position is not a finite number";
  const double R = config_.ball_radius;
  if (!contains(table_, p) || wall_clearance(table_, p, R) < 0.0) {
    return "the cue ball would not lie on the playing surface clear of the cushions";
  }
  if (s.ball_in_hand == BallInHand::kitchen && p.x > head_string()) {
    return "the cue ball must be placed behind the head string (x <= " +
           std::to_string(head_string()) + " m)";
  }
  for (std::size_t b = 1; b < s.on_table.size(); ++b) {
    if (s.on_table[b] && norm(s.position[b] - p) < 2.0 * R) {
      return "the cue ball would overlap ball " + std::to_string(b);
    }
  }
  return std::nullopt;
}

std::optional<std::string> Rules::check(const GameState& s, const Action& action) const {
  if (s.phase == Phase::game_over) return "the game is over";
  if (const auto* place = std::get_if<PlaceCueBall>(&action)) {
    return check_placement(s, place->position);
  }
  if (const auto* d = std::get_if<Decide>(&action)) {
    const LegalActions la = legal_actions(s);
    if (la.choices.empty()) {
      return "there is no decision to make now (phase " + std::string(to_string(s.phase)) + ")";
    }
    if (!std::count(la.choices.begin(), la.choices.end(), d->choice)) {
      return "choice " + std::string(to_string(d->choice)) + " is not on offer in phase " +
             std::string(to_string(s.phase));
    }
    return std::nullopt;
  }
  const Shoot& shot = std::get<Shoot>(action);
  if (s.phase != Phase::break_shot && s.phase != Phase::shot) {
    return "a decision is due (phase " + std::string(to_string(s.phase)) + "), not a shot";
  }
  if (!s.on_table[0]) return "the cue ball is in hand: place it first";
  const CueStrike& c = shot.strike;
  if (!std::isfinite(c.speed) || c.speed <= 0.0 || c.speed > kMaxCueSpeed) {
    return "strike speed must be in (0, 20] m/s";
  }
  if (!std::isfinite(c.phi)) return "strike phi must be a finite angle";
  if (!std::isfinite(c.theta) || c.theta < 0.0 || c.theta >= 90.0) {
    return "strike theta must be in [0, 90) degrees";
  }
  if (!std::isfinite(c.a) || !std::isfinite(c.b) || std::abs(c.a) > 1.0 ||
      std::abs(c.b) > 1.0) {
    return "strike offsets a and b must be within the ball ([-1, 1] radii)";
  }
  if (config_.game == GameType::nine_ball) {
    if (shot.safety) return "9-ball has no declared safety";
    if (shot.call) {
      // Informational only: a valid pocket and an object ball on the table.
      const Call& call = *shot.call;
      if (call.pocket < 0 || call.pocket >= static_cast<int>(table_.pockets.size())) {
        return "called pocket " + std::to_string(call.pocket) + " does not exist (0-" +
               std::to_string(table_.pockets.size() - 1) + ")";
      }
      if (call.ball < 1 || call.ball >= ball_count() ||
          !s.on_table[static_cast<std::size_t>(call.ball)]) {
        return "called ball " + std::to_string(call.ball) + " is not on the table";
      }
      if (shot.push_out) return "a push-out is not a pot attempt: it has no call";
    }
    if (shot.push_out && !legal_actions(s).push_out) {
      return "a push-out is only allowed on the shot right after the break";
    }
    return std::nullopt;
  }
  if (shot.push_out) return "8-ball has no push-out";
  if (s.phase == Phase::break_shot) {
    if (shot.call || shot.safety) return "the break is neither called nor a safety";
    return std::nullopt;
  }
  if (shot.call && shot.safety) return "a declared safety has no call";
  if (shot.call) {
    const Call& call = *shot.call;
    if (call.pocket < 0 || call.pocket >= static_cast<int>(table_.pockets.size())) {
      return "called pocket " + std::to_string(call.pocket) + " does not exist (0-" +
             std::to_string(table_.pockets.size() - 1) + ")";
    }
    if (!has(targets_of(s), call.ball)) {
      return "called ball " + std::to_string(call.ball) + " is not a legal target";
    }
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------
// Physics of a shot

Scenario Rules::shot_scenario(const GameState& s, const CueStrike& strike,
                              std::vector<int>* numbers) const {
  Scenario sc;
  sc.physics = base_.physics;
  sc.table = table_;
  sc.until.rest = true;
  if (numbers) numbers->clear();
  for (std::size_t b = 0; b < s.on_table.size(); ++b) {
    if (!s.on_table[b]) continue;
    sc.balls.push_back(base_.balls[b]);
    BallState st;
    st.position = s.position[b];
    sc.start.push_back(st);
    if (numbers) numbers->push_back(static_cast<int>(b));
  }
  CueSpec cue;
  cue.ball = 0;
  cue.strike = strike;
  sc.cue = cue;
  return sc;
}

ShotFacts Rules::facts(const std::vector<Event>& events) const {
  ShotFacts f;
  double contact_time = -1.0;
  std::vector<int> to_cushion;
  for (const Event& e : events) {
    switch (e.type) {
      case EventType::ball_ball:
        if (f.first_hit < 0 && (e.ball == 0 || e.other == 0)) {
          f.first_hit = e.ball == 0 ? e.other : e.ball;
          contact_time = e.time;
        }
        break;
      case EventType::ball_cushion:
        if (f.first_hit >= 0 && e.time >= contact_time) f.cushion_after_contact = true;
        if (e.ball != 0 && !has(to_cushion, e.ball)) to_cushion.push_back(e.ball);
        break;
      case EventType::ball_pocket:
        f.pocketed.push_back(e.ball);
        f.pocket_of.push_back(e.pocket);
        break;
      case EventType::cue_strike:
      case EventType::state_change:
        break;
    }
  }
  f.object_balls_to_cushion = static_cast<int>(to_cushion.size());
  return f;
}

Vec2 Rules::spot_position(const GameState& s, int ball) const {
  const double R = config_.ball_radius;
  const auto free = [&](Vec2 p) {
    if (wall_clearance(table_, p, R) < 0.0) return false;
    for (std::size_t b = 0; b < s.on_table.size(); ++b) {
      if (static_cast<int>(b) != ball && s.on_table[b] && norm(s.position[b] - p) < 2.0 * R) {
        return false;
      }
    }
    return true;
  };
  // The first free place along the long string: from the foot spot toward
  // the foot rail, then from the foot spot toward the head rail. Steps of
  // R/64 leave a spotted ball within a hair of the ball that blocks it.
  const Vec2 spot = table_.foot_spot;
  const double step = R / 64.0;
  for (double x = spot.x; x <= table_.length - R; x += step) {
    if (free({x, spot.y})) return {x, spot.y};
  }
  for (double x = spot.x - step; x >= R; x -= step) {
    if (free({x, spot.y})) return {x, spot.y};
  }
  throw std::logic_error("no free place on the long string to spot ball " +
                         std::to_string(ball));
}

// ---------------------------------------------------------------------------
// Playing an action

namespace {

// From the kitchen, a ball behind the head string may be hit first only
// after the cue ball has crossed the head string (WPA): did the cue ball's
// centre pass x > head string before its first contact? The shot is run
// again event by event up to that contact, and each piece of the cue
// ball's path (a parabola between events) is checked at its ends and at
// its turning point.
bool crossed_head_string(const Scenario& scenario, const std::vector<Event>& events) {
  double contact = -1.0;
  for (const Event& e : events) {
    if (e.type == EventType::ball_ball && (e.ball == 0 || e.other == 0)) {
      contact = e.time;
      break;
    }
  }
  if (contact < 0.0) return false;
  const double line = scenario.table.head_spot.x;
  Simulation sim(scenario);
  for (std::size_t guard = 0; guard <= events.size() + 1; ++guard) {
    const Simulation::Trajectory& tr = sim.trajectory(0);
    const double from = sim.time();
    const double to = std::min({sim.next_event_time(), contact, tr.t_end});
    const auto x_at = [&](double t) {
      const double dt = t - tr.t0;
      return tr.p0.x + tr.v0.x * dt + 0.5 * tr.acc.x * dt * dt;
    };
    double most = std::max(x_at(from), x_at(to));
    if (tr.acc.x != 0.0) {
      const double turn = tr.t0 - tr.v0.x / tr.acc.x;
      if (turn > from && turn < to) most = std::max(most, x_at(turn));
    }
    if (most > line) return true;
    if (to >= contact) return false;
    sim.advance_to(to);
  }
  return false;
}

// Turn bookkeeping shared by the rulings.
void pass_turn(GameState& s) {
  s.player = 1 - s.player;
  s.innings += 1;
}

}  // namespace

Outcome Rules::apply(const GameState& state, const Action& action) const {
  if (auto why = check(state, action)) throw std::invalid_argument(*why);
  Outcome out;
  out.state = state;
  GameState& s = out.state;
  Ruling& r = out.ruling;
  const int shooter = state.player;
  const int opp = 1 - shooter;
  const std::string who = player_name(shooter);

  if (const auto* place = std::get_if<PlaceCueBall>(&action)) {
    s.position[0] = place->position;
    s.on_table[0] = 1;
    s.kitchen_shot = state.phase == Phase::shot && state.ball_in_hand == BallInHand::kitchen;
    if (state.phase == Phase::shot) s.ball_in_hand = BallInHand::none;
    r.turn_continues = true;
    r.text = who + " places the cue ball.";
    return out;
  }

  if (const auto* d = std::get_if<Decide>(&action)) {
    r.turn_continues = true;
    const auto rerack = [&](int breaker) {
      s.rack_seed = mix_seed(state.rack_seed, static_cast<std::uint64_t>(state.racks));
      GameState fresh = start(s.rack_seed, breaker);
      fresh.shots = state.shots;
      fresh.innings = state.innings + (breaker != shooter ? 1 : 0);
      fresh.racks = state.racks + 1;
      fresh.fouls_in_a_row = state.fouls_in_a_row;
      s = fresh;
    };
    switch (d->choice) {
      case Choice::shoot:
        s.phase = Phase::shot;
        s.ball_in_hand = BallInHand::none;
        s.after_push_out = false;
        r.text = who + " takes the table after the push-out.";
        break;
      case Choice::pass_back:
        s.phase = Phase::shot;
        s.ball_in_hand = BallInHand::none;
        s.after_push_out = false;
        pass_turn(s);
        r.turn_continues = false;
        r.text = who + " passes the shot back to " + player_name(opp) + ".";
        break;
      case Choice::accept_table:
        s.phase = Phase::shot;
        s.ball_in_hand = state.scratch_on_break ? BallInHand::kitchen : BallInHand::none;
        s.scratch_on_break = false;
        r.text = who + " accepts the table.";
        break;
      case Choice::rerack_and_break:
        rerack(shooter);
        r.text = who + " has the balls re-racked and breaks.";
        break;
      case Choice::rerack_opponent_breaks:
        rerack(opp);
        r.turn_continues = false;
        r.text = who + " has the balls re-racked; " + player_name(opp) + " breaks again.";
        break;
      case Choice::respot_eight:
        s.position[8] = spot_position(state, 8);
        s.on_table[8] = 1;
        r.spotted.push_back(8);
        s.phase = Phase::shot;
        s.ball_in_hand = state.scratch_on_break ? BallInHand::kitchen : BallInHand::none;
        s.scratch_on_break = false;
        r.text = who + " has the 8 spotted and plays on.";
        break;
    }
    return out;
  }

  // A shot: simulate it and read what happened.
  const Shoot& shot = std::get<Shoot>(action);
  std::vector<int> numbers;
  Simulation sim(shot_scenario(state, shot.strike, &numbers));
  sim.advance_to_rest();
  if (!sim.at_rest()) {
    throw std::logic_error("the shot did not come to rest within the event limit");
  }
  out.events = sim.events();
  for (Event& e : out.events) {
    if (e.ball >= 0) e.ball = numbers[static_cast<std::size_t>(e.ball)];
    if (e.other >= 0) e.other = numbers[static_cast<std::size_t>(e.other)];
  }
  out.facts = facts(out.events);
  ShotFacts& f = out.facts;
  f.miscue = sim.cue_result() && sim.cue_result()->miscue;
  for (std::size_t k = 0; k < numbers.size(); ++k) {
    const auto b = static_cast<std::size_t>(numbers[k]);
    const BallState st = sim.ball(k);
    if (st.state == MotionState::pocketed) {
      s.on_table[b] = 0;
    } else {
      s.position[b] = st.position;
    }
  }
  s.shots += 1;
  s.kitchen_shot = false;
  s.after_push_out = false;

  const bool is_break = state.phase == Phase::break_shot;
  const bool cue_in = has(f.pocketed, 0);
  std::vector<int> objects;  // object balls pocketed, in order
  for (int b : f.pocketed) {
    if (b != 0) objects.push_back(b);
  }
  const std::vector<int> targets = targets_of(state);
  const auto pocket_of = [&](int ball) {
    for (std::size_t k = 0; k < f.pocketed.size(); ++k) {
      if (f.pocketed[k] == ball) return f.pocket_of[k];
    }
    return -1;
  };
  std::string what = who + (objects.empty() ? " pockets nothing" : " pockets " + join_balls(objects));
  if (cue_in) what += objects.empty() ? " but scratches" : " and scratches";
  what += ". ";

  // Fouls common to both games.
  std::vector<Foul>& fouls = r.fouls;
  const auto foul = [&](Foul x) {
    if (!std::count(fouls.begin(), fouls.end(), x)) fouls.push_back(x);
  };
  if (cue_in) foul(Foul::scratch);

  const auto game_over = [&](int winner, const std::string& why) {
    s.phase = Phase::game_over;
    s.winner = winner;
    s.result = why;
    r.winner = winner;
    r.turn_continues = false;
  };
  const auto ball_in_hand_for_opponent = [&](BallInHand where) {
    s.phase = Phase::shot;
    s.ball_in_hand = where;
    if (cue_in) s.on_table[0] = 0;
    pass_turn(s);
  };
  const auto spot = [&](int ball) {
    s.position[static_cast<std::size_t>(ball)] = spot_position(s, ball);
    s.on_table[static_cast<std::size_t>(ball)] = 1;
    r.spotted.push_back(ball);
  };

  if (config_.game == GameType::eight_ball) {
    const bool eight_in = has(f.pocketed, 8);
    if (is_break) {
      r.legal_break = !objects.empty() || f.object_balls_to_cushion >= 4;
      if (eight_in) {
        // The 8 on the break (WPA 8-ball): no loss; a choice.
        s.phase = Phase::eight_on_break_choice;
        s.scratch_on_break = cue_in;
        s.ball_in_hand = BallInHand::none;
        if (cue_in) {
          s.on_table[0] = 0;
          pass_turn(s);
          r.text = what + "The 8 fell on the break with a scratch: " + player_name(opp) +
                   " chooses to spot the 8 and shoot from the kitchen, or to re-rack and break.";
        } else {
          r.turn_continues = true;
          r.text = what + "The 8 fell on the break: " + who +
                   " chooses to spot the 8 and play on, or to re-rack and break again.";
        }
      } else if (!r.legal_break) {
        foul(Foul::illegal_break);
        s.phase = Phase::illegal_break_choice;
        s.scratch_on_break = cue_in;
        s.ball_in_hand = BallInHand::none;
        if (cue_in) s.on_table[0] = 0;
        pass_turn(s);
        r.text = what + "Illegal break (nothing pocketed, " +
                 std::to_string(f.object_balls_to_cushion) +
                 " object balls to a cushion): " + player_name(opp) +
                 " accepts the table or has the balls re-racked.";
      } else if (cue_in) {
        ball_in_hand_for_opponent(BallInHand::kitchen);
        r.text = what + "Foul (scratch on the break): " + player_name(opp) +
                 " has the cue ball in hand behind the head string; the table is open.";
      } else if (!objects.empty()) {
        s.phase = Phase::shot;
        s.ball_in_hand = BallInHand::none;
        r.turn_continues = true;
        r.text = what + "Legal break; the table is open and " + who + " shoots again.";
      } else {
        s.phase = Phase::shot;
        s.ball_in_hand = BallInHand::none;
        pass_turn(s);
        r.text = what + "Legal break; " + player_name(opp) + " to shoot on an open table.";
      }
    } else {
      if (f.first_hit < 0) {
        foul(Foul::no_contact);
      } else if (!has(targets, f.first_hit)) {
        foul(Foul::wrong_ball_first);
      } else if (state.kitchen_shot &&
                 state.position[static_cast<std::size_t>(f.first_hit)].x <= head_string() &&
                 !crossed_head_string(shot_scenario(state, shot.strike), out.events)) {
        foul(Foul::behind_head_string);
      }
      if (f.first_hit >= 0 && objects.empty() && !f.cushion_after_contact) foul(Foul::no_rail);
      const bool was_on_eight = has(targets, 8);
      if (eight_in) {
        const bool called_eight = shot.call && shot.call->ball == 8;
        const bool right_pocket = called_eight && pocket_of(8) == shot.call->pocket;
        if (!fouls.empty()) {
          game_over(opp, who + " pocketed the 8 on a foul (" + join_fouls(fouls) + ")");
        } else if (!was_on_eight) {
          game_over(opp, who + " pocketed the 8 before clearing the group");
        } else if (!called_eight) {
          game_over(opp, who + " pocketed the 8 without calling it");
        } else if (!right_pocket) {
          game_over(opp, who + " pocketed the 8 in an uncalled pocket (" +
                             table_.pockets[static_cast<std::size_t>(pocket_of(8))].name + ")");
        } else {
          game_over(shooter, who + " pocketed the 8 in the called pocket");
        }
        r.text = what + (fouls.empty() ? "" : "Foul (" + join_fouls(fouls) + "). ") + s.result +
                 ": " + player_name(s.winner) + " wins.";
      } else if (!fouls.empty()) {
        ball_in_hand_for_opponent(BallInHand::anywhere);
        r.text = what + "Foul (" + join_fouls(fouls) + "): " + player_name(opp) +
                 " has the cue ball in hand.";
      } else {
        // Did the shot count? A called ball in its called pocket; an
        // uncalled shot counts if the first ball hit went in (the obvious
        // shot); a safety never does.
        int made = -1;
        if (shot.safety) {
          made = -1;
        } else if (shot.call) {
          if (pocket_of(shot.call->ball) == shot.call->pocket) made = shot.call->ball;
        } else if (has(objects, f.first_hit)) {
          made = f.first_hit;
        }
        if (made > 0) {
          if (state.group[static_cast<std::size_t>(shooter)] == Group::none) {
            s.group[static_cast<std::size_t>(shooter)] = group_of(made);
            s.group[static_cast<std::size_t>(opp)] = other(group_of(made));
            r.assigned = group_of(made);
          }
          s.phase = Phase::shot;
          s.ball_in_hand = BallInHand::none;
          r.turn_continues = true;
          r.text = what + (r.assigned != Group::none
                               ? who + " takes the " + std::string(to_string(r.assigned)) + " and "
                               : who + " ") +
                   "shoots again.";
        } else {
          s.phase = Phase::shot;
          s.ball_in_hand = BallInHand::none;
          pass_turn(s);
          const char* why = shot.safety          ? "Safety. "
                            : objects.empty()      ? ""
                            : shot.call            ? "The called ball did not go in the called pocket. "
                                                   : "No called or obvious ball went in. ";
          r.text = what + why + player_name(opp) + " to shoot.";
        }
      }
    }
  } else {
    // 9-ball.
    const bool nine_in = has(f.pocketed, 9);
    const int lowest = targets.empty() ? -1 : targets.front();
    if (is_break) {
      r.legal_break = !objects.empty() || f.object_balls_to_cushion >= 4;
      if (f.first_hit < 0) foul(Foul::no_contact);
      else if (f.first_hit != lowest) foul(Foul::wrong_ball_first);
      if (!r.legal_break) foul(Foul::illegal_break);
    } else if (shot.push_out) {
      // Push-out: only the other fouls apply (WPA 9-ball).
    } else {
      if (f.first_hit < 0) foul(Foul::no_contact);
      else if (f.first_hit != lowest) foul(Foul::wrong_ball_first);
      if (f.first_hit >= 0 && objects.empty() && !f.cushion_after_contact) foul(Foul::no_rail);
    }
    auto& streak = s.fouls_in_a_row[static_cast<std::size_t>(shooter)];
    s.push_out_allowed = is_break;  // the shot after the break may be a push-out
    if (!fouls.empty()) {
      if (nine_in) spot(9);
      streak += 1;
      if (streak >= 3) {
        game_over(opp, who + " fouled three times in a row");
        r.text = what + "Foul (" + join_fouls(fouls) + "), the third in a row: " +
                 player_name(opp) + " wins.";
      } else {
        ball_in_hand_for_opponent(BallInHand::anywhere);
        r.text = what + "Foul (" + join_fouls(fouls) + "): " + player_name(opp) +
                 " has the cue ball in hand" +
                 (nine_in ? "; the 9 is spotted" : "") +
                 (streak == 2 ? "; " + who + " is on two fouls" : "") + ".";
      }
    } else if (shot.push_out) {
      streak = 0;
      if (nine_in) spot(9);
      s.phase = Phase::push_out_choice;
      s.after_push_out = true;
      s.ball_in_hand = BallInHand::none;
      pass_turn(s);
      r.text = what + "Push-out" + (nine_in ? "; the 9 is spotted" : "") + ": " +
               player_name(opp) + " shoots from here or passes the shot back.";
    } else {
      streak = 0;
      s.phase = Phase::shot;
      s.ball_in_hand = BallInHand::none;
      if (nine_in) {
        game_over(shooter, who + (is_break ? " pocketed the 9 on the break"
                                           : " pocketed the 9 legally"));
        r.text = what + s.result + ": " + who + " wins.";
      } else if (!objects.empty()) {
        r.turn_continues = true;
        r.text = what + (is_break ? "Legal break; " : "") + who + " shoots again" +
                 (is_break ? " and may push out." : ".");
      } else {
        pass_turn(s);
        r.text = what + (is_break ? "Legal break; " : "") + player_name(opp) + " to shoot" +
                 (is_break ? " and may push out." : ".");
      }
    }
  }

  r.call_made = !is_break && shot.call && r.fouls.empty() &&
                pocket_of(shot.call->ball) == shot.call->pocket;
  if (s.phase != Phase::game_over && config_.max_shots > 0 && s.shots >= config_.max_shots) {
    game_over(-1, "stalemate: no result after " + std::to_string(s.shots) + " shots");
    r.text += " The game is drawn (" + s.result + ").";
  }
  return out;
}

}  // namespace breakshot
