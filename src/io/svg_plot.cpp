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

namespace breakshot {
namespace {

// ---------------------------------------------------------------------------
// Limits that keep the files readable and small.

// The trajectory plot draws the paths of this many balls at most; beyond
// that a plot is a scribble, and a 1000-disk gas would be megabytes.
constexpr std::size_t kMaxPaths = 20;
// Points per path after simplification.
constexpr std::size_t kMaxPathPoints = 5000;
// The time plots show every ball up to kMaxSeriesAll balls, otherwise
// the first kMaxSeriesSome (and always the total).
constexpr std::size_t kMaxSeriesAll = 12;
constexpr std::size_t kMaxSeriesSome = 10;
// Legend labels longer than this are cut (ids are free text).
constexpr std::size_t kMaxLabelChars = 24;

// Typography. Widths of text are estimated, not measured: 0.62 em per
// character is about right for digits in DejaVu Sans and Helvetica.
constexpr double kFont = 13.0;
constexpr double kTickFont = 12.0;
constexpr double kTitleFont = 16.0;
constexpr double kCharWidth = 0.62 * kTickFont;
constexpr double kLegendRow = 19.0;

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
// Text.

// Fixed-point text; std::to_chars ignores the locale.
std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) {
    return "0";
  }
  std::array<char, 400> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v,
                               std::chars_format::fixed, decimals);
  if (r.ec != std::errc{}) {
    return "0";
  }
  std::string s(buf.data(), r.ptr);
  // A tiny negative rounded to zero prints as "-0.00", which reads as a
  // sign error on a tick label.
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) {
    s.erase(0, 1);
  }
  return s;
}

// Pixel coordinates: a hundredth of a pixel is below what anyone sees.
std::string px(double v) { return fixed(v, 2); }

// Up to 6 significant digits, shortest form (for times in titles).
std::string general(double v) {
  std::array<char, 64> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v,
                               std::chars_format::general, 6);
  return r.ec == std::errc{} ? std::string(buf.data(), r.ptr) : "?";
}

std::string xml_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // Control characters are not allowed in XML 1.0 at all.
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\t') {
          out += c;
        } else {
          out += '?';
        }
    }
  }
  return out;
}

// Number of characters a person sees (UTF-8 continuation bytes do not
// count), for width estimates.
std::size_t visible_chars(std::string_view s) {
  std::size_t n = 0;
  for (char c : s) {
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
      ++n;
    }
  }
  return n;
}

// A legend label: escaped, cut at kMaxLabelChars characters.
std::string legend_label(std::string_view id) {
  std::string cut;
  std::size_t chars = 0;
  for (std::size_t i = 0; i < id.size(); ++i) {
    const bool starts_char = (static_cast<unsigned char>(id[i]) & 0xC0) != 0x80;
    if (starts_char && ++chars > kMaxLabelChars) {
      cut += "\u2026";
      break;
    }
    cut += id[i];
  }
  return xml_escape(cut);
}

