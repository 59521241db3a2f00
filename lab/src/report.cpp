#include "sketchlab/lab/report.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "sketchlab/io/text_file.hpp"
#include "sketchlab/lab/provenance.hpp"

namespace sketchlab {
namespace fs = std::filesystem;
namespace {

// Shown first in tables and plotted against sweep values, when present.
const std::vector<std::string> headline = {
    "latency_p50_ms", "latency_p95_ms", "curves", "nodes", "patches", "dangling_endpoint_ratio",
    "input_deviation_mean_m", "ref_cassie_endpoint_mean_m", "ref_cassie_snap_agreement",
    "gt_distance_mean_m", "gt_distance_mean_aligned_eye_scale_m", "gt_parallel_recall",
    "gt_perpendicular_recall", "gt_coincident_point_recall"};

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::optional<double> parse_number(const std::string& s) {
  double v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

std::vector<std::string> metric_names(const std::vector<const CaseResult*>& cases) {
  std::set<std::string> all;
  for (const auto* c : cases)
    for (const auto& [k, v] : c->metrics.values) all.insert(k);
  std::vector<std::string> names;
  for (const auto& h : headline)
    if (all.erase(h)) names.push_back(h);
  names.insert(names.end(), all.begin(), all.end());
  return names;
}

std::vector<std::string> sweep_paths(const ExperimentConfig& config) {
  std::vector<std::string> paths;
  for (const auto& a : config.sweep) {
    std::string p;
    for (const auto& s : a.path) p += (p.empty() ? "" : ".") + s;
    paths.push_back(p);
  }
  return paths;
}

std::string point_value(const CaseResult& c, const std::string& path) {
  for (const auto& [p, v] : c.variant.point)
    if (p == path) return v;
  return "";
}

void write_csv(const RunSummary& s, const ExperimentConfig& config) {
  std::vector<const CaseResult*> all;
  for (const auto& c : s.cases) all.push_back(&c);
  const auto names = metric_names(all);
  const auto paths = sweep_paths(config);
  std::ostringstream out;
  out.precision(17);
  out << "recording,stack";
  for (const auto& p : paths) out << "," << csv_field(p);
  out << ",ok,error,wall_ms";
  for (const auto& n : names) out << "," << n;
  out << "\n";
  for (const auto& c : s.cases) {
    out << csv_field(c.recording.stem().string()) << "," << csv_field(c.variant.stack.name);
    for (const auto& p : paths) out << "," << csv_field(point_value(c, p));
    out << "," << (c.ok ? 1 : 0) << "," << csv_field(c.error) << "," << c.wall_ms;
    for (const auto& n : names) {
      out << ",";
      if (auto it = c.metrics.values.find(n); it != c.metrics.values.end()) out << it->second;
    }
    out << "\n";
  }
  write_text_file(s.run_dir / "metrics.csv", out.str());
}

void write_json(const RunSummary& s) {
  nlohmann::ordered_json cases = nlohmann::ordered_json::array();
  for (const auto& c : s.cases) {
    nlohmann::ordered_json point = nlohmann::ordered_json::object();
    for (const auto& [p, v] : c.variant.point) point[p] = v;
    nlohmann::ordered_json metrics = nlohmann::ordered_json::object();
    for (const auto& [k, v] : c.metrics.values) metrics[k] = v;
    nlohmann::ordered_json relations = nlohmann::ordered_json::object();
    for (const auto& [k, pr] : c.metrics.relations)
      relations[k] = {{"intended", pr.intended}, {"detected", pr.detected}, {"matched", pr.matched}};
    cases.push_back({{"recording", c.recording.stem().string()},
                     {"stack", c.variant.stack.name},
                     {"sweep_point", point},
                     {"ok", c.ok},
                     {"error", c.error},
                     {"dir", fs::relative(c.dir, s.run_dir).string()},
                     {"wall_ms", c.wall_ms},
                     {"metrics", metrics},
                     {"relations", relations}});
  }
  nlohmann::ordered_json root{{"run_dir", s.run_dir.filename().string()}, {"wall_s", s.wall_s}, {"cases", cases}};
  write_text_file(s.run_dir / "metrics.json", root.dump(1) + "\n");
}

std::string recording_section(const RunSummary& s, const fs::path& recording) {
  std::vector<const CaseResult*> cases;
  for (const auto& c : s.cases)
    if (c.recording == recording) cases.push_back(&c);
  const std::string name = recording.stem().string();
  std::ostringstream h;
  h << "<h2>" << html_escape(name) << "</h2>\n";
  if (fs::exists(s.run_dir / name / "side_by_side.png"))
    h << "<img src=\"" << html_escape(name) << "/side_by_side.png\" alt=\"" << html_escape(name)
      << " side by side\" style=\"max-width:100%\">\n";
  if (fs::exists(s.run_dir / name / (name + ".mlp")))
    h << "<p>MeshLab project: <a href=\"" << html_escape(name + "/" + name + ".mlp") << "\">"
      << html_escape(name) << ".mlp</a></p>\n";
  const auto names = metric_names(cases);
  h << "<table><tr><th>stack</th>";
  for (const auto& n : names) h << "<th>" << html_escape(n) << "</th>";
  h << "</tr>\n";
  for (const auto* c : cases) {
    h << "<tr><td>" << html_escape(c->variant.stack.name) << "</td>";
    if (!c->ok) {
      h << "<td colspan=\"" << names.size() << "\" class=\"error\">failed: " << html_escape(c->error) << "</td>";
    } else {
      for (const auto& n : names) {
        auto it = c->metrics.values.find(n);
        h << "<td>" << (it == c->metrics.values.end() ? "" : number(it->second)) << "</td>";
      }
    }
    h << "</tr>\n";
  }
  h << "</table>\n";
  std::vector<PlotSeries> latency;
  for (const auto* c : cases) {
    if (!c->ok || c->stroke_latency_ms.empty()) continue;
    PlotSeries series{c->variant.stack.name, {}};
    for (std::size_t i = 0; i < c->stroke_latency_ms.size(); ++i)
      series.points.emplace_back(double(i), c->stroke_latency_ms[i]);
    latency.push_back(std::move(series));
  }
  if (!latency.empty()) h << svg_line_plot("latency per stroke: " + name, "stroke", "ms", latency);
  return h.str();
}

// Metric against each numeric sweep axis, one series per base stack,
// averaged over recordings.
std::string sweep_section(const RunSummary& s, const ExperimentConfig& config) {
  std::ostringstream h;
  const auto paths = sweep_paths(config);
  for (const auto& path : paths) {
    for (const auto& metric : headline) {
      std::map<std::string, std::map<double, std::pair<double, int>>> acc;  // stack -> x -> (sum, n)
      for (const auto& c : s.cases) {
        const auto x = parse_number(point_value(c, path));
        auto it = c.metrics.values.find(metric);
        if (!c.ok || !x || it == c.metrics.values.end()) continue;
        const std::string base = c.variant.stack.name.substr(0, c.variant.stack.name.find('@'));
        auto& a = acc[base][*x];
        a.first += it->second;
        ++a.second;
      }
      std::vector<PlotSeries> series;
      for (const auto& [stack, xs] : acc) {
        PlotSeries p{stack, {}};
        for (const auto& [x, a] : xs) p.points.emplace_back(x, a.first / a.second);
        if (p.points.size() > 1) series.push_back(std::move(p));
      }
      if (!series.empty()) h << svg_line_plot(metric + " vs " + path, path, metric, series);
    }
  }
  if (h.tellp() > 0) return "<h2>Sweep</h2>\n" + h.str();
  return "";
}

}  // namespace

std::string svg_line_plot(const std::string& title, const std::string& x_label, const std::string& y_label,
                          const std::vector<PlotSeries>& series) {
  static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf"};
  const double W = 640, H = 300, L = 70, R = 160, T = 30, B = 45;
  double x0 = INFINITY, x1 = -INFINITY, y0 = 0, y1 = -INFINITY;
  for (const auto& s : series)
    for (const auto& [x, y] : s.points) {
      x0 = std::min(x0, x), x1 = std::max(x1, x);
      y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  if (!(x1 > x0)) x1 = x0 + 1;
  if (!(y1 > y0)) y1 = y0 + 1;
  const auto px = [&](double x) { return L + (x - x0) / (x1 - x0) * (W - L - R); };
  const auto py = [&](double y) { return H - B - (y - y0) / (y1 - y0) * (H - T - B); };
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
    << "<text x=\"" << W / 2 << "\" y=\"16\" text-anchor=\"middle\" font-size=\"13\">" << html_escape(title) << "</text>\n"
    << "<line x1=\"" << L << "\" y1=\"" << H - B << "\" x2=\"" << W - R << "\" y2=\"" << H - B << "\" stroke=\"black\"/>\n"
    << "<line x1=\"" << L << "\" y1=\"" << T << "\" x2=\"" << L << "\" y2=\"" << H - B << "\" stroke=\"black\"/>\n"
    << "<text x=\"" << L << "\" y=\"" << H - B + 14 << "\" text-anchor=\"middle\">" << number(x0) << "</text>\n"
    << "<text x=\"" << W - R << "\" y=\"" << H - B + 14 << "\" text-anchor=\"middle\">" << number(x1) << "</text>\n"
    << "<text x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 8 << "\" text-anchor=\"middle\">" << html_escape(x_label) << "</text>\n"
    << "<text x=\"" << L - 4 << "\" y=\"" << H - B << "\" text-anchor=\"end\">" << number(y0) << "</text>\n"
    << "<text x=\"" << L - 4 << "\" y=\"" << T + 4 << "\" text-anchor=\"end\">" << number(y1) << "</text>\n"
    << "<text x=\"14\" y=\"" << (T + H - B) / 2 << "\" transform=\"rotate(-90 14 " << (T + H - B) / 2
    << ")\" text-anchor=\"middle\">" << html_escape(y_label) << "</text>\n";
  for (std::size_t i = 0; i < series.size(); ++i) {
    const char* colour = colours[i % 7];
    o << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.5\" points=\"";
    for (const auto& [x, y] : series[i].points) o << number(px(x)) << "," << number(py(y)) << " ";
    o << "\"/>\n<text x=\"" << W - R + 10 << "\" y=\"" << T + 14 * (i + 1) << "\" fill=\"" << colour << "\">"
      << html_escape(series[i].name) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

void write_report(const RunSummary& s, const ExperimentConfig& config) {
  write_csv(s, config);
  write_json(s);
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" << html_escape(config.name)
    << " — sketchlab report</title>\n<style>body{font-family:sans-serif;margin:2em}"
       "table{border-collapse:collapse;font-size:12px}td,th{border:1px solid #ccc;padding:3px 6px;"
       "text-align:right}th{background:#f0f0f0}td:first-child{text-align:left}.error{color:#b00}</style>"
       "</head><body>\n"
    << "<h1>" << html_escape(config.name) << "</h1>\n<p>" << s.cases.size() << " cases, " << s.failed()
    << " failed, " << number(s.wall_s) << " s. Configuration: <a href=\"config.yaml\">config.yaml</a>; "
    << "metrics: <a href=\"metrics.csv\">metrics.csv</a>, <a href=\"metrics.json\">metrics.json</a>.</p>\n";
  for (const auto& rec : config.recordings) h << recording_section(s, rec);
  h << sweep_section(s, config);
  h << provenance_html(s.provenance, s.run_dir);  // provenance.hpp
  h << "</body></html>\n";
  write_text_file(s.run_dir / "report.html", h.str());
}

}  // namespace sketchlab
