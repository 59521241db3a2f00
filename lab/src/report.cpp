#include "sketchlab/lab/report.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <functional>
#include <tuple>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "sketchlab/io/text_file.hpp"
#include "html_escape.hpp"
#include "sketchlab/lab/provenance.hpp"
#include "sketchlab/lab/distribution.hpp"
#include "sketchlab/lab/metric_glossary.hpp"
#include "sketchlab/lab/svg_plot.hpp"
#include "sketchlab/plugin/plugin_host.hpp"

namespace sketchlab {

std::string report_web_bundle();  // lab/report_web/dist, compiled in (cmake/EmbedText.cmake)

namespace fs = std::filesystem;
namespace {

const char* const report_web_script = "report_web/sketchlab_report.js";

// Shown first in tables and plotted against sweep values, when present.
const std::vector<std::string> headline = {
    "latency_p50_ms", "latency_p95_ms", "curves", "nodes", "patches", "dangling_endpoint_ratio",
    "input_deviation_mean_m", "ref_cassie_endpoint_mean_m", "ref_cassie_snap_agreement",
    "gt_distance_mean_m", "gt_distance_mean_aligned_eye_scale_m", "gt_shape_distance_mean_m",
    "gt_shape_coverage_mean_m", "gt_parallel_recall",
    "gt_perpendicular_recall", "gt_coincident_point_recall"};

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


// ----- HTML presentation -------------------------------------------------

// Metric names present in `cases`, in glossary order (group rank, then name).
std::vector<std::string> displayed_metrics(const std::vector<const CaseResult*>& cases) {
  std::set<std::string> all;
  for (const auto* c : cases)
    if (c->ok)
      for (const auto& [k, v] : c->metrics.values) all.insert(k);
  std::vector<std::string> names(all.begin(), all.end());
  std::stable_sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
    const MetricInfo ia = metric_info(a), ib = metric_info(b);
    // Group by hundreds of rank, then by group name (one per reference
    // track), then by rank within the group.
    return std::make_tuple(ia.rank / 100, std::cref(ia.group), ia.rank) <
           std::make_tuple(ib.rank / 100, std::cref(ib.group), ib.rank);
  });
  return names;
}

std::string header_label(const MetricInfo& info) {
  return html_escape(info.label) + (info.unit.empty() ? "" : " <span class=\"unit\">(" + html_escape(info.unit) + ")</span>");
}

// Rows are metrics grouped under a group row (a table that fits the page
// whatever the number of metrics), columns are the stacks; `cell(metric,
// column)` gives the cell's HTML.
std::string metric_table(const std::vector<std::string>& names, const std::vector<std::string>& columns,
                         const std::function<std::string(const std::string&, std::size_t)>& cell,
                         const std::string& caption) {
  std::ostringstream h;
  h << "<table class=\"metrics\"><caption>" << caption << "</caption>\n<thead><tr><th>metric</th>";
  for (const auto& c : columns) h << "<th>" << html_escape(c) << "</th>";
  h << "</tr></thead>\n<tbody>\n";
  std::string group;
  for (const auto& n : names) {
    const MetricInfo info = metric_info(n);
    if (info.group != group) {
      group = info.group;
      h << "<tr class=\"group\"><th colspan=\"" << columns.size() + 1 << "\">" << html_escape(group) << "</th></tr>\n";
    }
    h << "<tr><th title=\"" << html_escape(n) << "\"><a href=\"#metric-" << html_escape(n) << "\">"
      << header_label(info) << "</a></th>";
    for (std::size_t i = 0; i < columns.size(); ++i) h << "<td>" << cell(n, i) << "</td>";
    h << "</tr>\n";
  }
  h << "</tbody></table>\n";
  return h.str();
}

std::string displayed(const std::string& metric, double stored) {
  return format_displayed(stored * metric_info(metric).scale);
}

// Stacks in config order (variants of a sweep each count as a stack).
std::vector<std::string> stack_names(const RunSummary& s) {
  std::vector<std::string> names;
  for (const auto& c : s.cases)
    if (std::find(names.begin(), names.end(), c.variant.stack.name) == names.end())
      names.push_back(c.variant.stack.name);
  return names;
}