// "10" with a superscript exponent, e.g. 10⁻⁶, in UTF-8.
std::string power_of_ten(int e) {
  static constexpr std::array<const char*, 10> kSup = {
      "\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
      "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string s = "10";
  if (e < 0) {
    s += "\u207b";
  }
  for (char d : std::to_string(std::abs(e))) {
    s += kSup[static_cast<std::size_t>(d - '0')];
  }
  return s;
}

std::string plural(std::size_t n, std::string_view word) {
  return std::to_string(n) + " " + std::string(word) + (n == 1 ? "" : "s");
}

// ---------------------------------------------------------------------------
// Axes.

// The smallest of 1, 2, 5 x 10^k that is >= raw.
double nice_step(double raw) {
  if (!(raw > 0.0) || !std::isfinite(raw)) {
    return 1.0;
  }
  const double base = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / base;
  // The tolerance keeps 0.2 (whose log10 rounds below -0.699) a 2.
  constexpr double tol = 1e-9;
  if (f <= 1.0 + tol) return base;
  if (f <= 2.0 + tol) return 2.0 * base;
  if (f <= 5.0 + tol) return 5.0 * base;
  return 10.0 * base;
}

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

  std::string label(double v) const {
    return fixed(v / std::pow(10.0, exp3), decimals);
  }

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

// Chooses how tick labels are written. Plain decimals while the values
// read well that way (0.001 to 9999); beyond that a common engineering
// exponent (a multiple of 3) moves into the axis title, so one axis
// never mixes 0.0005 and 5e-4 styles. `magnitude` is the largest |value|
// the labels must cover; panels that are read together pass the same.
void choose_labels(Axis& a, double magnitude) {
  a.exp3 = 0;
  if (magnitude > 0.0 && std::isfinite(magnitude) &&
      (magnitude < 1e-3 || magnitude >= 1e4)) {
    a.exp3 = 3 * static_cast<int>(std::floor(std::log10(magnitude) / 3.0));
  }
  const double scaled = a.step / std::pow(10.0, a.exp3);
  const int d = -static_cast<int>(std::floor(std::log10(scaled) + 1e-9));
  a.decimals = std::clamp(d, 0, 12);
}

double magnitude(const Axis& a) { return std::max(std::abs(a.lo), std::abs(a.hi)); }

void choose_labels(Axis& a) { choose_labels(a, magnitude(a)); }

// An axis for values in [lo, hi] (with 0 in it if nonnegative, for
// energies). A range narrower than min_span (constant or nearly constant
// data) is first padded to min_span around its middle, so a flat line
// sits mid-axis instead of magnifying rounding noise. Then 4 % margins
// on both sides keep the extreme values, drawn with thick lines, off the
// frame (and a zero energy off the bottom edge). The ends are not
// rounded out to whole ticks: that would waste up to half the height.
Axis value_axis(double lo, double hi, double min_span, bool nonnegative,
                double target_ticks = 6.0) {
  if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) {
    lo = 0.0;  // no data
    hi = 0.0;
  }
  if (nonnegative) {
    lo = std::min(lo, 0.0);
  }
  if (hi - lo < min_span) {
    const double mid = 0.5 * (lo + hi);
    lo = mid - 0.5 * min_span;
    hi = mid + 0.5 * min_span;
    if (nonnegative && lo < 0.0 && mid >= 0.0) {
      hi -= lo;  // keep the padded axis starting at 0
      lo = 0.0;
    }
  }
  const double margin = 0.04 * (hi - lo);
  Axis a;
  a.lo = lo - margin;
  a.hi = hi + margin;
  a.step = nice_step((a.hi - a.lo) / target_ticks);
  choose_labels(a);
  return a;
}

// The time axis spans exactly the run (not widened to whole ticks).
Axis time_axis(double t0, double t1) {
  if (!std::isfinite(t0) || !std::isfinite(t1)) {
    t0 = 0.0;
    t1 = 1.0;
  }
  if (!(t1 > t0)) {
    t1 = t0 + 1.0;  // a single frame: show one second
  }
  Axis a;
  a.lo = t0;
  a.hi = t1;
  a.step = nice_step((t1 - t0) / 8.0);
  choose_labels(a);
  return a;
}

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

