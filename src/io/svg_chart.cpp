// The SVG chart kit (svg_chart.hpp): text, axes, panels, legends and
// the decimation of long series and paths, for the plots of svg_plot.cpp.

#include "io/svg_chart.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace breakshot::svg {
namespace {

// Points per path after simplification.
constexpr std::size_t kMaxPathPoints = 5000;
// Legend labels longer than this are cut (ids are free text).
constexpr std::size_t kMaxLabelChars = 24;

// Typography. Widths of text are estimated, not measured: 0.62 em per
// character is about right for digits in DejaVu Sans and Helvetica.
constexpr double kFont = 13.0;
constexpr double kTickFont = 12.0;
constexpr double kTitleFont = 16.0;
constexpr double kCharWidth = 0.62 * kTickFont;
constexpr double kLegendRow = 19.0;

}  // namespace

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

namespace {

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

}  // namespace

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
                double target_ticks) {
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
          std::string_view attrs) {
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
               const std::string& y_title, bool x_labels, bool grid) {
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

namespace {

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

}  // namespace

namespace {

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

}  // namespace

namespace {

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

}  // namespace

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

}  // namespace breakshot::svg