// Per stack, across recordings: median [first quartile, third quartile] of
// each metric over the recordings where it is defined, n = that count.
std::string summary_section(const RunSummary& s) {
  const auto stacks = stack_names(s);
  std::vector<const CaseResult*> all;
  for (const auto& c : s.cases) all.push_back(&c);
  const auto names = displayed_metrics(all);
  if (names.empty()) return "";
  std::set<std::string> recordings;
  for (const auto& c : s.cases) recordings.insert(c.recording.stem().string());
  const auto cell = [&](const std::string& metric, std::size_t column) -> std::string {
    std::vector<double> v;
    for (const auto& c : s.cases)
      if (c.ok && c.variant.stack.name == stacks[column])
        if (auto it = c.metrics.values.find(metric); it != c.metrics.values.end()) v.push_back(it->second);
    if (v.empty()) return "";
    const Distribution d = distribution(v);
    if (v.size() == 1) return displayed(metric, d.median) + " <span class=\"n\">n=1</span>";
    return displayed(metric, d.median) + " <span class=\"iqr\">[" + displayed(metric, d.p25) + ", " +
           displayed(metric, d.p75) + "]</span> <span class=\"n\">n=" + std::to_string(v.size()) + "</span>";
  };
  std::ostringstream h;
  h << "<section id=\"summary\"><h2>Summary across recordings</h2>\n"
    << metric_table(names, stacks, cell,
                    "Median [first, third quartile] over the " + std::to_string(recordings.size()) +
                        " recording(s) of each stack; n = recordings where the metric applies and the case ran. "
                        "Units in brackets; definitions in the <a href=\"#glossary\">glossary</a>.")
    << "</section>\n";
  return h.str();
}

// Empirical CDF of the time per corrected stroke (one sample per stroke,
// not per event), one line per stack, over the given cases.
std::string latency_plot(const std::vector<const CaseResult*>& cases, const std::string& title) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<double>> per_stack;
  for (const auto* c : cases) {
    if (!c->ok || c->stroke_latency_ms.empty()) continue;
    if (!per_stack.count(c->variant.stack.name)) order.push_back(c->variant.stack.name);
    auto& v = per_stack[c->variant.stack.name];
    v.insert(v.end(), c->stroke_latency_ms.begin(), c->stroke_latency_ms.end());
  }
  std::vector<PlotSeries> series;
  bool positive = true;
  double lo = INFINITY, hi = 0;
  for (const auto& name : order) {
    const auto& v = per_stack[name];
    for (double x : v) positive = positive && x > 0, lo = std::min(lo, x), hi = std::max(hi, x);
    series.push_back({name + " (" + std::to_string(v.size()) + " strokes)", empirical_cdf(v)});
  }
  if (series.empty()) return "";
  PlotOptions o;
  o.title = title;
  o.x_label = "time per corrected stroke (ms)";
  o.y_label = "fraction of strokes";
  o.steps = true;
  o.markers = false;
  o.log_x = positive && hi > 20 * lo;  // latencies span decades across stacks
  return svg_plot(series, o);
}

std::string latency_section(const RunSummary& s) {
  std::vector<const CaseResult*> all;
  for (const auto& c : s.cases) all.push_back(&c);
  const std::string plot = latency_plot(all, "Latency per stroke, all recordings");
  if (plot.empty()) return "";
  return "<section id=\"latency\"><h2>Latency</h2>\n<figure>" + plot +
         "<figcaption>Empirical distribution of the time per corrected stroke (corrector and surfacer, "
         "one sample per stroke), all recordings pooled: a curve further left is faster; where it "
         "reaches 0.5 is the median.</figcaption></figure></section>\n";
}

// The legend of the side-by-side pictures (the viewer's SceneStyle).
const char* picture_legend =
    "<ul class=\"legend\"><li><span class=\"swatch\" style=\"background:#b8b8b8\"></span>raw stroke</li>"
    "<li><span class=\"swatch\" style=\"background:#4d5466\"></span>scaffold curve</li>"
    "<li><span class=\"swatch\" style=\"background:#0d0d14;height:4px\"></span>shape curve</li>"
    "<li><span class=\"swatch\" style=\"background:#1a1a24\"></span>other curve</li>"
    "<li><span class=\"swatch dot\" style=\"background:#d9541a\"></span>node</li>"
    "<li><span class=\"swatch\" style=\"background:#5994e6;opacity:.5;height:10px\"></span>patch</li></ul>";