void open_svg(std::string& out, double w, double h) {
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(w) +
         "\" height=\"" + px(h) + "\" viewBox=\"0 0 " + px(w) + " " + px(h) +
         "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"" +
         px(kFont) + "\">\n";
  out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

void close_svg(std::string& out) { out += "</svg>\n"; }

void text(std::string& out, double x, double y, std::string_view escaped,
          std::string_view attrs = {}) {
  out += "<text x=\"" + px(x) + "\" y=\"" + px(y) + "\"";
  if (!attrs.empty()) {
    out += " ";
    out += attrs;
  }
  out += ">";
  out += escaped;
  out += "</text>\n";
}

void titles(std::string& out, double x, const std::string& title,
            const std::string& subtitle) {
  text(out, x, 26.0, xml_escape(title),
       "font-size=\"" + px(kTitleFont) + "\" font-weight=\"bold\"");
  text(out, x, 46.0, xml_escape(subtitle), "fill=\"#444\"");
}

// Frame, grid, ticks and axis titles of a panel. Tick labels on the x
// axis only if x_labels (stacked panels share the bottom one's).
void draw_axes(std::string& out, const Panel& p, const std::string& x_title,
               const std::string& y_title, bool x_labels, bool grid = true) {
  const Rect& r = p.r;
  const std::string tick_font = "font-size=\"" + px(kTickFont) + "\"";
  if (grid) {
    out += "<g stroke=\"#e4e4e4\" stroke-width=\"1\">\n";
    for (double t : p.ax.ticks()) {
      const std::string x = px(p.X(t));
      out += "<line x1=\"" + x + "\" y1=\"" + px(r.y) + "\" x2=\"" + x +
             "\" y2=\"" + px(r.y + r.h) + "\"/>\n";
    }
    for (double t : p.ay.ticks()) {
      const std::string y = px(p.Y(t));
      out += "<line x1=\"" + px(r.x) + "\" y1=\"" + y + "\" x2=\"" +
             px(r.x + r.w) + "\" y2=\"" + y + "\"/>\n";
    }
    out += "</g>\n";
  }
  out += "<rect x=\"" + px(r.x) + "\" y=\"" + px(r.y) + "\" width=\"" + px(r.w) +
         "\" height=\"" + px(r.h) + "\" fill=\"none\" stroke=\"#666\"/>\n";

  // Tick marks point outwards, so they never hide data.
  out += "<g stroke=\"#666\" stroke-width=\"1\">\n";
  for (double t : p.ax.ticks()) {
    const std::string x = px(p.X(t));
    out += "<line x1=\"" + x + "\" y1=\"" + px(r.y + r.h) + "\" x2=\"" + x +
           "\" y2=\"" + px(r.y + r.h + 5.0) + "\"/>\n";
  }
  for (double t : p.ay.ticks()) {
    const std::string y = px(p.Y(t));
    out += "<line x1=\"" + px(r.x - 5.0) + "\" y1=\"" + y + "\" x2=\"" +
           px(r.x) + "\" y2=\"" + y + "\"/>\n";
  }
  out += "</g>\n";

  if (x_labels) {
    for (double t : p.ax.ticks()) {
      text(out, p.X(t), r.y + r.h + 19.0, p.ax.label(t),
           tick_font + " text-anchor=\"middle\"");
    }
    text(out, r.x + 0.5 * r.w, r.y + r.h + 40.0, xml_escape(x_title),
         "text-anchor=\"middle\"");
  }
  for (double t : p.ay.ticks()) {
    // +4: a baseline offset that centres digits on the tick (rsvg and
    // browsers disagree on dominant-baseline, so I don't use it).
    text(out, r.x - 8.0, p.Y(t) + 4.0, p.ay.label(t),
         tick_font + " text-anchor=\"end\"");
  }
  const double label_w = static_cast<double>(p.ay.label_chars()) * kCharWidth;
  const double yx = r.x - 8.0 - label_w - 12.0;
  const double yy = r.y + 0.5 * r.h;
  text(out, yx, yy, xml_escape(y_title),
       "text-anchor=\"middle\" transform=\"rotate(-90 " + px(yx) + " " + px(yy) +
           ")\"");
}

// Room to the left of a panel for its tick labels and rotated title.
double left_margin(const Axis& ay) {
  return 8.0 + static_cast<double>(ay.label_chars()) * kCharWidth + 12.0 + 22.0;
}

// Legend entries.
struct LegendItem {
  enum class Swatch { line, path, hollow, filled, none };
  Swatch swatch = Swatch::line;
  std::string colour;
  double width = 1.5;  // line width
  std::string label;   // escaped
};

double legend_width(const std::vector<LegendItem>& items) {
  std::size_t chars = 0;
  for (const LegendItem& it : items) {
    chars = std::max(chars, visible_chars(it.label));
  }
  return 12.0 + 26.0 + 8.0 + static_cast<double>(chars) * 0.6 * kFont + 10.0;
}

double legend_height(const std::vector<LegendItem>& items) {
  return 10.0 + kLegendRow * static_cast<double>(items.size());
}

// The legend sits right of the plot, outside the data area, so it never
// covers a curve.
void draw_legend(std::string& out, double x, double y,
                 const std::vector<LegendItem>& items) {
  const double w = legend_width(items);
  const double h = legend_height(items);
  out += "<rect x=\"" + px(x) + "\" y=\"" + px(y) + "\" width=\"" + px(w) +
         "\" height=\"" + px(h) + "\" fill=\"white\" stroke=\"#bbb\"/>\n";
  double row = y + 5.0 + 0.5 * kLegendRow;
  for (const LegendItem& it : items) {
    const double sx = x + 12.0;
    const std::string cy = px(row);
    switch (it.swatch) {
      case LegendItem::Swatch::line:
      case LegendItem::Swatch::path:
        out += "<line x1=\"" + px(sx) + "\" y1=\"" + cy + "\" x2=\"" +
               px(sx + 26.0) + "\" y2=\"" + cy + "\" stroke=\"" + it.colour +
               "\" stroke-width=\"" + px(it.width) + "\"/>\n";
        if (it.swatch == LegendItem::Swatch::path) {
          out += "<circle cx=\"" + px(sx + 26.0) + "\" cy=\"" + cy +
                 "\" r=\"4.5\" fill=\"" + it.colour +
                 "\" stroke=\"#222\" stroke-width=\"0.6\"/>\n";
        }
        break;
      case LegendItem::Swatch::hollow:
        out += "<circle cx=\"" + px(sx + 13.0) + "\" cy=\"" + cy +
               "\" r=\"5\" fill=\"none\" stroke=\"" + it.colour +
               "\" stroke-width=\"1.5\"/>\n";
        break;
      case LegendItem::Swatch::filled:
        out += "<circle cx=\"" + px(sx + 13.0) + "\" cy=\"" + cy +
               "\" r=\"5\" fill=\"" + it.colour +
               "\" stroke=\"#222\" stroke-width=\"0.6\"/>\n";
        break;
      case LegendItem::Swatch::none:
        break;
    }
    text(out, sx + 34.0, row + 4.5, it.label,
         it.swatch == LegendItem::Swatch::none ? "fill=\"#444\" font-style=\"italic\"" : "");
    row += kLegendRow;
  }
}

void clip_rect(std::string& out, const std::string& id, const Rect& r) {
  out += "<clipPath id=\"" + id + "\"><rect x=\"" + px(r.x) + "\" y=\"" +
         px(r.y) + "\" width=\"" + px(r.w) + "\" height=\"" + px(r.h) +
         "\"/></clipPath>\n";
}

// ---------------------------------------------------------------------------
// Decimation.

// Indices of the points of a time series worth drawing: per pixel column
// the first, lowest, highest and last point (the "M4" rule). The polyline
// through them looks the same as the full one at this width, and a
// million-frame trace becomes a few thousand points.
std::vector<std::size_t> m4_indices(const std::vector<double>& t,
                                    const std::vector<double>& y,
                                    const Axis& ax, double width_px) {
  const std::size_t n = t.size();
  const auto columns = static_cast<std::size_t>(std::max(1.0, std::ceil(width_px)));
  std::vector<std::size_t> keep;
  if (n <= 4 * columns) {
    keep.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      keep[i] = i;
    }
    return keep;
  }
  keep.reserve(4 * columns + 4);
  const double span = ax.hi - ax.lo;
  std::size_t i = 0;
  while (i < n) {
    const double c = std::floor((t[i] - ax.lo) / span * static_cast<double>(columns));
    std::size_t lo = i;
    std::size_t hi = i;
    std::size_t j = i + 1;
    while (j < n &&
           std::floor((t[j] - ax.lo) / span * static_cast<double>(columns)) == c) {
      if (y[j] < y[lo]) lo = j;
      if (y[j] > y[hi]) hi = j;
      ++j;
    }
    std::array<std::size_t, 4> four = {i, lo, hi, j - 1};
    std::sort(four.begin(), four.end());
    for (std::size_t k : four) {
      if (keep.empty() || keep.back() != k) {
        keep.push_back(k);
      }
    }
    i = j;
  }
  return keep;
}

