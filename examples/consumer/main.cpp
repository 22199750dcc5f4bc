// Uses an installed breakshot through find_package(breakshot): builds a
// scenario in code, simulates it, prints what happened and checks the
// result against what physics says. Exits non-zero if it looks wrong.
#include <breakshot/breakshot.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <variant>

namespace bs = breakshot;

namespace {

int failures = 0;

void expect(bool ok, const std::string& what) {
  if (!ok) {
    std::fprintf(stderr, "consumer: FAILED: %s\n", what.c_str());
    ++failures;
  }
}

}  // namespace

int main() {
  // Two equal balls on a 2 m x 2 m frictionless table. The cue ball hits
  // the object ball slightly off centre at t = 0.568 s; neither reaches a
  // wall before t = 1 s, so the collision is the only event and momentum
  // and energy must be what they were at the start.
  const double r = 0.03;
  const double m = 0.17;
  const double speed = 0.6;
  const double offset = 0.01;

  bs::Scenario s;
  s.physics.model = bs::Model::ideal;
  s.table = bs::make_rectangle({-1.0, -1.0}, {1.0, 1.0});
  s.balls = {bs::BallSpec{"cue", r, m, 1.0}, bs::BallSpec{"object", r, m, 1.0}};
  bs::BallState cue;
  cue.position = {-0.4, offset};
  cue.velocity = {speed, 0.0};
  cue.state = bs::MotionState::moving;
  bs::BallState object;
  object.position = {0.0, 0.0};
  object.state = bs::MotionState::stationary;
  s.start = {cue, object};
  s.until.rest = false;
  s.until.time = 1.0;

  if (auto err = bs::validate(s)) {
    std::fprintf(stderr, "consumer: invalid scenario: %s: %s\n", err->path.c_str(),
                 err->reason.c_str());
    return 1;
  }

  const bs::RunResult result = bs::simulate(s);

  std::printf("breakshot consumer: %zu events, final time %.6f s\n", result.events.size(),
              result.final_time);
  for (const bs::Event& e : result.events) {
    std::printf("  t=%.9f %s ball=%d other=%d\n", e.time,
                std::string(bs::to_string(e.type)).c_str(), e.ball, e.other);
  }
  for (std::size_t i = 0; i < result.final_balls.size() && i < s.balls.size(); ++i) {
    const bs::BallState& b = result.final_balls[i];
    std::printf("  %-6s position (%.6f, %.6f) velocity (%.6f, %.6f) %s\n",
                s.balls[i].id.c_str(), b.position.x, b.position.y, b.velocity.x,
                b.velocity.y, std::string(bs::to_string(b.state)).c_str());
  }

  expect(result.complete, "the run completes");
  expect(result.final_time == 1.0, "the run ends at the requested time");
  expect(result.final_balls.size() == 2, "two final states");
  expect(result.events.size() == 1, "exactly one event (the ball-ball collision)");
  if (result.final_balls.size() != 2 || result.events.empty()) {
    std::fprintf(stderr, "consumer: result looks wrong\n");
    return 1;
  }

  const bs::Event& hit = result.events.front();
  const double t_hit = (0.4 - std::sqrt(4 * r * r - offset * offset)) / speed;
  expect(hit.type == bs::EventType::ball_ball, "the event is a ball-ball collision");
  expect(std::abs(hit.time - t_hit) < 1e-12, "the collision happens at the analytic time");

  bs::Vec2 p0{};
  bs::Vec2 p1{};
  double e0 = 0.0;
  double e1 = 0.0;
  for (std::size_t i = 0; i < 2; ++i) {
    p0 += bs::momentum(s.balls[i], s.start[i]);
    p1 += bs::momentum(s.balls[i], result.final_balls[i]);
    e0 += bs::kinetic_energy(s.balls[i], s.start[i]);
    e1 += bs::kinetic_energy(s.balls[i], result.final_balls[i]);
  }
  std::printf("  momentum before (%.12f, %.12f) after (%.12f, %.12f)\n", p0.x, p0.y, p1.x,
              p1.y);
  std::printf("  energy   before %.12f after %.12f\n", e0, e1);
  expect(bs::norm(p1 - p0) <= 1e-12 * bs::norm(p0), "momentum is conserved");
  expect(std::abs(e1 - e0) <= 1e-12 * e0, "energy is conserved (elastic collision)");
  expect(result.final_balls[1].position.x > 0.0, "the object ball moved forwards");

  // The game and AI layers: a game of 9-ball between two baseline players,
  // played through a GameSession, replays identical from its record text.
  bs::GameConfig config;
  config.game = bs::GameType::nine_ball;
  const bs::NoiseModel noise = bs::parse_noise("tournament");
  bs::GameSession game(config, bs::Seats{{"baseline", "baseline"}, {noise, noise}}, 7, 0);
  const auto player = bs::make_player("baseline");
  while (!game.over()) {
    game.play(player->decide(game.rules(), game.state(), game.next_player_seed()));
  }
  std::printf("  9-ball: %zu actions, %s\n", game.actions(), game.state().result.c_str());
  const auto reread = bs::read_record(bs::write_record(game.record()));
  expect(std::holds_alternative<bs::GameRecord>(reread), "the game's record reads back");
  expect(bs::replay(game.record()).identical, "the game replays identical");

  if (failures > 0) {
    std::fprintf(stderr, "consumer: %d check(s) failed\n", failures);
    return 1;
  }
  std::printf("consumer: OK\n");
  return 0;
}