std::string recording_section(const RunSummary& s, const fs::path& recording, const std::set<std::string>& scenes_shown) {
  std::vector<const CaseResult*> cases;
  for (const auto& c : s.cases)
    if (c.recording == recording) cases.push_back(&c);
  const std::string name = recording.stem().string();
  std::ostringstream h;
  h << "<section class=\"recording\" id=\"rec-" << html_escape(name) << "\"><h2>" << html_escape(name) << "</h2>\n";
  if (fs::exists(s.run_dir / name / "side_by_side.png"))
    h << "<figure class=\"wide\"><img src=\"" << html_escape(name) << "/side_by_side.png\" alt=\"" << html_escape(name)
      << " side by side\"><figcaption>Final sketches of every stack from one camera. " << picture_legend
      << "Curves are coloured by their deviation from the input stroke where the colour bar is shown; the "
         "scale bar gives the length at the focal point.</figcaption></figure>\n";
  else if (fs::exists(s.run_dir / name / "side_by_side.error.txt"))
    h << "<p class=\"error\">No picture: " << html_escape(read_text_file(s.run_dir / name / "side_by_side.error.txt"))
      << "</p>\n";
  // The 3D views (report_web/): every stack's scene.gltf, linked cameras.
  std::vector<std::pair<std::string, std::string>> scenes;  // (stack, file relative to the run folder)
  for (const auto* c : cases)
    if (c->ok)
      if (const auto key = fs::relative(c->dir / "scene.gltf", s.run_dir).generic_string(); scenes_shown.count(key))
        scenes.emplace_back(c->variant.stack.name, key);
  if (!scenes.empty()) {
    h << "<figure class=\"wide\"><div class=\"scene-row\" data-recording=\"" << html_escape(name) << "\">";
    for (const auto& [stack, file] : scenes)
      h << "<div class=\"scene\" data-scene=\"" << html_escape(file) << "\" data-title=\"" << html_escape(stack)
        << "\"></div>";
    h << "</div><figcaption>Interactive 3D (drag to orbit, wheel to zoom, right-drag to pan; the views "
         "move together). Each view is the case's <code>scene.gltf</code>.</figcaption></figure>\n";
  }
  if (fs::exists(s.run_dir / name / (name + ".mlp")))
    h << "<p>MeshLab project: <a href=\"" << html_escape(name + "/" + name + ".mlp") << "\">"
      << html_escape(name) << ".mlp</a></p>\n";
  std::vector<std::string> columns;
  for (const auto* c : cases) columns.push_back(c->variant.stack.name);
  const auto names = displayed_metrics(cases);
  for (const auto* c : cases)
    if (!c->ok)
      h << "<p class=\"error\">" << html_escape(c->variant.stack.name) << " failed: " << html_escape(c->error) << "</p>\n";
  if (!names.empty())
    h << metric_table(names, columns,
                      [&](const std::string& metric, std::size_t i) -> std::string {
                        if (!cases[i]->ok) return "failed";
                        auto it = cases[i]->metrics.values.find(metric);
                        return it == cases[i]->metrics.values.end() ? "" : displayed(metric, it->second);
                      },
                      "Metrics of " + html_escape(name) + " per stack.");
  const std::string plot = latency_plot(cases, "Latency per stroke: " + name);
  if (!plot.empty()) h << "<figure>" << plot << "</figure>\n";
  h << "</section>\n";
  return h.str();
}

