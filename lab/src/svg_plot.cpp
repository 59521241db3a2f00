#include "sketchlab/lab/svg_plot.hpp"
#include "html_escape.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sketchlab/lab/metric_glossary.hpp"

namespace sketchlab {
namespace {

std::string coord(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

// Colour-blind-safe qualitative palette (Okabe & Ito 2008) and a marker
// shape per series, so series differ also in print without colour.
const char* const colours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000"};

std::string marker(int shape, double x, double y, const char* colour) {
  std::ostringstream o;
  const std::string cx = coord(x), cy = coord(y);
  switch (shape % 3) {
    case 0: o << "<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"3.5\" fill=\"" << colour << "\"/>"; break;
    case 1: o << "<rect x=\"" << coord(x - 3.2) << "\" y=\"" << coord(y - 3.2) << "\" width=\"6.4\" height=\"6.4\" fill=\"" << colour << "\"/>"; break;
    default: o << "<path d=\"M" << coord(x) << " " << coord(y - 4) << "L" << coord(x + 4) << " " << coord(y + 3)
               << "L" << coord(x - 4) << " " << coord(y + 3) << "Z\" fill=\"" << colour << "\"/>";
  }
  return o.str();
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!(hi > lo)) return {lo};
  const double raw = (hi - lo) / std::max(target, 1);
  const double exponent = std::floor(std::log10(raw));
  const double mag = std::pow(10.0, exponent);
  double m = 10.0;
  for (double c : {1.0, 2.0, 5.0})
    if (c * mag >= raw) { m = c; break; }
  // Tick k is k·m·10^e, computed as k·m / 10^-e below 1 so that 0.6 is 0.6
  // (6 / 10), not 6 × 0.1.
  const double inverse = exponent < 0 ? std::pow(10.0, -exponent) : 0.0;
  const auto tick = [&](double k) { return inverse > 0 ? k * m / inverse : k * m * mag; };
  const double step = m * mag;
  std::vector<double> ticks;
  for (double k = std::ceil(lo / step - 1e-9); tick(k) <= hi + 1e-9 * step; ++k) ticks.push_back(tick(k) == 0.0 ? 0.0 : tick(k));
  return ticks;
}

std::vector<std::pair<double, double>> empirical_cdf(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
               values.end());
  std::sort(values.begin(), values.end());
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i < values.size(); ++i) out.emplace_back(values[i], double(i + 1) / double(values.size()));
  return out;
}

