// The baseline player's three-cushion shot (internal; baseline.cpp uses
// it). The method: baseline_carom.cpp.
#pragma once

#include "breakshot/game.hpp"

namespace breakshot::ai {

/// The baseline's shot in a three-cushion state (a shot phase): a
/// one-ball-first system shot from the mirror construction, the first of
/// its refinements on the engine that scores, else the easiest as the
/// geometry gives it.
Shoot three_cushion_shot(const Rules& rules, const GameState& state);

}  // namespace breakshot::ai
