// `sketchlab fidelity DIR_OR_RECORDING... --corrector NAME [--param k=v ...]
// [--track cassie] [--csv-dir DIR] [--cassie-logs DIR [--no-patches] [--cassie-subset]]`:
// the teacher-forced comparison (kernel run/teacher_forced.hpp) over many
// sessions at once, summarised per CASSIE system (Freehand / Armature /
// Patch / showcase), for the study sessions together and for all.
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "cassie_subset.hpp"
#include "commands.hpp"
#include "fidelity_causes.hpp"
#include "plugin_arguments.hpp"
#include "reference_patches.hpp"
#include "sketchlab/io/text_file.hpp"
#include "sketchlab/lab/teacher_forced.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/recording/recording_reader.hpp"

namespace sketchlab::cli {
namespace {

namespace fs = std::filesystem;

struct FidelityOptions {
  std::vector<std::string> inputs;
  std::string corrector;
  std::vector<std::string> params;
  std::string track = "cassie";
  std::string csv_dir;
  double snap_tolerance = 1e-4;
  bool causes = false;
  std::string cassie_logs;
  bool no_patches = false;
  bool cassie_subset = false;
  double near = 0.02;
};

// Directories expand to their *.jsonl files (sorted); files are kept as given.
std::vector<fs::path> expand(const std::vector<std::string>& inputs) {
  std::vector<fs::path> out;
  for (const std::string& in : inputs) {
    const fs::path p(in);
    if (fs::is_directory(p)) {
      std::vector<fs::path> found;
      for (const auto& e : fs::directory_iterator(p))
        if (e.is_regular_file() && e.path().extension() == ".jsonl") found.push_back(e.path());
      if (found.empty()) throw std::runtime_error(in + ": directory holds no .jsonl recording");
      std::sort(found.begin(), found.end());
      out.insert(out.end(), found.begin(), found.end());
    } else if (fs::is_regular_file(p)) {
      out.push_back(p);
    } else {
      throw std::runtime_error(in + ": no such recording or directory");
    }
  }
  return out;
}

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// The columns of the table (issue #15), one row per group or session.
const char* const header_row =
    "group,sessions,strokes,compared,errors,snap_agreement_pct,snap_kind_agreement_pct,"
    "snap_recall_pct,snap_precision_pct,endpoint_median_mm,endpoint_p90_mm,mean_deviation_median_mm,"
    "mean_deviation_p90_mm,line_agreement_pct,cpu_p50_ms,cpu_p95_ms,cpu_max_ms,wall_p50_ms,wall_p95_ms,"
    "wall_max_ms,planar_agreement_pct,closed_agreement_pct";

// Agreement with CASSIE's flags (--cassie-logs), empty without any.
std::string agreement(const DecisionCount& c) { return c.strokes() ? fixed(100 * c.agreement(), 1) : ""; }

std::string row(const std::string& name, std::size_t sessions, const TeacherForcedSummary& s,
                const DecisionCounts& d) {
  std::ostringstream o;
  o << name << ',' << sessions << ',' << s.strokes << ',' << s.compared << ',' << s.errors << ','
    << fixed(100 * s.snap_agreement(), 1) << ',' << fixed(100 * s.snap_kind_agreement(), 1) << ','
    << fixed(100 * s.snap_recall(), 1) << ',' << fixed(100 * s.snap_precision(), 1) << ','
    << fixed(1000 * s.endpoint_distance.median, 2) << ',' << fixed(1000 * s.endpoint_distance.p90, 2)
    << ',' << fixed(1000 * s.mean_deviation.median, 2) << ',' << fixed(1000 * s.mean_deviation.p90, 2)
    << ',' << fixed(100 * s.line_agreement(), 1) << ',' << fixed(s.cpu_ms.median, 3) << ','
    << fixed(s.cpu_ms.p95, 3) << ',' << fixed(s.cpu_ms.max, 3) << ',' << fixed(s.latency_ms.median, 3)
    << ',' << fixed(s.latency_ms.p95, 3) << ',' << fixed(s.latency_ms.max, 3) << ',' << agreement(d.planar) << ','
    << agreement(d.closed);
  return o.str();
}

// The stroke whose curve lies farthest from its samples (two-sided), for
// the curve-to-stroke table: a reference curve far off is a quirk of the
// reference (its deviation figures measure that), ours a bug.
struct Farthest {
  double distance = -1.0;  // m
  std::string at;          // "<session> stroke <id>"
  void add(const std::vector<TeacherForcedStroke>& strokes, const std::string& session, bool reference) {
    for (const TeacherForcedStroke& t : strokes) {
      const std::optional<double>& d = reference ? t.reference_stroke_distance : t.output_stroke_distance;
      if (d && *d > distance) distance = *d, at = session + " stroke " + std::to_string(t.stroke);
    }
  }
};

const char* const stroke_distance_header =
    "group,ours_median_mm,ours_p90_mm,ours_max_mm,ours_max_at,reference_median_mm,reference_p90_mm,"
    "reference_max_mm,reference_max_at";

// Median, p90 and max in mm and where the max is (empty, as the agreement
// columns, when nothing was measured: strokes of pixels).
std::string stroke_distance_cells(const Distribution& d, const Farthest& far) {
  if (d.count == 0) return ",,,";
  return fixed(1000 * d.median, 2) + ',' + fixed(1000 * d.p90, 2) + ',' + fixed(1000 * d.max, 2) + ',' + far.at;
}

std::string stroke_distance_row(const std::string& name, const TeacherForcedSummary& s,
                                const std::array<Farthest, 2>& far) {
  return name + ',' + stroke_distance_cells(s.output_stroke_distance, far[0]) + ',' +
         stroke_distance_cells(s.reference_stroke_distance, far[1]);
}

// The CSV rows as an aligned text table.
std::string aligned(const std::vector<std::string>& rows) {
  std::vector<std::vector<std::string>> cells;
  std::vector<std::size_t> width;
  for (const std::string& r : rows) {
    std::vector<std::string> c;
    std::stringstream ss(r);
    for (std::string x; std::getline(ss, x, ',');) c.push_back(x);
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (width.size() <= i) width.push_back(0);
      width[i] = std::max(width[i], c[i].size());
    }
    cells.push_back(std::move(c));
  }
  std::ostringstream o;
  for (const auto& c : cells) {
    for (std::size_t i = 0; i < c.size(); ++i)
      o << (i ? "  " : "") << std::string(i ? width[i] - c[i].size() : 0, ' ') << c[i]
        << std::string(i ? 0 : width[i] - c[i].size(), ' ');
    o << '\n';
  }
  return o.str();
}

}  // namespace

