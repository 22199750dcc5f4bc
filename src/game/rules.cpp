// What the games on a pool table share (src/game/ruleset.hpp): the rules'
// set-up, placing the cue ball, the strike's limits, a shot's simulation
// and facts, spotting, the stalemate limit. The games' own rulings are in
// rules_eight.cpp and rules_nine.cpp; docs/rules.md lists the clauses.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"
#include "ruleset.hpp"

namespace breakshot {

namespace detail {

bool has(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

std::string player_name(int p) { return "Player " + std::to_string(p + 1); }

std::string join_balls(const std::vector<int>& balls) {
  std::string out;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (i > 0) out += i + 1 == balls.size() ? " and " : ", ";
    out += balls[i] == 0 ? "the cue ball" : std::to_string(balls[i]);
  }
  return out;
}

std::string fouls_in_words(const std::vector<Foul>& fouls) {
  std::string out;
  for (std::size_t i = 0; i < fouls.size(); ++i) {
    if (i > 0) out += i + 1 == fouls.size() ? " and " : ", ";
    out += foul_words(fouls[i]);
  }
  return out;
}

std::vector<int> lowest_ball(const GameState& s) {
  const auto n = static_cast<int>(s.on_table.size());
  for (int b = 1; b < n; ++b) {
    if (s.on_table[static_cast<std::size_t>(b)]) return {b};
  }
  return {};
}

void rotation_reply(DecisionRuling& d, Choice choice, const std::string& taken,
                    const std::string& handed) {
  GameState& s = d.s;
  if (choice != Choice::shoot && choice != Choice::pass_back) return;  // refused by check()
  s.phase = Phase::shot;
  s.ball_in_hand = BallInHand::none;
  s.after_push_out = false;
  if (choice == Choice::shoot) {
    d.r.text = d.who + " " + taken + ".";
    return;
  }
  d.pass_turn();
  d.r.turn_continues = false;
  d.r.text = d.who + " " + handed + " " + player_name(d.opp) + ".";
}

void rotation_foul(ShotRuling& x, int game_ball, bool spot_game_ball) {
  Ruling& r = x.r;
  if (spot_game_ball) x.spot(game_ball);
  auto& streak = x.s.fouls_in_a_row[static_cast<std::size_t>(x.shooter)];
  streak += 1;
  if (streak >= 3) {
    x.game_over(x.opp, x.who + " fouled three times in a row");
    r.text = x.what + "Foul: " + fouls_in_words(r.fouls) +
             ". The third foul in a row: " + player_name(x.opp) + " wins.";
    return;
  }
  x.ball_in_hand_for_opponent(BallInHand::anywhere);
  r.text = x.what + "Foul: " + fouls_in_words(r.fouls) + ". " + player_name(x.opp) +
           " has the cue ball in hand" +
           (spot_game_ball ? "; the " + std::to_string(game_ball) + " is spotted" : "") +
           (streak == 2 ? "; " + x.who + " is on two fouls" : "") + ".";
}

std::optional<std::string> check_call(const Rules& rules, const GameState& s, const Call& call,
                                      int ball_count) {
  if (auto why = check_called_pocket(rules, call)) return why;
  if (call.ball < 1 || call.ball >= ball_count || !s.on_table[static_cast<std::size_t>(call.ball)]) {
    return "called ball " + std::to_string(call.ball) + " is not on the table";
  }
  return std::nullopt;
}

std::optional<std::string> check_called_pocket(const Rules& rules, const Call& call) {
  const auto pockets = rules.table().pockets.size();
  if (call.pocket < 0 || call.pocket >= static_cast<int>(pockets)) {
    return "called pocket " + std::to_string(call.pocket) + " does not exist (0-" +
           std::to_string(pockets - 1) + ")";
  }
  return std::nullopt;
}

std::vector<Foul> pool_foul_kinds() {
  return {Foul::scratch, Foul::no_contact,    Foul::wrong_ball_first,
          Foul::no_rail, Foul::illegal_break, Foul::behind_head_string};
}

void DecisionRuling::rerack(int breaker) {
  s.rack_seed = mix_seed(before.rack_seed, static_cast<std::uint64_t>(before.racks));
  GameState fresh = rules.start(s.rack_seed, breaker);
  fresh.shots = before.shots;
  fresh.innings = before.innings + (breaker != shooter ? 1 : 0);
  fresh.racks = before.racks + 1;
  fresh.fouls_in_a_row = before.fouls_in_a_row;
  s = fresh;
}

void DecisionRuling::pass_turn() {
  s.player = 1 - s.player;
  s.innings += 1;
}

void ShotRuling::foul(Foul x) {
  if (!std::count(r.fouls.begin(), r.fouls.end(), x)) r.fouls.push_back(x);
}

void ShotRuling::game_over(int winner, const std::string& why) {
  s.phase = Phase::game_over;
  s.winner = winner;
  s.result = why;
  r.winner = winner;
  r.turn_continues = false;
}

void ShotRuling::pass_turn() {
  s.player = 1 - s.player;
  s.innings += 1;
}

void ShotRuling::ball_in_hand_for_opponent(BallInHand where) {
  s.phase = Phase::shot;
  s.ball_in_hand = where;
  if (cue_gone()) s.on_table[0] = 0;
  pass_turn();
}

void ShotRuling::spot(int ball) {
  s.position[static_cast<std::size_t>(ball)] = rules.spot_position(s, ball);
  s.on_table[static_cast<std::size_t>(ball)] = 1;
  r.spotted.push_back(ball);
}

int ShotRuling::pocket_of(int ball) const {
  for (std::size_t k = 0; k < f.pocketed.size(); ++k) {
    if (f.pocketed[k] == ball) return f.pocket_of[k];
  }
  return -1;
}

}  // namespace detail

using detail::has;
using detail::player_name;

namespace {

std::shared_ptr<const detail::Ruleset> make_ruleset(GameType game) {
  switch (game) {
    case GameType::eight_ball:
      return detail::make_eight_ball_ruleset();
    case GameType::nine_ball:
      return detail::make_nine_ball_ruleset();
    case GameType::snooker:
      return detail::make_snooker_ruleset();
    case GameType::three_cushion:
      return detail::make_three_cushion_ruleset();
    case GameType::ten_ball:
      return detail::make_ten_ball_ruleset();
  }
  throw std::invalid_argument("unknown game type");
}

}  // namespace

std::optional<std::string> check_game_physics(const GamePhysics& p) {
  if (!is_cushion_model(p.cushion_model)) {
    return "physics.cushion_model: not a cushion model";
  }
  if (p.ball_ball_model != BallBallModel::friction &&
      p.ball_ball_model != BallBallModel::mathavan_2014) {
    return "physics.ball_ball_model: not a ball-ball model";
  }
  if (p.ball_ball_friction_fit) {
    if (auto bad = check_friction_curve(p.ball_ball_friction_curve)) {
      return "physics.ball_ball_friction." + std::string(1, bad->member) + ": " + bad->reason;
    }
  } else if (!std::isfinite(p.ball_ball_friction) || p.ball_ball_friction < 0.0) {
    return "physics.ball_ball_friction: must be a finite number >= 0";
  }
  // Zero would leave a spinning ball spinning for ever: no shot would end.
  if (!std::isfinite(p.spinning_friction) || !(p.spinning_friction > 0.0)) {
    return "physics.spinning_friction: must be a finite number > 0";
  }
  return std::nullopt;
}

std::optional<GamePhysics> game_physics_preset(std::string_view name) {
  if (name == "default") return GamePhysics{};
  if (name == "legacy") return kLegacyGamePhysics;
  return std::nullopt;
}

Rules::Rules(GameConfig config) : config_(std::move(config)), ruleset_(make_ruleset(config_.game)) {
  if (!std::isfinite(config_.ball_radius) || config_.ball_radius <= 0.0) {
    throw std::invalid_argument("ball_radius must be a positive number of metres");
  }
  if (!std::isfinite(config_.ball_mass) || config_.ball_mass <= 0.0) {
    throw std::invalid_argument("ball_mass must be a positive number of kilograms");
  }
  if (config_.max_shots < 0) throw std::invalid_argument("max_shots must be 0 or more");
  // make_break_scenario names the table size in its error.
  if (config_.game == GameType::snooker && config_.table_size != "12ft") {
    throw std::invalid_argument("snooker is played on the \"12ft\" table, not \"" +
                                config_.table_size + "\"");
  }
  if (config_.game == GameType::three_cushion) {
    if (config_.table_size != "10ft") {
      throw std::invalid_argument("three_cushion is played on the \"10ft\" carom table, not \"" +
                                  config_.table_size + "\"");
    }
    if (config_.carom.target < 1) {
      throw std::invalid_argument("carom.target must be at least 1 point, not " +
                                  std::to_string(config_.carom.target));
    }
    if (config_.carom.innings_limit < 0) {
      throw std::invalid_argument("carom.innings_limit must be 0 (none) or more, not " +
                                  std::to_string(config_.carom.innings_limit));
    }
  }
  base_ = make_break_scenario(std::string(to_string(config_.game)), config_.table_size, 0, 1.0);
  table_ = base_.table;
  if (4.0 * config_.ball_radius >= table_.width) {
    throw std::invalid_argument("ball_radius is too large for a " + config_.table_size + " table");
  }
  if (auto bad = check_game_physics(config_.physics)) throw std::invalid_argument(*bad);
  const GamePhysics& gp = config_.physics;
  base_.physics.ball_ball_model = gp.ball_ball_model;
  base_.physics.ball_ball_friction_fit = gp.ball_ball_friction_fit;
  base_.physics.ball_ball_friction_curve = gp.ball_ball_friction_curve;
  base_.physics.airborne = gp.airborne;
  base_.physics.ball_ball_friction = gp.ball_ball_friction;
  base_.physics.spinning_friction = gp.spinning_friction;
  // The cushion law as a scenario's table.cushion_model sets it:
  // mathavan_2010 with Mathavan et al.'s own restitution and contact
  // height (the restitution is each ball's wall_restitution).
  const double e = default_cushion_restitution(gp.cushion_model);
  table_.cushion.model = gp.cushion_model;
  table_.cushion.restitution = e;
  if (gp.cushion_model == CushionModel::mathavan_2010) {
    table_.cushion.nose_height = kMathavanNoseHeight;
  }
  base_.table = table_;
  base_.cue.reset();
  base_.balls.clear();
  base_.start.clear();
  static constexpr const char* kCaromIds[] = {"white", "yellow", "red"};
  const bool carom = config_.game == GameType::three_cushion;
  for (int n = 0; n < ball_count(); ++n) {
    const std::string id = carom ? kCaromIds[n] : n == 0 ? "cue" : std::to_string(n);
    base_.balls.push_back({id, config_.ball_radius, config_.ball_mass, e});
  }
}

int Rules::ball_count() const { return ruleset_->ball_count(); }

int Rules::cue_ball(const GameState& s) const { return ruleset_->cue_ball(s); }

std::vector<Foul> Rules::foul_kinds() const {
  std::vector<Foul> kinds = ruleset_->foul_kinds();
  // Only balls in flight leave the table: without airborne physics the
  // kind cannot occur, and summaries keep the list they always had.
  if (config_.physics.airborne) kinds.push_back(Foul::ball_off_table);
  return kinds;
}

double Rules::head_string() const { return table_.head_spot.x; }

GameState Rules::start(std::uint64_t rack_seed, int breaker) const {
  if (breaker != 0 && breaker != 1) throw std::invalid_argument("breaker must be 0 or 1");
  GameState s;
  s.game = config_.game;
  s.position.assign(static_cast<std::size_t>(ball_count()), Vec2{});
  s.on_table.assign(static_cast<std::size_t>(ball_count()), 0);
  if (ruleset_->start(*this, rack_seed, breaker, s)) return s;
  const std::string game(to_string(config_.game));
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

std::vector<int> Rules::targets(const GameState& s) const { return ruleset_->targets(s); }

std::vector<int> Rules::balls_on(const GameState& s) const { return ruleset_->balls_on(s); }

int Rules::ball_value(int ball) const {
  if (ball <= 0 || ball >= ball_count()) return 0;
  return ruleset_->ball_value(ball);
}

Standing Rules::standing(const GameState& s) const { return ruleset_->standing(s); }

LegalActions Rules::legal_actions(const GameState& s) const {
  LegalActions la;
  if (s.phase == Phase::game_over) return la;
  if (s.phase != Phase::break_shot && s.phase != Phase::shot) {
    la.choices = ruleset_->state_choices(s);
    return la;
  }
  la.place = s.ball_in_hand;
  la.must_place = !s.on_table[0];
  la.shoot = !la.must_place;
  ruleset_->legal_shot(s, la);
  la.targets = ruleset_->targets(s);
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
    return "the cue ball would not lie on the playing surface clear of the "
           "cushions";
  }
  if (s.ball_in_hand == BallInHand::kitchen && p.x > head_string()) {
    return "the cue ball must be placed behind the head string (x <= " +
           std::to_string(head_string()) + " m)";
  }
  if (auto why = ruleset_->check_place(*this, s, p)) return why;
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
  if (shot.cue_ball) {
    if (config_.game != GameType::three_cushion) {
      return "only three-cushion shots name the ball they strike (cue_ball)";
    }
    const int b = *shot.cue_ball;
    if (b < 0 || b >= ball_count() || !s.on_table[static_cast<std::size_t>(b)]) {
      return "cue_ball " + std::to_string(b) + " is not a ball on the table (0-" +
             std::to_string(ball_count() - 1) + ")";
    }
  }
  const CueStrike& c = shot.strike;
  if (!std::isfinite(c.speed) || c.speed <= 0.0 || c.speed > kMaxCueSpeed) {
    return "strike speed must be in (0, 20] m/s";
  }
  if (!std::isfinite(c.phi)) return "strike phi must be a finite angle";
  if (!std::isfinite(c.theta) || c.theta < 0.0 || c.theta >= 90.0) {
    return "strike theta must be in [0, 90) degrees";
  }
  if (!std::isfinite(c.a) || !std::isfinite(c.b) || std::abs(c.a) > 1.0 || std::abs(c.b) > 1.0) {
    return "strike offsets a and b must be within the ball ([-1, 1] radii)";
  }
  return ruleset_->check_shot(*this, s, shot);
}

// ---------------------------------------------------------------------------
// Physics of a shot

Scenario Rules::shot_scenario(const GameState& s, const CueStrike& strike,
                              std::vector<int>* numbers) const {
  return shot_scenario(s, strike, cue_ball(s), numbers);
}

Scenario Rules::shot_scenario(const GameState& s, const CueStrike& strike, int cue_number,
                              std::vector<int>* numbers) const {
  Scenario sc;
  shot_scenario(s, strike, cue_number, numbers, sc);
  return sc;
}

void Rules::shot_scenario(const GameState& s, const CueStrike& strike, int cue_number,
                          std::vector<int>* numbers, Scenario& sc) const {
  // Every field as a new Scenario has it, but the memory kept.
  sc.physics = base_.physics;
  sc.table = table_;
  sc.balls.clear();
  sc.start.clear();
  sc.pair_restitution.clear();
  sc.until = Until{};
  sc.until.rest = true;
  sc.sample_dt.reset();
  sc.max_events = Scenario{}.max_events;
  if (numbers) numbers->clear();
  std::int32_t cue_index = 0;
  for (std::size_t b = 0; b < s.on_table.size(); ++b) {
    if (!s.on_table[b]) continue;
    if (static_cast<int>(b) == cue_number) cue_index = static_cast<std::int32_t>(sc.balls.size());
    sc.balls.push_back(base_.balls[b]);
    BallState st;
    st.position = s.position[b];
    sc.start.push_back(st);
    if (numbers) numbers->push_back(static_cast<int>(b));
  }
  // A cue ball off the table (in hand) leaves the strike on the first
  // ball, as it always has: the caller places it first.
  CueSpec cue;
  cue.ball = cue_index;
  cue.strike = strike;
  sc.cue = cue;
}

ShotFacts Rules::facts(const std::vector<Event>& events, int cue) const {
  ShotFacts f;
  double contact_time = -1.0;
  std::vector<int> to_cushion;
  for (const Event& e : events) {
    switch (e.type) {
      case EventType::ball_ball:
        if (f.first_hit < 0 && (e.ball == cue || e.other == cue)) {
          f.first_hit = e.ball == cue ? e.other : e.ball;
          contact_time = e.time;
        }
        break;
      case EventType::ball_cushion:
        if (f.first_hit >= 0 && e.time >= contact_time) f.cushion_after_contact = true;
        if (e.ball != cue && !has(to_cushion, e.ball)) to_cushion.push_back(e.ball);
        break;
      case EventType::ball_pocket:
        f.pocketed.push_back(e.ball);
        f.pocket_of.push_back(e.pocket);
        break;
      case EventType::ball_off_table:
        f.off_table.push_back(e.ball);
        break;
      case EventType::cue_strike:
      case EventType::state_change:
      case EventType::ball_slate:
        break;
    }
  }
  f.object_balls_to_cushion = static_cast<int>(to_cushion.size());
  return f;
}

Vec2 Rules::spot_position(const GameState& s, int ball) const {
  if (const std::optional<Vec2> p = ruleset_->spot_position(*this, s, ball)) return *p;
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
  throw std::logic_error("no free place on the long string to spot ball " + std::to_string(ball));
}

// ---------------------------------------------------------------------------
// Playing an action

Outcome Rules::apply(const GameState& state, const Action& action) const {
  ShotWorkspace work;
  return apply(state, action, work);
}

Outcome Rules::apply(const GameState& state, const Action& action, ShotWorkspace& work) const {
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
    detail::DecisionRuling ruling{*this, state, s, r, shooter, opp, who};
    ruleset_->decide(ruling, d->choice);
    return out;
  }

