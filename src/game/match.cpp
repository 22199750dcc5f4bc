// Games and matches between players (include/breakshot/match.hpp).
//
// A game is played through a GameSession (session.hpp), which owns the
// seed streams, the noise and the record.
//
// Noise: each seat shoots with its player's own noise (Player::noise(),
// the AI levels) or, for a player without one, with the match's; the
// record keeps both seats' noise, so replay() needs no player.
//
// The per-player figures are computed from the records alone (add_game),
// so any set of saved records can be summed up the same way.

#include "breakshot/match.hpp"

#include "breakshot/session.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <variant>

namespace breakshot {

namespace {

std::string player_label(int seat, const Player& p) {
  return "player " + std::to_string(seat) + " (" + p.name() + ")";
}

/// Actions a game may take before the guard calls it a runaway: a shot
/// is preceded by at most a placement and a decision or two, so four per
/// shot of the stalemate limit is far more than a game that obeys the
/// limit can reach.
std::size_t action_limit(const GameConfig& config) {
  if (config.max_shots <= 0) return 0;  // no limit asked for
  return 4 * static_cast<std::size_t>(config.max_shots) + 16;
}

const GameState& state_before(const GameRecord& record, std::size_t i) {
  return i == 0 ? record.start : record.actions[i - 1].after;
}

/// Object balls the shot from `before` pocketed: those on the table
/// before and off after, and those the ruling spotted (they were on the
/// table before the shot, so they fell during it).
int pocketed_by_shot(const GameState& before, const RecordedAction& ra) {
  // Three-cushion has no pockets: the balls its rulings spot again left
  // the table or touched another ball.
  if (before.game == GameType::three_cushion) return 0;
  int n = 0;
  for (std::size_t b = 1; b < before.on_table.size() && b < ra.after.on_table.size(); ++b) {
    if (before.on_table[b] && !ra.after.on_table[b]) ++n;
  }
  for (const int b : ra.ruling.spotted) {
    const auto ub = static_cast<std::size_t>(b);
    if (b > 0 && ub < before.on_table.size() && before.on_table[ub] && ub < ra.after.on_table.size() &&
        ra.after.on_table[ub]) {
      ++n;
    }
  }
  return n;
}

/// Snooker's figures of a finished frame (PlayerStats::snooker): the
/// frame's scores, the breaks of its visits (a visit ends with a shot
/// after which the turn does not continue, or with the frame), the
/// penalties and misses.
void add_snooker(MatchSummary& summary, const GameRecord& record, const GameState& end) {
  std::array<SnookerStats*, 2> st{&*summary.players[0].snooker, &*summary.players[1].snooker};
  if (end.snooker) {
    for (std::size_t p = 0; p < 2; ++p) st[p]->points += end.snooker->score[p];
  }
  int visit = 0;
  int visitor = -1;
  const auto close = [&] {
    if (visitor >= 0 && visit > 0) {
      SnookerStats& v = *st[static_cast<std::size_t>(visitor)];
      v.scoring_visits += 1;
      v.break_points += visit;
      v.highest_break = std::max(v.highest_break, visit);
      if (visit >= 50) v.breaks_50 += 1;
      if (visit >= 100) v.breaks_100 += 1;
    }
    visit = 0;
    visitor = -1;
  };
  for (const RecordedAction& ra : record.actions) {
    if (!std::holds_alternative<Shoot>(ra.action) || !ra.ruling.snooker) continue;
    const SnookerRuling& k = *ra.ruling.snooker;
    SnookerStats& me = *st[static_cast<std::size_t>(ra.player)];
    me.foul_points_given += k.penalty;
    if (k.miss) me.misses += 1;
    if (visitor != ra.player) close();
    visitor = ra.player;
    visit += k.points;
    if (!ra.ruling.turn_continues || ra.after.phase == Phase::game_over) close();
  }
  close();
}

/// Three-cushion's figures of a finished game (PlayerStats::carom): the
/// points, and the runs of its innings (an inning ends with a shot after
/// which the turn does not continue, or with the game).
void add_carom(MatchSummary& summary, const GameRecord& record, const GameState& end) {
  std::array<CaromStats*, 2> st{&*summary.players[0].carom, &*summary.players[1].carom};
  if (end.carom) {
    for (std::size_t p = 0; p < 2; ++p) st[p]->points += end.carom->score[p];
  }
  for (const CaromInning& inning : carom_innings(record)) {
    if (inning.points == 0) continue;
    CaromStats& c = *st[static_cast<std::size_t>(inning.player)];
    c.scoring_innings += 1;
    c.highest_run = std::max(c.highest_run, inning.points);
  }
}

/// The noise `p`'s shots are played with: its own, else the match's.
NoiseModel effective_noise(const Player& p, const NoiseModel& match_noise) {
  return p.noise().value_or(match_noise);
}

/// empty_summary with the players' effective noise already known.
MatchSummary empty_summary_with(const MatchOptions& options,
                                const std::array<NoiseModel, 2>& noise,
                                const std::vector<Foul>& fouls) {
  MatchSummary s;
  s.game = options.game;
  s.table_size = options.table_size;
  s.physics = options.physics;
  s.carom = options.carom;
  s.seed = options.seed;
  s.noise = options.noise;
  for (std::size_t p = 0; p < 2; ++p) {
    s.players[p].name = options.players[p];
    s.players[p].noise = to_string(noise[p]);
    // Every foul kind of the game, so that a summary lists them all, 0 included.
    for (const Foul f : fouls) s.players[p].fouls[std::string(to_string(f))] = 0;
    if (options.game == GameType::snooker) s.players[p].snooker = SnookerStats{};
    if (options.game == GameType::three_cushion) s.players[p].carom = CaromStats{};
  }
  return s;
}

GameConfig config_of(const MatchOptions& options) {
  GameConfig config = default_game_config(options.game);
  config.table_size = options.table_size;
  config.physics = options.physics;
  if (options.game == GameType::three_cushion) config.carom = options.carom;
  return config;
}

// A player whose decisions are timed (MatchOptions::timing).
class TimedPlayer final : public Player {
 public:
  TimedPlayer(Player& inner, std::vector<double>& seconds) : inner_(inner), seconds_(seconds) {}
  std::string name() const override { return inner_.name(); }
  std::optional<NoiseModel> noise() const override { return inner_.noise(); }
  Action decide(const Rules& rules, const GameState& state, std::uint64_t seed) override {
    const auto start = std::chrono::steady_clock::now();
    Action a = inner_.decide(rules, state, seed);
    seconds_.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return a;
  }