void add_fidelity_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "fidelity",
      "Teacher-forced comparison with a reference track over many sessions: snap agreement, snap "
      "kind, recall/precision, endpoint distance, deviation, line/Bézier agreement and latency per "
      "CASSIE system (Freehand / Armature / Patch / showcase)");
  auto o = std::make_shared<FidelityOptions>();
  cmd->add_option("recordings", o->inputs, "Recordings (.jsonl) or directories of them")->required();
  cmd->add_option("--corrector", o->corrector, "Corrector plugin name")->required();
  cmd->add_option("--param", o->params, "Corrector parameter key=value (repeatable)");
  cmd->add_option("--track", o->track, "Reference track (default cassie)");
  cmd->add_option("--csv-dir", o->csv_dir,
                  "Write <session>.csv (one row per stroke), summary.csv (one row per session "
                  "and per group) and stroke_distance.csv (the curve-to-stroke table, the same rows) into this "
                  "directory");
  cmd->add_option("--snap-tolerance", o->snap_tolerance,
                  "Distance (m) under which an endpoint counts as snapped (default 1e-4)");
  cmd->add_flag("--causes", o->causes,
                "Also break the ends whose snap kind differs down by cause, and every end's distance to "
                "the reference's down by the pair of snap kinds, per group (see app/fidelity_causes.hpp)");
  cmd->add_option("--cassie-logs", o->cassie_logs,
                  "CASSIE's raw_data directory: <session>.json gives the constraints CASSIE applied and "
                  "rejected, for --causes, and its per-stroke flags (planar, closedLoop, onSurface), compared "
                  "with ours in a table per group and the planar/closed agreement columns; CASSIE's patches "
                  "alive at each stroke are rebuilt too (--no-patches: not)");
  cmd->add_flag("--no-patches", o->no_patches,
                "With --cassie-logs: do not rebuild CASSIE's patches (raw_data allCreatedPatches, meshed by the "
                "soapfilm surfacer) for each stroke; without them on-surface projection never acts");
  cmd->add_flag("--cassie-subset", o->cassie_subset,
                "With --cassie-logs: each logged stroke enforces, of the constraints we detect, the one nearest "
                "each target CASSIE applied, within the corrector's oracle_radius (mirrored twins: their twin's "
                "log, reflected), and rejects the rest, no search (the corrector's `oracle` parameter); strokes "
                "without a log are searched as usual")
      ->needs("--cassie-logs");
  cmd->add_option("--near", o->near,
                  "Distance (m) within which a constraint target is an end's, for --causes (default 0.02)");
  cmd->callback([o, &exit_code] {
    const std::vector<fs::path> files = expand(o->inputs);
    PluginHost host;
    load_plugins(host);
    std::map<std::string, ParamValue> params;
    if (const LoadedPlugin* plugin = host.find(PluginKind::corrector, o->corrector))
      params = parse_param_arguments(*plugin, o->params);
    const auto corrector = host.make_corrector(o->corrector, params);
    TeacherForcedOptions opt;
    opt.track = o->track;
    opt.snap_tolerance = o->snap_tolerance;
    if (!o->csv_dir.empty()) {
      std::error_code ec;
      fs::create_directories(o->csv_dir, ec);
      if (ec) throw std::runtime_error("--csv-dir " + o->csv_dir + ": cannot create the directory: " + ec.message());
    }
    std::shared_ptr<Surfacer> surfacer;
    if (!o->cassie_logs.empty() && !o->no_patches) surfacer = reference_patch_surfacer(host, "soapfilm");

    std::map<std::string, std::vector<TeacherForcedStroke>> groups;
    std::map<std::string, std::size_t> group_sessions;
    std::vector<TeacherForcedStroke> study, all;
    std::vector<std::string> session_rows{std::string(header_row)};
    std::vector<std::string> session_distance_rows{std::string(stroke_distance_header)};
    std::map<std::string, std::map<std::string, CauseCount>> causes;
    std::map<std::string, std::size_t> cause_ends;
    std::map<std::string, std::map<std::string, EndDistances>> end_distances;
    std::map<std::string, DecisionCounts> decisions;  // by row name
    std::map<std::string, std::array<Farthest, 2>> farthest;  // by row name: ours, the reference's
    std::size_t unlogged_total = 0;
    for (const fs::path& f : files) {
      const Recording rec = read_recording(f);
      const std::string session = f.stem().string();
      opt.surfacer = surfacer.get();
      opt.patches = surfacer ? cassie_reference_patches(rec, o->cassie_logs, session) : std::vector<ReferencePatch>{};
      std::map<StrokeId, CassieConstraintLog> logs;
      if (!o->cassie_logs.empty()) {
        logs = cassie_constraint_logs(rec, o->cassie_logs, session, "CASSIE's constraint logs");
        add_mirrored_twin_logs(rec, logs);
      }
      std::shared_ptr<Corrector> session_corrector = corrector;
      std::optional<TemporaryFile> oracle;
      std::size_t unlogged = 0;
      if (o->cassie_subset) {
        oracle.emplace(session + "-oracle", oracle_text(logs));
        auto with_oracle = params;
        with_oracle["oracle"] = oracle->path().string();
        try {
          session_corrector = host.make_corrector(o->corrector, with_oracle);
        } catch (const std::exception& e) {
          throw std::runtime_error("--cassie-subset needs a corrector with an `oracle` parameter (cassie): " +
                                   std::string(e.what()));
        }
        for (const Event& e : rec.events)
          if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) unlogged += !logs.count(s->stroke.id);
        unlogged_total += unlogged;
      }
      std::vector<TeacherForcedStroke> strokes;
      std::vector<std::string> warnings;
      try {
        strokes = teacher_forced(rec, *session_corrector, opt, &warnings);
      } catch (const std::invalid_argument& e) {
        throw std::runtime_error(f.string() + ": " + e.what() + " (--track chooses one)");
      }
      const std::string group = fidelity_group(rec.header);
      if (!o->csv_dir.empty()) write_text_file(fs::path(o->csv_dir) / (session + ".csv"), teacher_forced_csv(strokes));
      const bool in_study = group == "Armature" || group == "Patch";
      if (!o->cassie_logs.empty())
        for (const std::string& key : {session, group, std::string(in_study ? "Armature+Patch" : ""), std::string("all")})
          if (!key.empty()) count_decisions(strokes, logs, decisions[key]);
      const TeacherForcedSummary summary = summarize(strokes);
      std::array<Farthest, 2> here;
      for (int k = 0; k < 2; ++k) here[k].add(strokes, session, k == 1);
      session_rows.push_back(row(session + " (" + group + ")", 1, summary, decisions[session]));
      session_distance_rows.push_back(stroke_distance_row(session + " (" + group + ")", summary, here));
      std::cerr << session << ": " << strokes.size() << " strokes";
      if (o->cassie_subset) std::cerr << ", " << unlogged << " without a CASSIE log (searched as usual)";
      if (!opt.patches.empty())
        std::cerr << ", " << opt.patches.size() << " CASSIE patches (" << warnings.size() << " left out)";
      std::cerr << "\n";
      for (const std::string& w : warnings) std::cerr << "warning: " << session << ": " << w << "\n";
      for (const std::string& key : {group, std::string(in_study ? "Armature+Patch" : ""), std::string("all")})
        if (!key.empty())
          for (int k = 0; k < 2; ++k) farthest[key][k].add(strokes, session, k == 1);
      auto& g = groups[group];
      g.insert(g.end(), strokes.begin(), strokes.end());
      ++group_sessions[group];
      if (in_study) study.insert(study.end(), strokes.begin(), strokes.end());
      all.insert(all.end(), strokes.begin(), strokes.end());
      if (o->causes) {
        const std::string cg = in_study ? "Armature+Patch" : group;
        count_causes(strokes, o->cassie_logs.empty() ? nullptr : &logs, o->near, causes[cg]);
        cause_ends[cg] += summary.endpoints;
        add_end_distances(strokes, raw_stroke_ends(rec), end_distances[cg]);
      }
    }
    std::vector<std::string> rows{std::string(header_row)};
    std::vector<std::string> distance_rows{std::string(stroke_distance_header)};
    const auto add_rows = [&](const std::string& name, std::size_t sessions, const std::vector<TeacherForcedStroke>& s) {
      const TeacherForcedSummary sum = summarize(s);
      rows.push_back(row(name, sessions, sum, decisions[name]));
      distance_rows.push_back(stroke_distance_row(name, sum, farthest[name]));
    };
    for (const char* name : {"Freehand", "Armature", "Patch", "showcase"})
      if (groups.count(name)) add_rows(name, group_sessions[name], groups[name]);
    for (const auto& [name, strokes] : groups)
      if (name != "Freehand" && name != "Armature" && name != "Patch" && name != "showcase")
        add_rows(name, group_sessions[name], strokes);
    if (!study.empty()) add_rows("Armature+Patch", group_sessions["Armature"] + group_sessions["Patch"], study);
    add_rows("all", files.size(), all);
    std::cout << "corrector " << o->corrector;
    for (const std::string& p : o->params) std::cout << " " << p;
    if (o->cassie_subset)
      std::cout << " --cassie-subset (" << unlogged_total << " strokes without a CASSIE log, searched as usual)";
    std::cout << "\n" << aligned(rows);
    // CASSIE's Freehand system only fitted its strokes (data/cassie/README.md):
    // its row measures a corrector against plain fits, not against neatening.
    if (groups.count("Freehand") && o->corrector != "freehand")
      std::cout << "(Freehand: CASSIE's Freehand system only fits its strokes; compare those sessions with "
                   "--corrector freehand)\n";
    std::cout << "\ncurve to its stroke's samples, two-sided (Hausdorff), and the stroke where it is largest:\n"
              << aligned(distance_rows);
    for (const auto& [name, counts] : causes)
      std::cout << "\n" << name << ": " << cause_ends[name] << " ends, snap kind differs at:\n"
                << cause_table(counts, cause_ends[name]);
    if (!o->cassie_logs.empty())
      for (const char* name : {"Freehand", "Armature", "Patch", "showcase", "Armature+Patch", "all"})
        if (decisions.count(name) && decisions[name].planar.strokes() + decisions[name].closed.strokes() > 0)
          std::cout << "\n" << name << ": CASSIE's per-stroke flags (raw_data) against our decisions:\n"
                    << decision_table(decisions[name]);
    for (const auto& [name, d] : end_distances)
      std::cout << "\n" << name << ": distance from each of CASSIE's ends to ours, by snap kinds:\n"
                << end_distance_table(d);
    if (!o->csv_dir.empty()) {
      // The session rows (with the header), then the group rows.
      const auto write_csv = [&](const char* name, const std::vector<std::string>& sessions,
                                 const std::vector<std::string>& groups_rows) {
        std::string csv;
        for (const std::string& r : sessions) csv += r + "\n";
        for (std::size_t i = 1; i < groups_rows.size(); ++i) csv += groups_rows[i] + "\n";
        write_text_file(fs::path(o->csv_dir) / name, csv);
      };
      write_csv("summary.csv", session_rows, rows);
      write_csv("stroke_distance.csv", session_distance_rows, distance_rows);
    }
    exit_code = 0;
  });
}

}  // namespace sketchlab::cli
