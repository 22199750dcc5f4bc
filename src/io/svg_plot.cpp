// SVG plots of a trace (plot.hpp; trace() in src/physics/lab.cpp): the balls'
// paths on the table, kinetic energy against time and momentum against
// time. Plain standalone SVG 1.1 text, written without any library.
//
// The output is deterministic: every number goes through std::to_chars
// with a fixed precision (no locale, no iostream state), and nothing
// depends on addresses, time or hash order.

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "breakshot/carom.hpp"
#include "breakshot/lab.hpp"
#include "breakshot/plot.hpp"
#include "breakshot/snooker.hpp"
#include "io/svg_chart.hpp"

namespace breakshot {
namespace {

using namespace svg;  // the chart kit (svg_chart.hpp)

// ---------------------------------------------------------------------------
// Limits that keep the files readable and small.

// The trajectory plot draws the paths of this many balls at most; beyond
// that a plot is a scribble, and a 1000-disk gas would be megabytes.
constexpr std::size_t kMaxPaths = 20;
// The time plots show every ball up to kMaxSeriesAll balls, otherwise
// the first kMaxSeriesSome (and always the total).
constexpr std::size_t kMaxSeriesAll = 12;
constexpr std::size_t kMaxSeriesSome = 10;

// tab10 followed by its light companions (as in matplotlib's tab20
// reordered), so the first 20 balls get distinct colours and a ball has
// the same colour in all three plots.
constexpr std::array<const char*, 20> kPalette = {
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf",
    "#aec7e8", "#ffbb78", "#98df8a", "#ff9896", "#c5b0d5",
    "#c49c94", "#f7b6d2", "#c7c7c7", "#dbdb8d", "#9edae5"};
constexpr const char* kOtherBalls = "#a0a0a0";

const char* ball_colour(std::size_t i) { return kPalette[i % kPalette.size()]; }

// ---------------------------------------------------------------------------
// Data common to the plots.

struct Common {
  std::size_t n = 0;  // balls
  std::string model;
  std::vector<double> t;  // frame times
  double t0 = 0.0;
  double t1 = 0.0;
};

Common common(const Scenario& scenario, const std::vector<Sample>& frames) {
  Common c;
  c.n = scenario.balls.size();
  c.model = std::string(to_string(scenario.physics.model));
  c.t.reserve(frames.size());
  for (const Sample& f : frames) {
    c.t.push_back(f.time);
  }
  if (!frames.empty()) {
    c.t0 = frames.front().time;
    c.t1 = frames.back().time;
  }
  return c;
}

std::string time_range(const Common& c) {
  return "t = " + general(c.t0) + " to " + general(c.t1) + " s";
}

// A ball's state in a frame; frames shorter than the scenario (which a
// correct trace never has) read as at rest at the origin.
BallState state_of(const Sample& f, std::size_t i) {
  return i < f.balls.size() ? f.balls[i] : BallState{};
}

std::size_t series_count(std::size_t n) {
  return n <= kMaxSeriesAll ? n : kMaxSeriesSome;
}

// "total and every ball", or "total and the first 10 of 16 balls".
std::string shown_balls(std::size_t n) {
  if (n <= kMaxSeriesAll) {
    return "system total (black) and each ball";
  }
  return "system total (black) and the first " + std::to_string(kMaxSeriesSome) +
         " of " + std::to_string(n) + " balls";
}

std::vector<LegendItem> series_legend(const Scenario& scenario, std::size_t shown) {
  std::vector<LegendItem> items;
  items.push_back({LegendItem::Swatch::line, "#000", 3.0, "total"});
  for (std::size_t i = 0; i < shown; ++i) {
    items.push_back({LegendItem::Swatch::line, ball_colour(i), 1.5,
                     legend_label(scenario.balls[i].id)});
  }
  if (shown < scenario.balls.size()) {
    items.push_back({LegendItem::Swatch::none, "", 0.0,
                     "(" + std::to_string(scenario.balls.size() - shown) +
                         " more not shown)"});
  }
  return items;
}

// ---------------------------------------------------------------------------
// The three plots.

std::string trajectories_svg(const Scenario& scenario, const std::vector<Sample>& frames) {
  const Common c = common(scenario, frames);
  const std::size_t paths = std::min(c.n, kMaxPaths);
  const std::vector<BallState>& first = frames.empty() ? scenario.start : frames.front().balls;
  const std::vector<BallState>& last = frames.empty() ? scenario.start : frames.back().balls;

  // Extent: the table and everything a ball ever reached (a pocketed
  // ball may sit beyond the cushion noses).
  double x0 = scenario.table.min.x;
  double y0 = scenario.table.min.y;
  double x1 = scenario.table.max.x;
  double y1 = scenario.table.max.y;
  auto grow = [&](Vec2 p, double r) {
    if (std::isfinite(p.x) && std::isfinite(p.y)) {
      x0 = std::min(x0, p.x - r);
      y0 = std::min(y0, p.y - r);
      x1 = std::max(x1, p.x + r);
      y1 = std::max(y1, p.y + r);
    }
  };
  for (Vec2 v : scenario.table.outline) {
    grow(v, 0.0);
  }
  for (const Sample& f : frames) {
    for (std::size_t i = 0; i < f.balls.size() && i < c.n; ++i) {
      grow(f.balls[i].position, scenario.balls[i].radius);
    }
  }
  for (std::size_t i = 0; i < first.size() && i < c.n; ++i) {
    grow(first[i].position, scenario.balls[i].radius);
  }
  if (!(x1 > x0)) {
    x0 -= 0.5;
    x1 += 0.5;
  }
  if (!(y1 > y0)) {
    y0 -= 0.5;
    y1 += 0.5;
  }
  const double pad = 0.04 * std::max(x1 - x0, y1 - y0);
  x0 -= pad;
  y0 -= pad;
  x1 += pad;
  y1 += pad;

  // Equal aspect: one scale (px per metre) for both axes, and one tick
  // step, so a square looks square and the grid is made of squares.
  constexpr double kMaxW = 760.0;
  constexpr double kMaxH = 600.0;
  const double scale = std::min(kMaxW / (x1 - x0), kMaxH / (y1 - y0));
  Panel p;
  p.ax.lo = x0;
  p.ax.hi = x1;
  p.ay.lo = y0;
  p.ay.hi = y1;
  const double step = nice_step(std::max(x1 - x0, y1 - y0) / 7.0);
  p.ax.step = step;
  p.ay.step = step;
  // One label style for both axes: choose from the larger magnitude.
  const double both = std::max(magnitude(p.ax), magnitude(p.ay));
  choose_labels(p.ax, both);
  choose_labels(p.ay, both);

  // Legend.
  std::vector<LegendItem> items;
  for (std::size_t i = 0; i < paths; ++i) {
    items.push_back({LegendItem::Swatch::path, ball_colour(i), 2.0,
                     legend_label(scenario.balls[i].id)});
  }
  if (paths < c.n) {
    items.push_back({LegendItem::Swatch::filled, kOtherBalls, 0.0,
                     xml_escape("other " + std::to_string(c.n - paths) + " (end only)")});
  }
  items.push_back({LegendItem::Swatch::hollow, "#333", 0.0, "start"});
  items.push_back({LegendItem::Swatch::filled, "#333", 0.0, "end"});

  const double left = left_margin(p.ay);
  const double top = 64.0;
  p.r = {left, top, (x1 - x0) * scale, (y1 - y0) * scale};
  const double legend_x = p.r.x + p.r.w + 20.0;
  const double width = std::max(legend_x + legend_width(items) + 16.0, 560.0);
  const double height =
      std::max(p.r.y + p.r.h + 56.0, p.r.y + legend_height(items) + 20.0);

  std::string out;
  open_svg(out, width, height);
  std::string sub = time_range(c);
  if (paths < c.n) {
    sub += "; paths of the first " + std::to_string(paths) + " of " +
           std::to_string(c.n) + " balls, every ball's end position";
  } else {
    sub += "; circles at true radius: hollow at start, filled at end";
  }
  titles(out, left, c.model + " model, " + plural(c.n, "ball") + ": trajectories", sub);

  // The playing surface under the grid lines, so they show on it.
  out += "<rect x=\"" + px(p.r.x) + "\" y=\"" + px(p.r.y) + "\" width=\"" +
         px(p.r.w) + "\" height=\"" + px(p.r.h) + "\" fill=\"#fafafa\"/>\n";
  if (!scenario.table.outline.empty()) {
    out += "<polygon fill=\"#e3f1e3\" points=\"";
    for (std::size_t k = 0; k < scenario.table.outline.size(); ++k) {
      const Vec2 v = scenario.table.outline[k];
      out += (k == 0 ? "" : " ") + px(p.X(v.x)) + "," + px(p.Y(v.y));
    }
    out += "\"/>\n";
  }
  draw_axes(out, p, p.ax.title("x", "m"), p.ay.title("y", "m"), true);
  if (!scenario.table.outline.empty()) {
    out += "<polygon fill=\"none\" stroke=\"#2f5d2f\" stroke-width=\"2\" "
           "stroke-linejoin=\"round\" points=\"";
    for (std::size_t k = 0; k < scenario.table.outline.size(); ++k) {
      const Vec2 v = scenario.table.outline[k];
      out += (k == 0 ? "" : " ") + px(p.X(v.x)) + "," + px(p.Y(v.y));
    }
    out += "\"/>\n";
  }

  // The snooker table's markings: the baulk line, the D and the six spots.
  if (scenario.table.shape == TableShape::snooker) {
    const SnookerMarks m = snooker_marks();
    const std::string line = "stroke=\"#2f5d2f\" stroke-width=\"1\" fill=\"none\"";
    out += "<line x1=\"" + px(p.X(m.baulk_x)) + "\" y1=\"" + px(p.Y(0.0)) + "\" x2=\"" +
           px(p.X(m.baulk_x)) + "\" y2=\"" + px(p.Y(scenario.table.width)) + "\" " + line + "/>\n";
    const double r = m.d_radius * scale;
    out += "<path d=\"M " + px(p.X(m.d_centre.x)) + " " + px(p.Y(m.d_centre.y - m.d_radius)) +
           " A " + px(r) + " " + px(r) + " 0 0 1 " + px(p.X(m.d_centre.x)) + " " +
           px(p.Y(m.d_centre.y + m.d_radius)) + "\" " + line + "/>\n";
    out += "<g fill=\"#2f5d2f\">\n";
    for (const Vec2 spot : {m.yellow, m.green, m.brown, m.blue, m.pink, m.black}) {
      out += "<circle cx=\"" + px(p.X(spot.x)) + "\" cy=\"" + px(p.Y(spot.y)) + "\" r=\"1.5\"/>\n";
    }
    out += "</g>\n";
  }

  // The carom table's markings: the three spots on the long string, the
  // two starting spots and the diamonds (drawn on the cushion lines).
  if (scenario.table.shape == TableShape::carom) {
    const CaromMarks m = carom_marks();
    out += "<g fill=\"#2f5d2f\">\n";
    for (const Vec2 spot :
         {m.top_spot, m.centre_spot, m.bottom_spot, m.starting_spots[0], m.starting_spots[1]}) {
      out += "<circle cx=\"" + px(p.X(spot.x)) + "\" cy=\"" + px(p.Y(spot.y)) + "\" r=\"1.5\"/>\n";
    }
    for (const Vec2 d : m.diamonds) {
      out += "<circle cx=\"" + px(p.X(d.x)) + "\" cy=\"" + px(p.Y(d.y)) + "\" r=\"2.5\"/>\n";
    }
    out += "</g>\n";
  }

  // A ball smaller than a pixel would vanish; draw it at least this big.
  auto radius_px = [&](std::size_t i) {
    return std::max(scenario.balls[i].radius * scale, 1.0);
  };

  // Balls without a drawn path: end positions only, in grey, under the
  // others.
  if (paths < c.n) {
    out += "<g fill=\"" + std::string(kOtherBalls) +
           "\" stroke=\"#555\" stroke-width=\"0.5\">\n";
    for (std::size_t i = paths; i < c.n && i < last.size(); ++i) {
      out += "<circle cx=\"" + px(p.X(last[i].position.x)) + "\" cy=\"" +
             px(p.Y(last[i].position.y)) + "\" r=\"" + px(radius_px(i)) + "\"/>\n";
    }
    out += "</g>\n";
  }

  for (std::size_t i = 0; i < paths; ++i) {
    std::vector<Pt> pts;
    pts.reserve(frames.size());
    for (const Sample& f : frames) {
      const Vec2 q = state_of(f, i).position;
      pts.push_back({p.X(q.x), p.Y(q.y)});
    }
    polyline(out, simplify_path(std::move(pts)),
             stroke(ball_colour(i), 1.5) + " stroke-opacity=\"0.9\"");
  }
  for (std::size_t i = 0; i < paths && i < first.size(); ++i) {
    out += "<circle cx=\"" + px(p.X(first[i].position.x)) + "\" cy=\"" +
           px(p.Y(first[i].position.y)) + "\" r=\"" + px(radius_px(i)) +
           "\" fill=\"none\" " + stroke(ball_colour(i), 1.5) + "/>\n";
  }
  for (std::size_t i = 0; i < paths && i < last.size(); ++i) {
    out += "<circle cx=\"" + px(p.X(last[i].position.x)) + "\" cy=\"" +
           px(p.Y(last[i].position.y)) + "\" r=\"" + px(radius_px(i)) +
           "\" fill=\"" + ball_colour(i) +
           "\" fill-opacity=\"0.85\" stroke=\"#222\" stroke-width=\"0.8\"/>\n";
  }

  draw_legend(out, legend_x, p.r.y, items);
  close_svg(out);
  return out;
}

// Layout of the time plots: a fixed width; the plot area is what is left
// after the y labels and the legend.
constexpr double kTimeWidth = 1000.0;

std::string energy_svg(const Scenario& scenario, const std::vector<Sample>& frames) {
  const Common c = common(scenario, frames);
  const std::size_t shown = series_count(c.n);

  std::vector<std::vector<double>> e(shown, std::vector<double>(frames.size()));
  std::vector<double> total(frames.size(), 0.0);
  double ball_hi = 0.0;
  double total_hi = 0.0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    for (std::size_t i = 0; i < c.n; ++i) {
      const double ke = kinetic_energy(scenario.balls[i], state_of(frames[k], i));
      total[k] += ke;
      if (i < shown) {
        e[i][k] = ke;
        ball_hi = std::max(ball_hi, ke);
      }
    }
    total_hi = std::max(total_hi, total[k]);
  }

