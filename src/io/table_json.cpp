// The JSON of a game's table and its markings (table_json.hpp).

#include "io/table_json.hpp"

#include <array>

namespace breakshot::json_io {

std::string_view wall_kind_name(WallKind k) {
  switch (k) {
    case WallKind::segment:
      return "segment";
    case WallKind::corner:
      return "corner";
    case WallKind::arc:
      return "arc";
  }
  return "segment";
}

ojson snooker_marks_json(const SnookerMarks& m) {
  ojson j = ojson::object();
  j["baulk_line"] = m.baulk_x;
  j["d_centre"] = vec2_json(m.d_centre);
  j["d_radius"] = m.d_radius;
  ojson spots = ojson::object();
  spots["yellow"] = vec2_json(m.yellow);
  spots["green"] = vec2_json(m.green);
  spots["brown"] = vec2_json(m.brown);
  spots["blue"] = vec2_json(m.blue);
  spots["pink"] = vec2_json(m.pink);
  spots["black"] = vec2_json(m.black);
  j["spots"] = spots;
  return j;
}

ojson carom_marks_json(const CaromMarks& m) {
  ojson j = ojson::object();
  j["top_spot"] = vec2_json(m.top_spot);
  j["centre_spot"] = vec2_json(m.centre_spot);
  j["bottom_spot"] = vec2_json(m.bottom_spot);
  j["starting_spots"] =
      ojson::array({vec2_json(m.starting_spots[0]), vec2_json(m.starting_spots[1])});
  ojson diamonds = ojson::array();
  for (const Vec2 d : m.diamonds) diamonds.push_back(vec2_json(d));
  j["diamonds"] = diamonds;
  return j;
}

ojson game_table_json(const Rules& rules) {
  const Table& t = rules.table();
  const GameConfig& c = rules.config();
  ojson j = ojson::object();
  j["size"] = c.table_size;
  j["length"] = t.length;
  j["width"] = t.width;
  j["ball_radius"] = c.ball_radius;
  j["ball_count"] = rules.ball_count();
  j["head_string"] = rules.head_string();
  j["head_spot"] = vec2_json(t.head_spot);
  j["foot_spot"] = vec2_json(t.foot_spot);
  ojson outline = ojson::array();
  for (const Vec2 v : t.outline) outline.push_back(vec2_json(v));
  j["outline"] = outline;
  ojson walls = ojson::array();
  for (const Wall& w : t.walls) {
    ojson wj = ojson::object();
    wj["kind"] = wall_kind_name(w.kind);
    wj["a"] = vec2_json(w.a);
    wj["b"] = vec2_json(w.b);
    wj["normal"] = vec2_json(w.normal);
    wj["radius"] = w.radius;
    wj["name"] = w.name;
    walls.push_back(wj);
  }
  j["walls"] = walls;
  ojson pockets = ojson::array();
  for (const Pocket& p : t.pockets) {
    ojson pj = ojson::object();
    pj["centre"] = vec2_json(p.centre);
    pj["radius"] = p.radius;
    pj["name"] = p.name;
    pockets.push_back(pj);
  }
  j["pockets"] = pockets;
  if (c.game == GameType::snooker) j["snooker"] = snooker_marks_json(snooker_marks());
  if (c.game == GameType::three_cushion) j["carom"] = carom_marks_json(carom_marks());
  return j;
}

}  // namespace breakshot::json_io