 private:
  Player& inner_;
  std::vector<double>& seconds_;
};

}  // namespace

GameRecord play_game(const Rules& rules, Player& p0, Player& p1, int breaker,
                     std::uint64_t game_seed, const NoiseModel& noise) {
  if (breaker != 0 && breaker != 1) {
    throw std::invalid_argument("play_game: the breaker must be 0 or 1, not " +
                                std::to_string(breaker));
  }
  const Seats seats{{p0.name(), p1.name()},
                    {effective_noise(p0, noise), effective_noise(p1, noise)}};
  GameSession session(rules.config(), seats, game_seed, breaker);
  Player* const players[2] = {&p0, &p1};
  const std::size_t limit = action_limit(rules.config());
  while (!session.over()) {
    const std::size_t i = session.actions();
    if (limit != 0 && i >= limit) {
      throw std::logic_error("the game did not end after " + std::to_string(i) +
                             " actions (max_shots is " +
                             std::to_string(rules.config().max_shots) + ")");
    }
    const GameState& state = session.state();
    const int seat = state.player;
    Player& player = *players[seat];
    const Action action = player.decide(session.rules(), state, session.next_player_seed());
    if (auto why = session.check(action)) {
      throw std::logic_error(player_label(seat, player) + " chose an action the rules refuse (" +
                             std::string(to_string(state.phase)) + ", action " +
                             std::to_string(i) + "): " + *why);
    }
    try {
      session.play(action);
    } catch (const GameSession::ExecutedRefused& e) {
      // The intended action passed check(), so the noise made it illegal:
      // perturb() promises strikes the rules accept, so this is a bug.
      throw std::logic_error(player_label(seat, player) + ": the shot as executed (after noise) " +
                             "is refused at action " + std::to_string(i) + ": " + e.what());
    }
  }
  return session.record();
}

double PlayerStats::pot_rate() const {
  return pot_attempts > 0 ? static_cast<double>(pots_made) / static_cast<double>(pot_attempts)
                          : 0.0;
}

double SnookerStats::mean_break() const {
  return scoring_visits > 0
             ? static_cast<double>(break_points) / static_cast<double>(scoring_visits)
             : 0.0;
}

double PlayerStats::general_average() const {
  return carom && innings > 0 ? static_cast<double>(carom->points) / static_cast<double>(innings)
                              : 0.0;
}

double PlayerStats::balls_per_inning() const {
  return innings > 0 ? static_cast<double>(balls_pocketed) / static_cast<double>(innings) : 0.0;
}

MatchSummary empty_summary(const MatchOptions& options,
                           const std::array<NoiseModel, 2>& seat_noise) {
  return empty_summary_with(options, seat_noise, Rules(config_of(options)).foul_kinds());
}

void add_game(MatchSummary& summary, const GameRecord& record) {
  const GameState& end = record.actions.empty() ? record.start : record.actions.back().after;
  if (end.phase != Phase::game_over) {
    throw std::invalid_argument("add_game: the game is not over (phase " +
                                std::string(to_string(end.phase)) + ")");
  }
  summary.games_played += 1;
  if (end.winner < 0) {
    summary.draws += 1;
  } else {
    summary.players[static_cast<std::size_t>(end.winner)].games_won += 1;
  }

  // The breaker's first inning is the break; then the incoming player
  // begins one whenever the count moves (GameState::innings).
  summary.players[static_cast<std::size_t>(record.start.player)].innings += record.start.innings;
  std::size_t last_break = 0;  // index of the last break shot
  bool any_break = false;
  for (std::size_t i = 0; i < record.actions.size(); ++i) {
    const RecordedAction& ra = record.actions[i];
    const GameState& before = state_before(record, i);
    PlayerStats& me = summary.players[static_cast<std::size_t>(ra.player)];
    if (ra.after.innings > before.innings) {
      summary.players[static_cast<std::size_t>(ra.after.player)].innings +=
          ra.after.innings - before.innings;
    }
    if (!std::holds_alternative<Shoot>(ra.action)) continue;
    me.shots += 1;
    if (before.phase == Phase::break_shot) {
      me.breaks += 1;
      last_break = i;
      any_break = true;
    }
    me.balls_pocketed += pocketed_by_shot(before, ra);
    const Shoot& shot = std::get<Shoot>(ra.action);
    if (before.phase != Phase::break_shot && shot.call) {
      me.pot_attempts += 1;
      if (ra.ruling.call_made) me.pots_made += 1;
    }
    for (const Foul f : ra.ruling.fouls) me.fouls[std::string(to_string(f))] += 1;
  }

  if (summary.players[0].snooker && summary.players[1].snooker) add_snooker(summary, record, end);
  if (summary.players[0].carom && summary.players[1].carom) add_carom(summary, record, end);

  if (end.winner >= 0 && any_break && record.actions[last_break].player == end.winner) {
    bool opponent_shot = false;
    for (std::size_t i = last_break; i < record.actions.size(); ++i) {
      const RecordedAction& ra = record.actions[i];
      opponent_shot = opponent_shot ||
                      (ra.player != end.winner && std::holds_alternative<Shoot>(ra.action));
    }
    if (!opponent_shot) summary.players[static_cast<std::size_t>(end.winner)].break_and_runs += 1;
  }
}

MatchGameError::MatchGameError(int game, std::uint64_t game_seed, const std::string& reason)
    : std::runtime_error("game " + std::to_string(game) + " (seed " + std::to_string(game_seed) +
                         "): " + reason),
      game_(game),
      game_seed_(game_seed),
      reason_(reason) {}

namespace {

std::string range_text(const GameRange& r) {
  return r.count == 1 ? "game " + std::to_string(r.first)
                      : "games " + std::to_string(r.first) + " to " +
                            std::to_string(r.first + r.count - 1);
}

/// The union of two sets of ranges (each ascending, disjoint, never
/// adjacent), in the same form; std::invalid_argument if they overlap.
std::vector<GameRange> join_ranges(const std::vector<GameRange>& a,
                                   const std::vector<GameRange>& b) {
  std::vector<GameRange> all(a);
  all.insert(all.end(), b.begin(), b.end());
  std::sort(all.begin(), all.end(),
            [](const GameRange& x, const GameRange& y) { return x.first < y.first; });
  std::vector<GameRange> out;
  for (const GameRange& r : all) {
    if (r.count <= 0) continue;
    if (!out.empty()) {
      GameRange& last = out.back();
      // 64 bits: first + count of a range read from a file may pass INT_MAX.
      const std::int64_t last_end = std::int64_t{last.first} + last.count;
      if (r.first < last_end) {
        const std::int64_t end = std::min(last_end, std::int64_t{r.first} + r.count);
        throw std::invalid_argument(
            "first_game: the summaries overlap: both cover " +
            range_text(GameRange{r.first, static_cast<int>(end - r.first)}));
      }
      if (r.first == last_end) {
        last.count += r.count;
        continue;
      }
    }
    out.push_back(r);
  }
  return out;
}

void same(const std::string& field, const std::string& a, const std::string& b) {
  if (a != b) {
    throw std::invalid_argument(field + ": the summaries are of different matches ('" + a +
                                "' and '" + b + "')");
  }
}

}  // namespace

void add_summary(MatchSummary& into, const MatchSummary& part) {
  same("game", std::string(to_string(into.game)), std::string(to_string(part.game)));
  same("table_size", into.table_size, part.table_size);
  if (!(into.physics == part.physics)) {
    throw std::invalid_argument(
        "physics: the summaries are of different matches (played with different physics)");
  }
  if (!(into.carom == part.carom)) {
    throw std::invalid_argument(
        "carom: the summaries are of different matches (another target, innings limit or "
        "equalizing inning)");
  }
  same("seed", std::to_string(into.seed), std::to_string(part.seed));
  same("noise", to_string(into.noise), to_string(part.noise));
  for (std::size_t p = 0; p < 2; ++p) {
    const std::string at = "players[" + std::to_string(p) + "].";
    const PlayerStats& a = into.players[p];
    const PlayerStats& b = part.players[p];
    same(at + "name", a.name, b.name);
    same(at + "noise", a.noise, b.noise);
    std::string ka;
    std::string kb;
    for (const auto& f : a.fouls) ka += (ka.empty() ? "" : ", ") + f.first;
    for (const auto& f : b.fouls) kb += (kb.empty() ? "" : ", ") + f.first;
    same(at + "fouls", ka, kb);
  }
  // Everything that can throw is done before the first change.
  std::vector<GameRange> ranges = join_ranges(into.ranges, part.ranges);
  const auto add = [](int& to, int n, const char* field) {
    if (n > std::numeric_limits<int>::max() - to) {
      throw std::invalid_argument(std::string(field) + ": the sum passes " +
                                  std::to_string(std::numeric_limits<int>::max()));
    }
    to += n;
  };
  MatchSummary sum = into;
  sum.ranges = std::move(ranges);
  add(sum.games_played, part.games_played, "games_played");
  add(sum.draws, part.draws, "draws");
  for (std::size_t p = 0; p < 2; ++p) {
    PlayerStats& to = sum.players[p];
    const PlayerStats& from = part.players[p];
    add(to.games_won, from.games_won, "games_won");
    add(to.breaks, from.breaks, "breaks");
    add(to.break_and_runs, from.break_and_runs, "break_and_runs");
    add(to.innings, from.innings, "innings");
    add(to.shots, from.shots, "shots");
    add(to.balls_pocketed, from.balls_pocketed, "balls_pocketed");
    add(to.pot_attempts, from.pot_attempts, "pot_attempts");
    add(to.pots_made, from.pots_made, "pots_made");
    for (const auto& [kind, count] : from.fouls) add(to.fouls[kind], count, "fouls");
    if (to.snooker && from.snooker) {
      SnookerStats& a = *to.snooker;
      const SnookerStats& b = *from.snooker;
      add(a.points, b.points, "snooker.points");
      a.highest_break = std::max(a.highest_break, b.highest_break);
      add(a.breaks_50, b.breaks_50, "snooker.breaks_50");
      add(a.breaks_100, b.breaks_100, "snooker.breaks_100");
      add(a.scoring_visits, b.scoring_visits, "snooker.scoring_visits");
      add(a.break_points, b.break_points, "snooker.break_points");
      add(a.foul_points_given, b.foul_points_given, "snooker.foul_points_given");
      add(a.misses, b.misses, "snooker.misses");
    }
    if (to.carom && from.carom) {
      CaromStats& a = *to.carom;
      const CaromStats& b = *from.carom;
      add(a.points, b.points, "carom.points");
      a.highest_run = std::max(a.highest_run, b.highest_run);
      add(a.scoring_innings, b.scoring_innings, "carom.scoring_innings");
    }
    to.decision_seconds.insert(to.decision_seconds.end(), from.decision_seconds.begin(),
                               from.decision_seconds.end());
  }
  into = std::move(sum);
}

namespace {

/// The checks every play_match makes on its options.
void check_match_options(const MatchOptions& options) {
  if (options.games < 1) {
    throw std::invalid_argument("the number of games must be at least 1, not " +
                                std::to_string(options.games));
  }
  if (options.first_game < 0) {
    throw std::invalid_argument("first_game: must be 0 or more, not " +
                                std::to_string(options.first_game));
  }
  if (options.first_game > std::numeric_limits<int>::max() - options.games) {
    throw std::invalid_argument("first_game: first_game + games (" +
                                std::to_string(options.first_game) + " + " +
                                std::to_string(options.games) + ") passes " +
                                std::to_string(std::numeric_limits<int>::max()));
  }
  if (options.jobs < 0) {
    throw std::invalid_argument("jobs: must be 0 (one per core) or more, not " +
                                std::to_string(options.jobs));
  }
}

/// Game g of the match, as every play_match plays it.
GameRecord play_match_game(const Rules& rules, const MatchOptions& options, Player& p0, Player& p1,
                           int g) {
  const std::uint64_t game_seed = mix_seed(options.seed, static_cast<std::uint64_t>(g));
  if (!options.name_failing_game) return play_game(rules, p0, p1, g % 2, game_seed, options.noise);
  try {
    return play_game(rules, p0, p1, g % 2, game_seed, options.noise);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw MatchGameError(g, game_seed, e.what());
  }
}

}  // namespace

int match_threads(int jobs, int games) {
  int n = jobs;
  if (n == 0) n = static_cast<int>(std::thread::hardware_concurrency());
  return std::max(1, std::min(n, games));
}

MatchSummary play_match(const MatchOptions& options, Player& p0, Player& p1,
                        const RecordSink& sink) {
  check_match_options(options);
  const Rules rules(config_of(options));
  MatchSummary summary = empty_summary_with(
      options, {effective_noise(p0, options.noise), effective_noise(p1, options.noise)},
      rules.foul_kinds());
  TimedPlayer t0(p0, summary.players[0].decision_seconds);
  TimedPlayer t1(p1, summary.players[1].decision_seconds);
  Player& s0 = options.timing ? static_cast<Player&>(t0) : p0;
  Player& s1 = options.timing ? static_cast<Player&>(t1) : p1;
  summary.ranges = {GameRange{options.first_game, options.games}};
  const int end = options.first_game + options.games;
  for (int g = options.first_game; g < end; ++g) {
    const GameRecord record = play_match_game(rules, options, s0, s1, g);
    add_game(summary, record);
    if (sink) sink(g, record);
  }
  return summary;
}

MatchSummary play_match(const MatchOptions& options, const PlayerFactory& make,
                        const RecordSink& sink) {
  check_match_options(options);
  const int threads = match_threads(options.jobs, options.games);
  // Every worker's players, made here so that a factory's error is thrown
  // before any game starts.
  std::vector<std::array<std::unique_ptr<Player>, 2>> players(static_cast<std::size_t>(threads));
  for (auto& pair : players) {
    for (int seat = 0; seat < 2; ++seat) {
      pair[static_cast<std::size_t>(seat)] = make(seat);
      if (!pair[static_cast<std::size_t>(seat)]) {
        throw std::invalid_argument("play_match: the player factory made no player for seat " +
                                    std::to_string(seat));
      }
    }
  }
  if (threads == 1) return play_match(options, *players[0][0], *players[0][1], sink);

  const Rules rules(config_of(options));
  MatchSummary summary = empty_summary_with(options,
                                            {effective_noise(*players[0][0], options.noise),
                                             effective_noise(*players[0][1], options.noise)},
                                            rules.foul_kinds());
  summary.ranges = {GameRange{options.first_game, options.games}};

  // A finished game waiting for the ones before it to be added.
  struct Slot {
    bool ready = false;
    GameRecord record;
    std::array<std::vector<double>, 2> seconds;
    std::exception_ptr error;
  };
  const std::size_t n = static_cast<std::size_t>(options.games);
  std::vector<Slot> slots(n);
  std::mutex mutex;
  std::size_t added = 0;           // games added to the summary, in order (under mutex)
  std::exception_ptr first_error;  // the first error in index order (under mutex)
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};