  // With many balls the total dwarfs each ball's share, and on a common
  // axis the balls' curves are squashed into a band at zero (a 1000-disk
  // gas: a 5 J line over 0.005 J noise). Then the total gets a short
  // panel of its own on top and the balls an axis of their own below.
  const bool split = shown > 0 && ball_hi < 0.25 * total_hi;

  // Energies are >= 0, so axes start at 0. All zero (nothing moves): an
  // axis of 1 J, so the flat line at 0 is plainly zero.
  auto axis_for = [](double hi, double ticks) {
    return value_axis(0.0, hi, hi > 0.0 ? 1e-3 * hi : 1.0, true, ticks);
  };
  std::vector<Panel> panels(split ? 2 : 1);
  for (Panel& p : panels) {
    p.ax = time_axis(c.t0, c.t1);
  }
  // The short top panel of a split gets fewer ticks.
  panels[0].ay = axis_for(total_hi, split ? 3.0 : 6.0);
  if (split) {
    panels[1].ay = axis_for(ball_hi, 6.0);
    const double both = std::max(magnitude(panels[0].ay), magnitude(panels[1].ay));
    choose_labels(panels[0].ay, both);
    choose_labels(panels[1].ay, both);
  }

  const std::vector<LegendItem> items = series_legend(scenario, shown);
  double left = 0.0;
  for (const Panel& p : panels) {
    left = std::max(left, left_margin(p.ay));
  }
  const double lw = legend_width(items);
  const double top = 64.0;
  const double plot_w = kTimeWidth - left - lw - 36.0;
  const double gap = 24.0;
  double plot_bottom = top + 420.0;
  if (split) {
    panels[0].r = {left, top, plot_w, 130.0};
    panels[1].r = {left, top + 130.0 + gap, plot_w, 300.0};
    plot_bottom = top + 130.0 + gap + 300.0;
  } else {
    panels[0].r = {left, top, plot_w, 420.0};
  }
  const double height = std::max(plot_bottom + 56.0, top + legend_height(items) + 20.0);

