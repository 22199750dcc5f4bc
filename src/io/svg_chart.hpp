// A small SVG chart kit for the plots of svg_plot.cpp: numbers as text,
// axes with nice ticks, panels, legends and the decimation of long
// series and paths. Every number goes through std::to_chars with a
// fixed precision, so the same input gives the same bytes. Internal: not
// installed.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace breakshot::svg {

// ---------------------------------------------------------------------------
// Text.

/// Fixed-point text with `decimals` digits; std::to_chars ignores the locale.
std::string fixed(double v, int decimals);
/// Pixel coordinates: a hundredth of a pixel is below what anyone sees.
std::string px(double v);
/// Up to 6 significant digits, shortest form (for times in titles).
std::string general(double v);
std::string xml_escape(std::string_view s);
/// A legend label: escaped, cut at 24 characters (ids are free text).
std::string legend_label(std::string_view id);
/// "10" with a superscript exponent, e.g. 10⁻⁶, in UTF-8.
std::string power_of_ten(int e);
/// "1 ball", "3 balls".
std::string plural(std::size_t n, std::string_view word);

// ---------------------------------------------------------------------------
// Axes.

/// The smallest of 1, 2, 5 x 10^k that is >= raw.
double nice_step(double raw);

struct Axis {
  double lo = 0.0;  ///< range shown
  double hi = 1.0;
  double step = 0.2;  ///< between ticks
  int exp3 = 0;       ///< tick labels count units of 10^exp3
  int decimals = 1;   ///< of the tick labels

  std::vector<double> ticks() const {
    std::vector<double> out;
    // Ticks are integer multiples of the step, so 0 is exactly 0 and
    // labels do not pick up rounding from repeated addition.
    const auto first = static_cast<long long>(std::ceil(lo / step - 1e-9));
    const auto last = static_cast<long long>(std::floor(hi / step + 1e-9));
    for (long long k = first; k <= last && k - first < 200; ++k) {
      out.push_back(static_cast<double>(k) * step);
    }
    return out;
  }

  std::string label(double v) const { return fixed(v / std::pow(10.0, exp3), decimals); }

  /// "kinetic energy (J)" or, with an exponent, "kinetic energy (10⁻⁶ J)".
  std::string title(std::string_view quantity, std::string_view unit) const {
    std::string s(quantity);
    s += " (";
    if (exp3 != 0) {
      s += power_of_ten(exp3);
      s += " ";
    }
    s += unit;
    s += ")";
    return s;
  }

  /// Widest tick label, in characters.
  std::size_t label_chars() const {
    std::size_t n = 1;
    for (double t : ticks()) {
      n = std::max(n, label(t).size());
    }
    return n;
  }
};

/// Chooses how tick labels are written. Plain decimals while the values
/// read well that way (0.001 to 9999); beyond that a common engineering
/// exponent (a multiple of 3) moves into the axis title, so one axis
/// never mixes 0.0005 and 5e-4 styles. `magnitude` is the largest |value|
/// the labels must cover; panels that are read together pass the same.
void choose_labels(Axis& a, double magnitude);
double magnitude(const Axis& a);
void choose_labels(Axis& a);

/// An axis for values in [lo, hi] (with 0 in it if nonnegative, for
/// energies). A range narrower than min_span (constant or nearly constant
/// data) is first padded to min_span around its middle, so a flat line
/// sits mid-axis instead of magnifying rounding noise. Then 4 % margins
/// on both sides keep the extreme values off the frame. The ends are not
/// rounded out to whole ticks: that would waste up to half the height.
Axis value_axis(double lo, double hi, double min_span, bool nonnegative, double target_ticks = 6.0);

/// The time axis spans exactly the run (not widened to whole ticks).
Axis time_axis(double t0, double t1);

// ---------------------------------------------------------------------------
// Drawing.

struct Rect {
  double x = 0.0;
  double y = 0.0;
  double w = 1.0;
  double h = 1.0;
};

// A plot area and the axes that map data into it.
struct Panel {
  Rect r;
  Axis ax;
  Axis ay;
  double X(double v) const { return r.x + (v - ax.lo) / (ax.hi - ax.lo) * r.w; }
  double Y(double v) const { return r.y + r.h - (v - ay.lo) / (ay.hi - ay.lo) * r.h; }
};

// Legend entries.
struct LegendItem {
  enum class Swatch { line, path, hollow, filled, none };
  Swatch swatch = Swatch::line;
  std::string colour;
  double width = 1.5;  // line width
  std::string label;   // escaped
};

struct Pt {
  double x = 0.0;
  double y = 0.0;
};

void open_svg(std::string& out, double w, double h);
void close_svg(std::string& out);
/// A text element at (x, y); `escaped` is already XML-escaped.
void text(std::string& out, double x, double y, std::string_view escaped,
          std::string_view attrs = {});
/// The title and subtitle above a plot.
void titles(std::string& out, double x, const std::string& title, const std::string& subtitle);
/// Frame, grid, ticks and axis titles of a panel. Tick labels on the x
/// axis only if x_labels (stacked panels share the bottom one's).
void draw_axes(std::string& out, const Panel& p, const std::string& x_title,
               const std::string& y_title, bool x_labels, bool grid = true);
/// Room to the left of a panel for its tick labels and rotated title.
double left_margin(const Axis& ay);
double legend_width(const std::vector<LegendItem>& items);
double legend_height(const std::vector<LegendItem>& items);
/// The legend at (x, y), right of the plot, outside the data area, so it
/// never covers a curve.
void draw_legend(std::string& out, double x, double y, const std::vector<LegendItem>& items);
void clip_rect(std::string& out, const std::string& id, const Rect& r);

// ---------------------------------------------------------------------------
// Lines.

/// A path in pixels, simplified to what can be seen (at most 5000 points).
std::vector<Pt> simplify_path(std::vector<Pt> pts);
void polyline(std::string& out, const std::vector<Pt>& pts, const std::string& attrs);
/// A time series as a polyline in a panel, decimated to its width, then
/// simplified.
void series(std::string& out, const Panel& p, const std::vector<double>& t,
            const std::vector<double>& y, const std::string& attrs);
/// stroke="COLOUR" stroke-width="WIDTH".
std::string stroke(const std::string& colour, double width);

}  // namespace breakshot::svg