  // Under the mutex: adds the games that complete the order.
  const auto flush = [&]() {
    while (added < n && slots[added].ready && !first_error) {
      Slot& slot = slots[added];
      if (slot.error) {
        first_error = slot.error;
        break;
      }
      try {
        add_game(summary, slot.record);
        for (std::size_t p = 0; p < 2; ++p) {
          auto& all = summary.players[p].decision_seconds;
          all.insert(all.end(), slot.seconds[p].begin(), slot.seconds[p].end());
        }
        if (sink) sink(options.first_game + static_cast<int>(added), slot.record);
      } catch (...) {
        first_error = std::current_exception();
        break;
      }
      slot = Slot{};  // the record is no longer needed
      ++added;
    }
    if (first_error) stop = true;
  };

  const auto work = [&](std::size_t w) {
    Player& p0 = *players[w][0];
    Player& p1 = *players[w][1];
    while (!stop) {
      const std::size_t i = next.fetch_add(1);
      if (i >= n) break;
      Slot done;
      try {
        TimedPlayer t0(p0, done.seconds[0]);
        TimedPlayer t1(p1, done.seconds[1]);
        Player& s0 = options.timing ? static_cast<Player&>(t0) : p0;
        Player& s1 = options.timing ? static_cast<Player&>(t1) : p1;
        done.record =
            play_match_game(rules, options, s0, s1, options.first_game + static_cast<int>(i));
      } catch (...) {
        done.error = std::current_exception();
      }
      done.ready = true;
      const std::lock_guard<std::mutex> lock(mutex);
      slots[i] = std::move(done);
      flush();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads));
  for (std::size_t w = 0; w < static_cast<std::size_t>(threads); ++w) pool.emplace_back(work, w);
  for (std::thread& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
  return summary;
}

}  // namespace breakshot