  std::string out;
  open_svg(out, kTimeWidth, height);
  std::string sub = time_range(c) + "; translational + rotational; ";
  sub += split ? (shown < c.n ? "system total (top), the first " +
                                     std::to_string(shown) + " of " +
                                     std::to_string(c.n) + " balls (below)"
                              : std::string("system total (top), each ball (below)"))
               : shown_balls(c.n);
  titles(out, left, c.model + " model, " + plural(c.n, "ball") + ": kinetic energy", sub);
  for (std::size_t a = 0; a < panels.size(); ++a) {
    const Panel& p = panels[a];
    const bool bottom = a + 1 == panels.size();
    const std::string quantity = !split ? "kinetic energy" : a == 0 ? "total" : "per ball";
    draw_axes(out, p, p.ax.title("time", "s"), p.ay.title(quantity, "J"), bottom);
    const std::string id = "plot" + std::to_string(a);
    clip_rect(out, id, p.r);
    out += "<g clip-path=\"url(#" + id + ")\">\n";
    if (!split || a == 1) {
      for (std::size_t i = 0; i < shown; ++i) {
        series(out, p, c.t, e[i], stroke(ball_colour(i), 1.5));
      }
    }
    if (!split || a == 0) {
      series(out, p, c.t, total, stroke("#000", 3.0));
    }
    out += "</g>\n";
  }
  draw_legend(out, left + plot_w + 20.0, top, items);
  close_svg(out);
  return out;
}

std::string momentum_svg(const Scenario& scenario, const std::vector<Sample>& frames) {
  const Common c = common(scenario, frames);
  const std::size_t shown = series_count(c.n);

  // [component][ball] and the totals.
  std::array<std::vector<std::vector<double>>, 2> comp;
  std::array<std::vector<double>, 2> total;
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::array<double, 2> lo = {inf, inf};
  std::array<double, 2> hi = {-inf, -inf};
  double biggest = 0.0;  // largest |p| of any ball or total, either component
  for (std::size_t a = 0; a < 2; ++a) {
    comp[a].assign(shown, std::vector<double>(frames.size()));
    total[a].assign(frames.size(), 0.0);
  }
  for (std::size_t k = 0; k < frames.size(); ++k) {
    for (std::size_t i = 0; i < c.n; ++i) {
      const Vec2 m = momentum(scenario.balls[i], state_of(frames[k], i));
      const std::array<double, 2> v = {m.x, m.y};
      for (std::size_t a = 0; a < 2; ++a) {
        total[a][k] += v[a];
        biggest = std::max(biggest, std::abs(v[a]));
        if (i < shown) {
          comp[a][i][k] = v[a];
          lo[a] = std::min(lo[a], v[a]);
          hi[a] = std::max(hi[a], v[a]);
        }
      }
    }
    for (std::size_t a = 0; a < 2; ++a) {
      lo[a] = std::min(lo[a], total[a][k]);
      hi[a] = std::max(hi[a], total[a][k]);
      biggest = std::max(biggest, std::abs(total[a][k]));
    }
  }

  // Both panels pad a flat range to the same fraction of the largest
  // momentum in the run, so a constant p_y = 0 stays a flat line at 0
  // instead of a magnified picture of rounding noise.
  const double min_span = biggest > 0.0 ? 1e-3 * biggest : 1.0;
  std::array<Panel, 2> panels;
  for (std::size_t a = 0; a < 2; ++a) {
    panels[a].ax = time_axis(c.t0, c.t1);
    panels[a].ay = value_axis(lo[a], hi[a], min_span, false);
  }
  // One label style for both panels, so p_x and p_y read alike.
  const double both = std::max(magnitude(panels[0].ay), magnitude(panels[1].ay));
  choose_labels(panels[0].ay, both);
  choose_labels(panels[1].ay, both);

  const std::vector<LegendItem> items = series_legend(scenario, shown);
  const double left = std::max(left_margin(panels[0].ay), left_margin(panels[1].ay));
  const double lw = legend_width(items);
  const double top = 64.0;
  const double panel_h = 250.0;
  const double gap = 24.0;
  const double plot_w = kTimeWidth - left - lw - 36.0;
  panels[0].r = {left, top, plot_w, panel_h};
  panels[1].r = {left, top + panel_h + gap, plot_w, panel_h};
  const double height = std::max(top + 2.0 * panel_h + gap + 56.0,
                                 top + legend_height(items) + 20.0);

  std::string out;
  open_svg(out, kTimeWidth, height);
  titles(out, left, c.model + " model, " + plural(c.n, "ball") + ": linear momentum",
         time_range(c) + "; " + shown_balls(c.n));
  const std::array<std::string, 2> names = {"x momentum", "y momentum"};
  for (std::size_t a = 0; a < 2; ++a) {
    const Panel& p = panels[a];
    draw_axes(out, p, p.ax.title("time", "s"), p.ay.title(names[a], "kg m/s"), a == 1);
    const std::string id = a == 0 ? "px" : "py";
    clip_rect(out, id, p.r);
    out += "<g clip-path=\"url(#" + id + ")\">\n";
    for (std::size_t i = 0; i < shown; ++i) {
      series(out, p, c.t, comp[a][i], stroke(ball_colour(i), 1.5));
    }
    series(out, p, c.t, total[a], stroke("#000", 3.0));
    out += "</g>\n";
  }
  draw_legend(out, panels[0].r.x + plot_w + 20.0, top, items);
  close_svg(out);
  return out;
}

// The height of each ball's centre above its resting height against
// time (balls that leave the cloth), with the bottom of the ball on the
// rail's nose marked as a dashed line: a ball above it can clear a rail.
std::string height_svg(const Scenario& scenario, const std::vector<Sample>& frames) {
  const Common c = common(scenario, frames);
  const std::size_t shown = series_count(c.n);
  std::vector<std::vector<double>> z(shown, std::vector<double>(frames.size()));
  double hi = 0.0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    for (std::size_t i = 0; i < shown; ++i) {
      z[i][k] = state_of(frames[k], i).z;
      hi = std::max(hi, z[i][k]);
    }
  }
  const CushionParams& cp = scenario.table.cushion;
  const double r = scenario.balls.empty() ? kPoolBallRadius : scenario.balls[0].radius;
  const double nose = cushion_nose_height(cp, r);
  Panel p;
  p.ax = time_axis(c.t0, c.t1);
  p.ay = value_axis(0.0, std::max(hi, nose) * 1.05, 1e-3, true);
  choose_labels(p.ay);
  std::vector<LegendItem> items = series_legend(scenario, shown);
  items.erase(items.begin());  // no total: heights do not add up
  const double left = left_margin(p.ay);
  const double lw = legend_width(items);
  const double top = 64.0;
  const double panel_h = 320.0;
  const double plot_w = kTimeWidth - left - lw - 36.0;
  p.r = {left, top, plot_w, panel_h};
  const double height = std::max(top + panel_h + 56.0, top + legend_height(items) + 20.0);
  std::string out;
  open_svg(out, kTimeWidth, height);
  titles(out, left, c.model + " model, " + plural(c.n, "ball") + ": height above the cloth",
         time_range(c) + "; dashed: the rail's nose (" + general(nose) +
             " m): a ball whose bottom is below it meets a rail");
  draw_axes(out, p, p.ax.title("time", "s"), p.ay.title("height of the centre above rest", "m"),
            true);
  clip_rect(out, "hz", p.r);
  out += "<g clip-path=\"url(#hz)\">\n";
  series(out, p, c.t, std::vector<double>(frames.size(), nose),
         stroke("#888", 1.0) + " stroke-dasharray=\"6 4\"");
  for (std::size_t i = 0; i < shown; ++i) series(out, p, c.t, z[i], stroke(ball_colour(i), 1.5));
  out += "</g>\n";
  draw_legend(out, p.r.x + plot_w + 20.0, top, items);
  close_svg(out);
  return out;
}