  // A shot: simulate it and read what happened.
  const Shoot& shot = std::get<Shoot>(action);
  std::vector<int>& numbers = work.numbers;
  const int cue = shot.cue_ball.value_or(cue_ball(state));
  shot_scenario(state, shot.strike, cue, &numbers, work.scenario);
  // The first shot moves the scenario into its simulation; later ones
  // re-arm that simulation with a copy (into memory it already has).
  if (work.simulation) {
    work.simulation->reset(work.scenario);
  } else {
    work.simulation.emplace(std::move(work.scenario));
  }
  Simulation& sim = *work.simulation;
  sim.advance_to_rest();
  if (!sim.at_rest()) {
    throw std::logic_error("the shot did not come to rest within the event limit");
  }
  out.events = sim.events();
  for (Event& e : out.events) {
    if (e.ball >= 0) e.ball = numbers[static_cast<std::size_t>(e.ball)];
    if (e.other >= 0) e.other = numbers[static_cast<std::size_t>(e.other)];
  }
  out.facts = facts(out.events, cue);
  out.facts.miscue = sim.cue_result() && sim.cue_result()->miscue;
  for (std::size_t k = 0; k < numbers.size(); ++k) {
    const auto b = static_cast<std::size_t>(numbers[k]);
    const BallState st = sim.ball(k);
    if (st.state == MotionState::pocketed || st.state == MotionState::off_table) {
      s.on_table[b] = 0;
    } else {
      s.position[b] = st.position;
    }
  }
  rule_shot(state, shot, out);
  return out;
}

