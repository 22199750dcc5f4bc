// Exact equality of game records (include/breakshot/record.hpp): doubles
// are compared by their bits, so -0 is not +0 and a NaN equals itself.
// The names of a record's ending kinds, and three-cushion's innings of a
// record (carom_innings).
#include "breakshot/record.hpp"

#include <bit>
#include <cstdint>
#include <optional>
#include <string_view>
#include <variant>

namespace breakshot {

namespace {

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool identical(const GamePhysics& a, const GamePhysics& b) {
  const FrictionCurve& ka = a.ball_ball_friction_curve;
  const FrictionCurve& kb = b.ball_ball_friction_curve;
  return a.cushion_model == b.cushion_model && a.ball_ball_model == b.ball_ball_model &&
         a.ball_ball_friction_fit == b.ball_ball_friction_fit && same_bits(ka.a, kb.a) &&
         same_bits(ka.b, kb.b) && same_bits(ka.c, kb.c) &&
         same_bits(a.ball_ball_friction, b.ball_ball_friction) && a.airborne == b.airborne &&
         same_bits(a.spinning_friction, b.spinning_friction);
}

bool identical(const GameConfig& a, const GameConfig& b) {
  return a.game == b.game && a.table_size == b.table_size &&
         same_bits(a.ball_radius, b.ball_radius) && same_bits(a.ball_mass, b.ball_mass) &&
         a.max_shots == b.max_shots && identical(a.physics, b.physics);
}

bool identical(const NoiseModel& a, const NoiseModel& b) {
  return same_bits(a.phi, b.phi) && same_bits(a.theta, b.theta) && same_bits(a.speed, b.speed) &&
         same_bits(a.a, b.a) && same_bits(a.b, b.b);
}

}  // namespace

bool identical(const CueStrike& a, const CueStrike& b) {
  return same_bits(a.speed, b.speed) && same_bits(a.phi, b.phi) && same_bits(a.theta, b.theta) &&
         same_bits(a.a, b.a) && same_bits(a.b, b.b);
}

bool identical(const Action& a, const Action& b) {
  if (a.index() != b.index()) return false;
  if (const auto* pa = std::get_if<PlaceCueBall>(&a)) {
    const auto& pb = std::get<PlaceCueBall>(b);
    return same_bits(pa->position.x, pb.position.x) && same_bits(pa->position.y, pb.position.y);
  }
  if (const auto* sa = std::get_if<Shoot>(&a)) {
    const auto& sb = std::get<Shoot>(b);
    return identical(sa->strike, sb.strike) && sa->call == sb.call && sa->safety == sb.safety &&
           sa->push_out == sb.push_out;
  }
  return std::get<Decide>(a) == std::get<Decide>(b);
}

bool identical(const GameState& a, const GameState& b) {
  if (!(a == b)) return false;
  for (std::size_t i = 0; i < a.position.size(); ++i) {
    if (!same_bits(a.position[i].x, b.position[i].x) ||
        !same_bits(a.position[i].y, b.position[i].y)) {
      return false;
    }
  }
  return true;
}

bool RecordedAction::operator==(const RecordedAction& o) const {
  const bool intended_same = intended.has_value() == o.intended.has_value() &&
                             (!intended || identical(*intended, *o.intended));
  return player == o.player && identical(action, o.action) && intended_same &&
         noise_seed == o.noise_seed && ruling == o.ruling && identical(after, o.after);
}

bool GameRecord::operator==(const GameRecord& o) const {
  return identical(config, o.config) && engine == o.engine && players == o.players &&
         seed == o.seed && identical(noise[0], o.noise[0]) && identical(noise[1], o.noise[1]) &&
         identical(start, o.start) && actions == o.actions && ending == o.ending;
}

std::string_view to_string(GameEnding::Kind k) {
  return k == GameEnding::Kind::forfeit ? "forfeit" : "abandoned";
}

std::optional<GameEnding::Kind> parse_ending_kind(std::string_view s) {
  if (s == "forfeit") return GameEnding::Kind::forfeit;
  if (s == "abandoned") return GameEnding::Kind::abandoned;
  return std::nullopt;
}

std::vector<CaromInning> carom_innings(const GameRecord& record) {
  std::vector<CaromInning> innings;
  CaromInning inning;
  bool open = false;
  const auto close = [&] {
    if (open) innings.push_back(inning);
    inning = CaromInning{};
    open = false;
  };
  for (const RecordedAction& ra : record.actions) {
    if (!std::holds_alternative<Shoot>(ra.action) || !ra.ruling.carom) continue;
    if (open && inning.player != ra.player) close();
    open = true;
    inning.player = ra.player;
    if (ra.ruling.carom->point) inning.points += 1;
    if (!ra.ruling.turn_continues || ra.after.phase == Phase::game_over) close();
  }
  close();
  return innings;
}

}  // namespace breakshot