struct Pt {
  double x = 0.0;
  double y = 0.0;
};

double segment_distance(Pt p, Pt a, Pt b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double u = 0.0;
  if (len2 > 0.0) {
    u = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0);
  }
  const double ex = p.x - (a.x + u * dx);
  const double ey = p.y - (a.y + u * dy);
  return std::sqrt(ex * ex + ey * ey);
}

// Ramer-Douglas-Peucker with an explicit stack (a path of 10^5 points
// would overflow the call stack in the recursive form).
std::vector<Pt> rdp(const std::vector<Pt>& pts, double tol) {
  const std::size_t n = pts.size();
  if (n < 3) {
    return pts;
  }
  std::vector<char> keep(n, 0);
  keep[0] = 1;
  keep[n - 1] = 1;
  std::vector<std::pair<std::size_t, std::size_t>> stack = {{0, n - 1}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    double worst = -1.0;
    std::size_t at = a;
    for (std::size_t k = a + 1; k < b; ++k) {
      const double d = segment_distance(pts[k], pts[a], pts[b]);
      if (d > worst) {
        worst = d;
        at = k;
      }
    }
    if (worst > tol) {
      keep[at] = 1;
      stack.emplace_back(a, at);
      stack.emplace_back(at, b);
    }
  }
  std::vector<Pt> out;
  for (std::size_t k = 0; k < n; ++k) {
    if (keep[k] != 0) {
      out.push_back(pts[k]);
    }
  }
  return out;
}