Outcome Rules::apply_events(const GameState& state, const Shoot& shot, std::vector<Event> events,
                            const std::vector<Vec2>& rest, bool miscue) const {
  if (auto why = check(state, Action{shot})) throw std::invalid_argument(*why);
  const int n = ball_count();
  if (rest.size() != static_cast<std::size_t>(n)) {
    throw std::invalid_argument("rest: " + std::to_string(n) +
                                " positions (one per ball) needed, not " +
                                std::to_string(rest.size()));
  }
  for (std::size_t i = 0; i < events.size(); ++i) {
    const Event& e = events[i];
    if (e.ball < -1 || e.ball >= n || e.other < -1 || e.other >= n) {
      throw std::invalid_argument("events[" + std::to_string(i) +
                                  "]: names no ball of the game (0-" + std::to_string(n - 1) + ")");
    }
  }
  Outcome out;
  out.state = state;
  GameState& s = out.state;
  out.events = std::move(events);
  out.facts = facts(out.events, shot.cue_ball.value_or(cue_ball(state)));
  out.facts.miscue = miscue;
  for (int b : out.facts.pocketed) s.on_table[static_cast<std::size_t>(b)] = 0;
  for (int b : out.facts.off_table) s.on_table[static_cast<std::size_t>(b)] = 0;
  for (std::size_t b = 0; b < s.on_table.size(); ++b) {
    if (!state.on_table[b]) continue;
    if (!std::isfinite(rest[b].x) || !std::isfinite(rest[b].y)) {
      throw std::invalid_argument("rest[" + std::to_string(b) + "]: not a finite position");
    }
    // A ball that left the table keeps its place from before the shot, as
    // in apply().
    if (s.on_table[b]) s.position[b] = rest[b];
  }
  rule_shot(state, shot, out);
  return out;
}

