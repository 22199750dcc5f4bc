// The AI levels' three-cushion decisions (internal; ai_player.cpp
// dispatches to them). The method: carom_ai.cpp and docs/ai.md,
// "Three-cushion".
#pragma once

#include <cstdint>

#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"

namespace breakshot::ai_detail {

/// The shot `level` plays in a three-cushion state (any phase with a shot
/// to play). Deterministic for a seed, for any thread count.
Action carom_action(const AiLevel& level, const Rules& rules, const GameState& state,
                    std::uint64_t seed);

}  // namespace breakshot::ai_detail
