// The JSON of a game's table and its markings: one encoding, used by the
// web facade (bs_game_table) and the Python binding (Game.table).
// Internal: not installed.
//
//   table       {"size", "length", "width", "ball_radius", "ball_count",
//                "head_string", "head_spot", "foot_spot",
//                "outline": [[x, y]], "walls": [WALL], "pockets": [POCKET],
//                snooker only: "snooker": SNOOKER_MARKS,
//                three-cushion only: "carom": CAROM_MARKS}
//   WALL        {"kind": "segment" | "corner" | "arc", "a", "b", "normal",
//                "radius", "name"}
//   POCKET      {"centre", "radius", "name"}, in the index order calls use
//   SNOOKER_MARKS {"baulk_line" (x), "d_centre", "d_radius",
//                "spots": {"yellow", "green", "brown", "blue", "pink", "black"}}
//   CAROM_MARKS {"top_spot", "centre_spot", "bottom_spot",
//                "starting_spots": [2], "diamonds": [[x, y]]}
//
// Points are [x, y] in metres (table.hpp's frame). Not part of records.

#pragma once

#include <string_view>

#include "breakshot/carom.hpp"
#include "breakshot/game.hpp"
#include "breakshot/snooker.hpp"
#include "io/game_json.hpp"

namespace breakshot::json_io {

/// A wall's kind by name: "segment", "corner" or "arc".
std::string_view wall_kind_name(WallKind k);
ojson snooker_marks_json(const SnookerMarks& m);
ojson carom_marks_json(const CaromMarks& m);
/// The table `rules` plays on, with the game's markings.
ojson game_table_json(const Rules& rules);

}  // namespace breakshot::json_io