void Rules::rule_shot(const GameState& state, const Shoot& shot, Outcome& out) const {
  GameState& s = out.state;
  Ruling& r = out.ruling;
  const ShotFacts& f = out.facts;
  const int shooter = state.player;
  const int opp = 1 - shooter;
  const std::string who = player_name(shooter);
  s.shots += 1;
  s.kitchen_shot = false;
  s.after_push_out = false;

  detail::ShotRuling ruling{*this, state, shot,  out.events, f,  s,  r,     shooter, opp,
                            who,   {},    false, false,      {}, {}, false, {}};
  ruling.is_break = state.phase == Phase::break_shot;
  ruling.cue_in = has(f.pocketed, 0);
  ruling.cue_off = has(f.off_table, 0);
  for (int b : f.pocketed) {
    if (b != 0) ruling.objects.push_back(b);
  }
  for (int b : f.off_table) {
    if (b != 0) ruling.objects_off.push_back(b);
  }
  ruling.targets = ruleset_->targets(state);
  std::string& what = ruling.what;
  what = who + (ruling.objects.empty() ? " pockets nothing"
                                       : " pockets " + detail::join_balls(ruling.objects));
  if (ruling.cue_in) what += ruling.objects.empty() ? " but scratches" : " and scratches";
  what += ". ";
  if (!f.off_table.empty()) {
    // "The 3 leaves the table." / "The cue ball and the 3 leave the table."
    const std::string balls = detail::join_balls(f.off_table);
    what += (f.off_table.front() == 0 ? "T" + balls.substr(1) : "The " + balls) +
            (f.off_table.size() == 1 ? " leaves" : " leave") + " the table. ";
  }

  // Fouls common to every game on a pool table.
  if (ruling.cue_in) ruling.foul(Foul::scratch);
  if (!f.off_table.empty()) ruling.foul(Foul::ball_off_table);

  ruleset_->rule_shot(ruling);

  r.call_made = !ruling.is_break && shot.call && r.fouls.empty() &&
                ruling.pocket_of(shot.call->ball) == shot.call->pocket;
  if (s.phase != Phase::game_over && config_.max_shots > 0 && s.shots >= config_.max_shots) {
    ruling.game_over(-1, "stalemate: no result after " + std::to_string(s.shots) + " shots");
    r.text += " The game is drawn (" + s.result + ").";
  }
}

}  // namespace breakshot