// A sweep axis named as the plugin declares the parameter: "delta (m), the
// cassie corrector's parameter", when the path is
// stacks.<i>.<corrector|surfacer|input>.params.<name> and the plugin is known.
std::string axis_label(const std::string& path, const ExperimentConfig& config, const PluginHost* host) {
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
  if (parts.size() != 5 || parts[0] != "stacks" || parts[3] != "params") return path;
  std::size_t index = 0;
  const auto [end, ec] = std::from_chars(parts[1].data(), parts[1].data() + parts[1].size(), index);
  if (ec != std::errc() || index >= config.stacks.size()) return path;
  const StackConfig& stack = config.stacks[index];
  const PluginChoice* choice = nullptr;
  PluginKind kind = PluginKind::corrector;
  if (parts[2] == "corrector") choice = &stack.corrector;
  else if (parts[2] == "surfacer" && stack.surfacer) choice = &*stack.surfacer, kind = PluginKind::surfacer;
  else if (parts[2] == "input" && stack.input) choice = &*stack.input, kind = PluginKind::input;
  if (!choice) return path;
  std::string label = parts[4];
  if (host)
    if (const LoadedPlugin* plugin = host->find(kind, choice->plugin))
      for (const auto& spec : plugin->descriptor->params)
        if (spec.name == parts[4] && !spec.unit.empty()) label += " (" + spec.unit + ")";
  return label + ", " + choice->plugin + " " + parts[2] + " parameter";
}

// Metric against each numeric sweep axis, one series per base stack,
// averaged over recordings.
std::string sweep_section(const RunSummary& s, const ExperimentConfig& config, const PluginHost* host) {
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
      const MetricInfo info = metric_info(metric);
      std::vector<PlotSeries> series;
      for (const auto& [stack, xs] : acc) {
        PlotSeries p{stack, {}};
        for (const auto& [x, a] : xs) p.points.emplace_back(x, a.first / a.second * info.scale);
        if (p.points.size() > 1) series.push_back(std::move(p));
      }
      if (series.empty()) continue;
      PlotOptions o;
      const std::string x = axis_label(path, config, host);
      o.title = info.group + ": " + info.label;
      o.x_label = x;
      o.y_label = info.label + (info.unit.empty() ? "" : " (" + info.unit + ")") + ", mean over recordings";
      h << "<figure>" << svg_plot(series, o) << "</figure>\n";
    }
  }
  if (h.tellp() > 0) return "<section id=\"sweep\"><h2>Sweep</h2>\n" + h.str() + "</section>\n";
  return "";
}

std::string glossary_section(const RunSummary& s) {
  std::vector<const CaseResult*> all;
  for (const auto& c : s.cases) all.push_back(&c);
  const auto names = displayed_metrics(all);
  if (names.empty()) return "";
  std::ostringstream h;
  h << "<section id=\"glossary\"><h2>Glossary</h2>\n<table class=\"glossary\"><thead><tr><th>group</th>"
       "<th>column</th><th>unit</th><th>name in metrics.csv</th><th>meaning</th></tr></thead><tbody>\n";
  for (const auto& n : names) {
    const MetricInfo info = metric_info(n);
    h << "<tr id=\"metric-" << html_escape(n) << "\"><td>" << html_escape(info.group) << "</td><td>"
      << html_escape(info.label) << "</td><td>" << (info.unit.empty() ? "count" : html_escape(info.unit))
      << "</td><td><code>" << html_escape(n) << "</code></td><td>" << html_escape(info.description) << "</td></tr>\n";
  }
  h << "</tbody></table><p>metrics.csv and metrics.json hold the stored values: lengths in metres, "
       "ratios in [0, 1], times in milliseconds.</p></section>\n";
  return h.str();
}