// A path in pixels, simplified to what can be seen. Ideal and friction
// paths are straight between events and the trace has a frame at each
// event, so straight runs collapse to their corners and nothing visible
// is lost. Long paths (a gas) are first thinned evenly, which bounds the
// cost of RDP; then the tolerance grows until the path has at most
// kMaxPathPoints points.
std::vector<Pt> simplify_path(std::vector<Pt> pts) {
  constexpr std::size_t kMaxInput = 100000;
  if (pts.size() > kMaxInput) {
    std::vector<Pt> thin;
    thin.reserve(kMaxInput);
    const std::size_t n = pts.size();
    for (std::size_t k = 0; k < kMaxInput; ++k) {
      thin.push_back(pts[k * (n - 1) / (kMaxInput - 1)]);
    }
    pts = std::move(thin);
  }
  double tol = 0.25;  // px
  std::vector<Pt> out = rdp(pts, tol);
  while (out.size() > kMaxPathPoints) {
    tol *= 2.0;
    out = rdp(pts, tol);
  }
  return out;
}

void polyline(std::string& out, const std::vector<Pt>& pts, const std::string& attrs) {
  out += "<polyline fill=\"none\" stroke-linejoin=\"round\" stroke-linecap=\"round\" ";
  out += attrs;
  out += " points=\"";
  bool first = true;
  for (const Pt& p : pts) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      continue;
    }
    if (!first) {
      out += ' ';
    }
    first = false;
    out += px(p.x);
    out += ',';
    out += px(p.y);
  }
  out += "\"/>\n";
}

// A time series as a polyline in a panel, decimated to its width, then
// simplified: energies and momenta of the ideal model are constant
// between events, and dropping the points inside straight runs makes the
// files several times smaller with no visible change.
void series(std::string& out, const Panel& p, const std::vector<double>& t,
            const std::vector<double>& y, const std::string& attrs) {
  std::vector<Pt> pts;
  for (std::size_t k : m4_indices(t, y, p.ax, p.r.w)) {
    pts.push_back({p.X(t[k]), p.Y(y[k])});
  }
  polyline(out, rdp(pts, 0.25), attrs);
}

std::string stroke(const std::string& colour, double width) {
  return "stroke=\"" + colour + "\" stroke-width=\"" + px(width) + "\"";
}

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
  if (scenario.table.shape == "snooker") {
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
  if (scenario.table.shape == "carom") {
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