// Writes text to path, or throws naming the path.
void write_file(const std::string& path, const std::string& content) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) {
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  }
  const std::size_t written = std::fwrite(content.data(), 1, content.size(), f);
  const bool write_error = std::ferror(f) != 0;
  const bool close_failed = std::fclose(f) != 0;
  if (written != content.size() || write_error || close_failed) {
    throw std::runtime_error("cannot write " + path + ": write failed");
  }
}

}  // namespace

std::vector<std::string> write_plots(const Scenario& scenario,
                                     const std::vector<Sample>& frames,
                                     const std::string& prefix) {
  const std::vector<std::string> paths = {prefix + "-trajectories.svg",
                                          prefix + "-energy.svg",
                                          prefix + "-momentum.svg"};
  write_file(paths[0], trajectories_svg(scenario, frames));
  write_file(paths[1], energy_svg(scenario, frames));
  write_file(paths[2], momentum_svg(scenario, frames));
  // A run in which some ball left the cloth also shows the heights.
  const bool flew = std::any_of(frames.begin(), frames.end(), [](const Sample& f) {
    return std::any_of(f.balls.begin(), f.balls.end(), [](const BallState& b) { return b.z > 0.0; });
  });
  if (!flew) return paths;
  std::vector<std::string> all = paths;
  all.push_back(prefix + "-height.svg");
  write_file(all.back(), height_svg(scenario, frames));
  return all;
}

}  // namespace breakshot