std::string svg_plot(const std::vector<PlotSeries>& input, const PlotOptions& o) {
  const double W = o.width, H = o.height, L = 70, R = 180, T = 30, B = 50;
  std::vector<PlotSeries> series = input;
  for (auto& s : series)
    s.points.erase(std::remove_if(s.points.begin(), s.points.end(),
                                  [&](const auto& p) {
                                    return !std::isfinite(p.first) || !std::isfinite(p.second) ||
                                           (o.log_x && p.first <= 0.0);
                                  }),
                   s.points.end());
  const auto fx = [&](double x) { return o.log_x ? std::log10(x) : x; };
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const auto& s : series)
    for (const auto& [x, y] : s.points) {
      x0 = std::min(x0, fx(x)), x1 = std::max(x1, fx(x));
      y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  if (!std::isfinite(x0)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (!o.log_x && x0 > 0 && x0 < 0.25 * x1) x0 = 0;  // near zero: show it
  if (y0 > 0 && y0 < 0.5 * y1) y0 = 0;
  if (!(x1 > x0)) x0 -= 0.5, x1 += 0.5;
  if (!(y1 > y0)) y0 -= 0.5, y1 += 0.5;
  // Ticks round the range outwards (log axis: decades, or 1-2-5 inside one).
  std::vector<double> xt;
  if (o.log_x) {
    const double d0 = std::floor(x0), d1 = std::ceil(x1);
    for (double d = d0; d <= d1; ++d) xt.push_back(d);
    if (xt.size() < 3) {
      xt.clear();
      for (double d = d0; d <= d1; ++d)
        for (double m : {1.0, 2.0, 5.0}) xt.push_back(d + std::log10(m));
      while (xt.size() > 1 && xt.back() > d1) xt.pop_back();
    }
  } else {
    xt = nice_ticks(x0, x1);
  }
  std::vector<double> yt = nice_ticks(y0, y1);
  x0 = std::min(x0, xt.front()), x1 = std::max(x1, xt.back());
  y0 = std::min(y0, yt.front()), y1 = std::max(y1, yt.back());
  const auto px = [&](double x) { return L + (fx(x) - x0) / (x1 - x0) * (W - L - R); };
  const auto pxt = [&](double t) { return L + (t - x0) / (x1 - x0) * (W - L - R); };
  const auto py = [&](double y) { return H - B - (y - y0) / (y1 - y0) * (H - T - B); };

  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << W << " " << H << "\" width=\"" << W
    << "\" height=\"" << H << "\" class=\"plot\" font-family=\"sans-serif\" font-size=\"12\">\n"
    << "<title>" << html_escape(o.title) << "</title>\n"
    << "<text x=\"" << (L + W - R) / 2 << "\" y=\"18\" text-anchor=\"middle\" font-size=\"14\" font-weight=\"bold\">"
    << html_escape(o.title) << "</text>\n";
  for (double t : xt) {
    const double x = pxt(t);
    s << "<line x1=\"" << coord(x) << "\" y1=\"" << T << "\" x2=\"" << coord(x) << "\" y2=\"" << H - B
      << "\" stroke=\"#e4e4e4\"/><text x=\"" << coord(x) << "\" y=\"" << H - B + 16
      << "\" text-anchor=\"middle\">" << format_displayed(o.log_x ? std::pow(10.0, t) : t) << "</text>\n";
  }
  for (double t : yt) {
    const double y = py(t);
    s << "<line x1=\"" << L << "\" y1=\"" << coord(y) << "\" x2=\"" << W - R << "\" y2=\"" << coord(y)
      << "\" stroke=\"#e4e4e4\"/><text x=\"" << L - 6 << "\" y=\"" << coord(y + 4)
      << "\" text-anchor=\"end\">" << format_displayed(t) << "</text>\n";
  }
  s << "<rect x=\"" << L << "\" y=\"" << T << "\" width=\"" << W - L - R << "\" height=\"" << H - T - B
    << "\" fill=\"none\" stroke=\"#333\"/>\n"
    << "<text x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 12 << "\" text-anchor=\"middle\">" << html_escape(o.x_label)
    << (o.log_x ? " (log scale)" : "") << "</text>\n"
    << "<text x=\"16\" y=\"" << (T + H - B) / 2 << "\" transform=\"rotate(-90 16 " << (T + H - B) / 2
    << ")\" text-anchor=\"middle\">" << html_escape(o.y_label) << "</text>\n";
  for (std::size_t i = 0; i < series.size(); ++i) {
    const char* colour = colours[i % 7];
    const auto& pts = series[i].points;
    s << "<g class=\"series\"><polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.8\" points=\"";
    for (std::size_t k = 0; k < pts.size(); ++k) {
      if (o.steps && k > 0) s << coord(px(pts[k].first)) << "," << coord(py(pts[k - 1].second)) << " ";
      s << coord(px(pts[k].first)) << "," << coord(py(pts[k].second)) << " ";
    }
    s << "\"/>";
    // Markers on every point up to 60 of them; beyond, they would hide the line.
    if (o.markers && pts.size() <= 60)
      for (const auto& [x, y] : pts) s << marker(int(i), px(x), py(y), colour);
    const double ly = T + 8 + 18 * double(i);
    s << "<line x1=\"" << W - R + 12 << "\" y1=\"" << ly << "\" x2=\"" << W - R + 32 << "\" y2=\"" << ly
      << "\" stroke=\"" << colour << "\" stroke-width=\"1.8\"/>" << marker(int(i), W - R + 22, ly, colour)
      << "<text x=\"" << W - R + 38 << "\" y=\"" << ly + 4 << "\">" << html_escape(series[i].name) << "</text></g>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace sketchlab
