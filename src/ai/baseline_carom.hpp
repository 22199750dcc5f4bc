// The baseline player's three-cushion shot (internal; baseline.cpp uses
// it). The method: baseline_carom.cpp.
#pragma once

#include <vector>

#include "breakshot/game.hpp"
#include "breakshot/vec.hpp"

namespace breakshot::ai {

/// The centre of the image (i, j) of `p` in the unfolded table of ball
/// centres [lo.x, hi.x] x [lo.y, hi.y]: |i| reflections across the short
/// cushions, |j| across the long ones.
Vec2 carom_image(Vec2 p, Vec2 lo, Vec2 hi, int i, int j);

/// A rolling cue ball's departure direction (not normalised) from a
/// contact with normal n, travelling along u (both unit).
Vec2 carom_departure(Vec2 u, Vec2 n);

/// The contact angles on a ball at F (angle of the normal from the cue
/// ball's side, radians) from which a rolling cue ball coming from C
/// departs toward `target`, scanned in `steps` steps round the ball and
/// bisected.
std::vector<double> carom_contact_angles(Vec2 C, Vec2 F, Vec2 target, double R, int steps);

/// The baseline's shot in a three-cushion state (a shot phase): a
/// one-ball-first system shot from the mirror construction, the first of
/// its refinements on the engine that scores, else the easiest as the
/// geometry gives it.
Shoot three_cushion_shot(const Rules& rules, const GameState& state);

}  // namespace breakshot::ai