const char* report_css =
    "body{font-family:system-ui,sans-serif;margin:1.5em auto;max-width:1400px;padding:0 1em;color:#111;line-height:1.4}"
    "h1{margin-bottom:.2em}h2{border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:1.6em}"
    "nav a{margin-right:1em}figure{margin:1em 0}figure.wide img{width:100%;height:auto;border:1px solid #ddd}"
    "figcaption{font-size:14px;color:#333;margin-top:.3em}svg.plot{max-width:100%;height:auto}"
    "table{border-collapse:collapse;font-size:14px;margin:1em 0}caption{text-align:left;font-size:13px;color:#444;"
    "caption-side:bottom;padding-top:.3em}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right;"
    "font-variant-numeric:tabular-nums;white-space:nowrap}thead th{background:#eef;position:sticky;top:0}"
    "tbody th{text-align:left;font-weight:normal}tr.group th{background:#f4f4f4;font-weight:bold;text-align:left}"
    "th a{color:inherit;text-decoration:none}.unit,.n{color:#666;font-size:12px}.iqr{color:#444}"
    "table.glossary td{white-space:normal;text-align:left}.error{color:#b00}"
    "ul.legend{list-style:none;padding:0;margin:.3em 0;display:flex;flex-wrap:wrap;gap:1.2em}"
    ".swatch{display:inline-block;width:22px;height:3px;vertical-align:middle;margin-right:5px}"
    ".swatch.dot{width:9px;height:9px;border-radius:50%}"
    ".scene-row{display:flex;gap:4px;width:100%}.scene{flex:1;min-width:0;height:420px;border:1px solid #ddd;"
    "position:relative}.scene .title{position:absolute;left:8px;top:6px;font-size:14px;pointer-events:none;z-index:1}"
    "@media print{.scene-row{display:none}}";

}  // namespace

void write_report(const RunSummary& s, const ExperimentConfig& config, const PluginHost* host) {
  write_csv(s, config);
  write_json(s);
  // The 3D views: each case's scene.gltf wrapped in a classic script (a page
  // opened from file:// may not fetch() it), and the viewer bundle.
  std::vector<std::string> scene_scripts;
  std::set<std::string> scene_keys;
  for (const auto& c : s.cases) {
    if (!c.ok || !fs::exists(c.dir / "scene.gltf")) continue;
    const std::string key = fs::relative(c.dir / "scene.gltf", s.run_dir).generic_string();
    nlohmann::json gltf;
    try {
      gltf = nlohmann::json::parse(read_text_file(c.dir / "scene.gltf"));
    } catch (const nlohmann::json::exception&) {
      continue;  // not glTF: the case shows no 3D view, its file stays for inspection
    }
    write_text_file(c.dir / "scene.gltf.js", "(window.sketchlabScenes = window.sketchlabScenes || {})[" +
                                                 nlohmann::json(key).dump() + "] = " + gltf.dump() + ";\n");
    scene_scripts.push_back(key + ".js");
    scene_keys.insert(key);
  }
  const bool scenes = !scene_scripts.empty();
  if (scenes) {
    fs::create_directories(s.run_dir / "report_web");
    write_text_file(s.run_dir / report_web_script, report_web_bundle());
  }
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << html_escape(config.name)
    << " — sketchlab report</title>\n<style>" << report_css << "</style></head><body>\n"
    << "<h1>" << html_escape(config.name) << "</h1>\n<p>" << s.cases.size() << " cases, " << s.failed()
    << " failed, " << number(s.wall_s) << " s. Configuration: <a href=\"config.yaml\">config.yaml</a>; "
    << "metrics: <a href=\"metrics.csv\">metrics.csv</a>, <a href=\"metrics.json\">metrics.json</a>.</p>\n";
  const std::string summary = summary_section(s), latency = latency_section(s), sweep = sweep_section(s, config, host),
                    glossary = glossary_section(s);
  h << "<nav>";
  if (!summary.empty()) h << "<a href=\"#summary\">summary</a>";
  if (!latency.empty()) h << "<a href=\"#latency\">latency</a>";
  for (const auto& rec : config.recordings)
    h << "<a href=\"#rec-" << html_escape(rec.stem().string()) << "\">" << html_escape(rec.stem().string()) << "</a>";
  if (!sweep.empty()) h << "<a href=\"#sweep\">sweep</a>";
  if (!glossary.empty()) h << "<a href=\"#glossary\">glossary</a>";
  h << "</nav>\n" << summary << latency;
  h << provenance_html(s.provenance, s.run_dir);  // provenance.hpp
  for (const auto& rec : config.recordings) h << recording_section(s, rec, scene_keys);
  h << sweep << glossary;
  for (const auto& src : scene_scripts) h << "<script src=\"" << html_escape(src) << "\"></script>\n";
  if (scenes) h << "<script src=\"" << report_web_script << "\"></script>\n";
  h << "</body></html>\n";
  write_text_file(s.run_dir / "report.html", h.str());
}

}  // namespace sketchlab
