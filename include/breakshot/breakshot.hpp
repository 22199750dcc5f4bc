// Every public header of the library in one include, layer by layer
// (docs/architecture.md, "Layers"). The engine's internals (root finders,
// deterministic maths, cluster and airborne impulses) live beside their
// sources in src/, and so does the server of `breakshot serve`
// (src/web/serve.hpp), which is part of the command, not of the library.
#pragma once

// physics: tables, balls, the event-driven simulation, measures
#include "breakshot/ball.hpp"
#include "breakshot/carom.hpp"
#include "breakshot/event.hpp"
#include "breakshot/lab.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/scenario.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/snooker.hpp"
#include "breakshot/table.hpp"
#include "breakshot/vec.hpp"
#include "breakshot/version.hpp"

// game: the rules, racks, noise, a game in progress, records, matches
#include "breakshot/batch.hpp"
#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/record.hpp"
#include "breakshot/session.hpp"

// ai: the computer players
#include "breakshot/ai.hpp"
#include "breakshot/players.hpp"
#include "breakshot/pot_map.hpp"

// io: scenario and result files, plots, game records, match summaries
#include "breakshot/match_io.hpp"
#include "breakshot/plot.hpp"
#include "breakshot/record_io.hpp"
#include "breakshot/scenario_io.hpp"
