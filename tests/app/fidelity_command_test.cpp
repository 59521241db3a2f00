// `sketchlab fidelity`: the teacher-forced comparison over many sessions,
// summarised per CASSIE system, with a CSV per session.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_helpers.hpp"
#include "sketchlab/io/text_file.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;

namespace {

std::size_t lines_of(const fs::path& p) {
  std::ifstream in(p);
  std::size_t n = 0;
  for (std::string l; std::getline(in, l);) ++n;
  return n;
}

// The comma-separated cells of a CSV line (trailing empty cells dropped).
std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> c;
  std::stringstream ss(line);
  for (std::string x; std::getline(ss, x, ',');) c.push_back(x);
  return c;
}

}  // namespace

TEST_CASE("sketchlab fidelity prints the table per system and writes a CSV per session", "[app]") {
  const fs::path dir = test::fresh_dir("fidelity");
  const std::string a = test::source_path("data/recordings/01-2-2.jsonl");  // Patch, 32 strokes
  const std::string b = test::source_path("data/recordings/01-0-1.jsonl");  // Freehand, 56 strokes
  const auto r = test::run_captured(std::string(SKETCHLAB_CLI) + " fidelity " + a + " " + b +
                                    " --corrector cassie --param mirror=plane --csv-dir " + (dir / "csv").string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  for (const char* col : {"snap_agreement_pct", "snap_kind_agreement_pct", "snap_recall_pct", "snap_precision_pct",
                          "endpoint_median_mm", "mean_deviation_median_mm", "line_agreement_pct", "cpu_p95_ms",
                          "wall_max_ms"})
    CHECK(r.output.find(col) != std::string::npos);
  std::istringstream out(r.output);
  bool patch = false, freehand = false, all = false;
  for (std::string line; std::getline(out, line);) {
    patch |= line.rfind("Patch ", 0) == 0 && line.find(" 32 ") != std::string::npos;
    freehand |= line.rfind("Freehand ", 0) == 0 && line.find(" 56 ") != std::string::npos;
    all |= line.rfind("all ", 0) == 0 && line.find(" 88 ") != std::string::npos;
  }
  CHECK(patch);
  CHECK(freehand);
  CHECK(all);
  // The Freehand row under another corrector says how to read those sessions.
  CHECK(r.output.find("compare those sessions with --corrector freehand") != std::string::npos);
  CHECK(lines_of(dir / "csv" / "01-2-2.csv") == 1 + 32);
  CHECK(lines_of(dir / "csv" / "01-0-1.csv") == 1 + 56);
  // summary.csv: the header, the two sessions, the groups and "all".
  const std::string summary = read_text_file(dir / "csv" / "summary.csv");
  CHECK(summary.rfind("group,sessions,strokes", 0) == 0);
  CHECK(summary.find("\n01-2-2 (Patch),1,32,32,0,") != std::string::npos);
  CHECK(summary.find("\nFreehand,1,56,56,0,") != std::string::npos);
  CHECK(summary.find("\nall,2,88,88,0,") != std::string::npos);
}

TEST_CASE("sketchlab fidelity takes directories and names what it cannot read", "[app]") {
  const fs::path dir = test::fresh_dir("fidelity_errors");
  fs::create_directories(dir / "empty");
  const auto none = test::run_captured(std::string(SKETCHLAB_CLI) + " fidelity " + (dir / "missing").string() +
                                       " --corrector cassie");
  CHECK(none.status != 0);
  CHECK(none.output.find((dir / "missing").string() + ": no such recording or directory") != std::string::npos);
  const auto empty = test::run_captured(std::string(SKETCHLAB_CLI) + " fidelity " + (dir / "empty").string() +
                                        " --corrector cassie");
  CHECK(empty.status != 0);
  CHECK(empty.output.find("holds no .jsonl recording") != std::string::npos);
  const auto bad = test::run_captured(std::string(SKETCHLAB_CLI) + " fidelity " +
                                      test::source_path("data/recordings/01-2-2.jsonl") + " --corrector cassie --param lambda=2");
  CHECK(bad.status != 0);
  CHECK(bad.output.find("lambda") != std::string::npos);
}

namespace {

// Ends of the session CSV whose reference and output snap kinds differ.
std::size_t kind_mismatches(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::size_t n = 0;
  while (std::getline(in, line)) {
    const std::vector<std::string> c = cells_of(line);
    if (c.size() < 12 || c[2] != "1") continue;
    n += (c[8] != c[10]) + (c[9] != c[11]);  // reference_snap0/1 vs output_snap0/1
  }
  return n;
}

// The "total" row's end count of the cause table following `title`.
std::size_t cause_total(const std::string& output, const std::string& title) {
  const std::size_t at = output.find(title);
  if (at == std::string::npos) return 0;
  const std::size_t total = output.find("\ntotal", at);
  if (total == std::string::npos) return 0;
  std::istringstream row(output.substr(total + 6));
  std::size_t n = 0;
  row >> n;
  return n;
}

// Compared strokes of the session CSV.
std::size_t compared_strokes(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::size_t n = 0;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string cell;
    for (int i = 0; i < 3; ++i) std::getline(ss, cell, ',');
    n += cell == "1";
  }
  return n;
}

// Sum of the "count" column of the end-distance table following `title`, and
// the row whose group is `group` (empty if none).
std::size_t end_table_count(const std::string& output, const std::string& title, const std::string& group,
                            std::string& row) {
  std::size_t at = output.find(title);
  if (at == std::string::npos) return 0;
  std::istringstream in(output.substr(at));
  std::string line;
  std::getline(in, line);  // title
  std::getline(in, line);  // column names
  std::size_t n = 0;
  while (std::getline(in, line) && !line.empty()) {
    const std::size_t digits = line.find_first_of("0123456789", line.find("  "));
    std::istringstream cells(line.substr(digits));
    std::size_t count = 0;
    cells >> count;
    n += count;
    if (line.rfind(group + "  ", 0) == 0) row = line;
  }
  return n;
}

}  // namespace

TEST_CASE("sketchlab fidelity --causes accounts for every end whose snap kind differs", "[app]") {
  const fs::path dir = test::fresh_dir("fidelity_causes");
  const std::string rec = test::source_path("data/recordings/02-2-2.jsonl");  // Patch, CASSIE logs both lists
  const std::string base = std::string(SKETCHLAB_CLI) + " fidelity " + rec +
                           " --corrector cassie --param mirror=plane --causes --csv-dir " + (dir / "csv").string();
  // Without CASSIE's patches, so that the run without logs corrects the same.
  const auto with_logs =
      test::run_captured(base + " --no-patches --cassie-logs " + test::source_path("data/cassie/raw_data"));
  INFO(with_logs.output);
  REQUIRE(with_logs.status == 0);
  const std::size_t expected = kind_mismatches(dir / "csv" / "02-2-2.csv");
  CHECK(expected > 10);
  CHECK(cause_total(with_logs.output, "Armature+Patch: ") == expected);
  CHECK(with_logs.output.find("we snapped, CASSIE free: CASSIE rejected it") != std::string::npos);
  // Mirrored twins are not in CASSIE's log: they get their twin's, reflected.
  CHECK(with_logs.output.find("(no log of the stroke)") == std::string::npos);
  const auto without = test::run_captured(base);
  REQUIRE(without.status == 0);
  CHECK(cause_total(without.output, "Armature+Patch: ") == expected);
  CHECK(without.output.find("we snapped, CASSIE free: (no log of the stroke)") != std::string::npos);
  // Every end of every compared stroke is in the end-distance table once; an
  // end at the same node in both curves is at distance 0.
  std::string node_row;
  const std::string title = "Armature+Patch: distance from each of CASSIE's ends to ours";
  CHECK(end_table_count(with_logs.output, title, "CASSIE node, we node", node_row) ==
        2 * compared_strokes(dir / "csv" / "02-2-2.csv"));
  CHECK(node_row.find(" 0.00 /   0.00 ") != std::string::npos);
  const auto missing = test::run_captured(base + " --cassie-logs " + (dir / "nowhere").string());
  CHECK(missing.status != 0);
  CHECK(missing.output.find((dir / "nowhere" / "02-2-2.json").string()) != std::string::npos);
}

TEST_CASE("sketchlab fidelity warns of a --cassie-logs folder that is not raw_data and names a --csv-dir it cannot "
          "create",
          "[app]") {
  const fs::path dir = test::fresh_dir("fidelity_wrong_folders");
  const std::string base = std::string(SKETCHLAB_CLI) + " fidelity " +
                           test::source_path("data/recordings/01-2-1.jsonl") + " --corrector cassie --param mirror=plane";
  // sketch_graph/01-2-1.json is JSON too: the run used to go on silently
  // without any log or patch of CASSIE's.
  const auto graphs = test::run_captured(base + " --cassie-logs " + test::source_path("data/cassie/sketch_graph"));
  INFO(graphs.output);
  CHECK(graphs.status == 0);
  CHECK(graphs.output.find("sketch_graph/01-2-1.json: no stroke log (allSketchedStrokes)") != std::string::npos);
  CHECK(graphs.output.find("does --cassie-logs name CASSIE's raw_data folder?") != std::string::npos);
  std::ofstream(dir / "a_file") << "x";
  const auto blocked = test::run_captured(base + " --csv-dir " + (dir / "a_file" / "csv").string());
  INFO(blocked.output);
  CHECK(blocked.status != 0);
  CHECK(blocked.output.find("--csv-dir " + (dir / "a_file" / "csv").string() + ": cannot create the directory") !=
        std::string::npos);
}

TEST_CASE("sketchlab fidelity --cassie-logs compares CASSIE's planar and closed flags with ours", "[app]") {
  const fs::path dir = test::fresh_dir("fidelity_flags");
  const std::string rec = test::source_path("data/recordings/02-2-2.jsonl");  // Patch: planar flags, no closedLoop
  const auto r = test::run_captured(std::string(SKETCHLAB_CLI) + " fidelity " + rec +
                                    " --corrector cassie --param mirror=plane --csv-dir " + (dir / "csv").string() +
                                    " --cassie-logs " + test::source_path("data/cassie/raw_data"));
  INFO(r.output);
  REQUIRE(r.status == 0);
  const std::string summary = read_text_file(dir / "csv" / "summary.csv");
  INFO(summary);
  // New trailing columns; the session row has a planar agreement and no
  // closed one (this export has no closedLoop flag).
  CHECK(summary.rfind("group,sessions,strokes", 0) == 0);
  CHECK(summary.find("wall_max_ms,planar_agreement_pct,closed_agreement_pct\n") != std::string::npos);
  const std::size_t at = summary.find("\n02-2-2 (Patch),");
  REQUIRE(at != std::string::npos);
  std::vector<std::string> cells;
  std::stringstream row(summary.substr(at + 1, summary.find('\n', at + 1) - at - 1) + ",");  // keeps an empty last cell
  for (std::string x; std::getline(row, x, ',');) cells.push_back(x);
  REQUIRE(cells.size() == 22);
  CHECK(cells[21].empty());
  // Measured 90.5 % (88.9 % with planarity_test=snapped).
  CHECK(std::stod(cells[20]) >= 90.0);
  // The table: one row per flag of the export, the cells adding up.
  const std::size_t table = r.output.find("Patch: CASSIE's per-stroke flags (raw_data) against our decisions:");
  REQUIRE(table != std::string::npos);
  std::istringstream in(r.output.substr(r.output.find("planar (Béziers)", table) + std::string("planar (Béziers)").size()));
  std::size_t strokes = 0, both = 0, cassie_only = 0, ours_only = 0, neither = 0;
  in >> strokes >> both >> cassie_only >> ours_only >> neither;
  CHECK(strokes > 50);
  CHECK(both + cassie_only + ours_only + neither == strokes);
  CHECK(r.output.find("closed  ", table) == std::string::npos);
  // CASSIE's patches are rebuilt by default with the logs (soapfilm meshes
  // them): its 89 patches of this session, and strokes we project onto them.
  CHECK(r.output.find("02-2-2: 107 strokes, 89 CASSIE patches (") != std::string::npos);
  std::istringstream on(r.output.substr(r.output.find("on surface ", table) + std::string("on surface").size()));
  std::size_t on_strokes = 0, on_both = 0, on_cassie = 0, on_ours = 0;
  on >> on_strokes >> on_both >> on_cassie >> on_ours;
  CHECK(on_both + on_ours > 0);
  CHECK(r.output.find("planar in both (" + std::to_string(both) + "): control points to our plane", table) !=
        std::string::npos);
  // Without logs the columns are empty.
  const auto plain = test::run_captured(std::string(SKETCHLAB_CLI) + " fidelity " + rec +
                                        " --corrector cassie --param mirror=plane --csv-dir " + (dir / "plain").string());
  REQUIRE(plain.status == 0);
  CHECK(read_text_file(dir / "plain" / "summary.csv").find("\n02-2-2 (Patch),") != std::string::npos);
  CHECK(plain.output.find("per-stroke flags") == std::string::npos);
}

namespace {

// The session CSV without its timing columns (latency_ms, cpu_ms).
std::string untimed(const fs::path& csv) {
  std::ifstream in(csv);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> c;
    std::stringstream ss(line + ",");
    for (std::string x; std::getline(ss, x, ',');) c.push_back(x);
    for (std::size_t i = 0; i < c.size(); ++i)
      if (i != 15 && i != 16) out += c[i] + ",";
    out += "\n";
  }
  return out;
}

// Largest subsets_tried of the session CSV.
int max_subsets(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  int n = 0;
  while (std::getline(in, line)) {
    const std::vector<std::string> c = cells_of(line);
    if (c.size() > 14) n = std::max(n, std::stoi(c[14]));
  }
  return n;
}

}  // namespace

TEST_CASE("sketchlab fidelity --cassie-subset enforces CASSIE's own applied constraints", "[app]") {
  const fs::path dir = test::fresh_dir("fidelity_subset");
  const std::string rec = test::source_path("data/recordings/02-2-2.jsonl");  // Patch, 107 strokes, all logged
  const std::string logs = test::source_path("data/cassie/raw_data");
  const std::string base =
      std::string(SKETCHLAB_CLI) + " fidelity " + rec + " --corrector cassie --param mirror=plane --no-patches";
  const auto searched =
      test::run_captured(base + " --cassie-logs " + logs + " --csv-dir " + (dir / "searched").string());
  const auto subset =
      test::run_captured(base + " --cassie-logs " + logs + " --cassie-subset --csv-dir " + (dir / "subset").string());
  INFO(subset.output);
  REQUIRE(searched.status == 0);
  REQUIRE(subset.status == 0);
  CHECK(subset.output.find("02-2-2: 107 strokes, 0 without a CASSIE log (searched as usual)") != std::string::npos);
  CHECK(max_subsets(dir / "searched" / "02-2-2.csv") > 1);
  CHECK(max_subsets(dir / "subset" / "02-2-2.csv") == 1);  // no search: CASSIE's subset, solved once
  // CASSIE's selection removes most of our extra snaps (measured: snap
  // precision 92.1 -> 98.7 %, snap kind differs at 32 -> 25 of 214 ends).
  CHECK(kind_mismatches(dir / "subset" / "02-2-2.csv") < kind_mismatches(dir / "searched" / "02-2-2.csv"));

  // Strokes without a log (here an export with none) are searched as usual, and counted.
  fs::create_directories(dir / "nolog");
  { std::ofstream(dir / "nolog" / "02-2-2.json") << "{}"; }
  const auto unlogged = test::run_captured(base + " --cassie-logs " + (dir / "nolog").string() +
                                           " --cassie-subset --csv-dir " + (dir / "nolog_csv").string());
  REQUIRE(unlogged.status == 0);
  CHECK(unlogged.output.find("107 strokes without a CASSIE log, searched as usual") != std::string::npos);
  CHECK(untimed(dir / "nolog_csv" / "02-2-2.csv") == untimed(dir / "searched" / "02-2-2.csv"));

  const auto no_logs = test::run_captured(base + " --cassie-subset");
  CHECK(no_logs.status != 0);
  CHECK(no_logs.output.find("--cassie-subset requires --cassie-logs") != std::string::npos);
  const auto other = test::run_captured(std::string(SKETCHLAB_CLI) + " fidelity " + rec +
                                        " --corrector freehand --cassie-logs " + logs + " --cassie-subset");
  CHECK(other.status != 0);
  CHECK(other.output.find("--cassie-subset needs a corrector with an `oracle` parameter") != std::string::npos);
}

TEST_CASE("sketchlab fidelity names the stroke whose curve lies farthest from its samples", "[app]") {
  // 02-2-1 stroke 67: CASSIE applied a mirror-plane constraint 0.41 m from
  // the stroke (the plane z = 0.75, the samples at z = 1.17-1.20) and
  // stretched its curve there; ours stays on the samples.
  const fs::path dir = test::fresh_dir("fidelity_stroke_distance");
  const auto r = test::run_captured(std::string(SKETCHLAB_CLI) + " fidelity " +
                                    test::source_path("data/recordings/02-2-1.jsonl") +
                                    " --corrector cassie --param mirror=plane --csv-dir " + dir.string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK(r.output.find("curve to its stroke's samples, two-sided (Hausdorff)") != std::string::npos);
  CHECK(r.output.find("02-2-1 stroke 67") != std::string::npos);
  std::istringstream csv(read_text_file(dir / "02-2-1.csv"));
  std::string line;
  std::getline(csv, line);
  CHECK(line.find(",output_stroke_distance,reference_stroke_distance,error") != std::string::npos);
  bool found = false;
  while (std::getline(csv, line)) {
    const std::vector<std::string> c = cells_of(line);
    REQUIRE(c.size() >= 19);
    if (c[0] != "67") continue;
    found = true;
    CHECK(std::stod(c[17]) < 0.01);  // ours: 4.7 mm
    CHECK(std::stod(c[18]) > 0.4);   // CASSIE's: 414 mm
  }
  CHECK(found);
  // The table as CSV, a row per session and per group.
  const std::string table = read_text_file(dir / "stroke_distance.csv");
  CHECK(table.rfind("group,ours_median_mm,", 0) == 0);
  CHECK(table.find("\n02-2-1 (Patch),") != std::string::npos);
  CHECK(table.find("\nall,") != std::string::npos);
  CHECK(table.find(",02-2-1 stroke 67\n") != std::string::npos);
}

TEST_CASE("sketchlab fidelity measures no curve-to-stroke distance on strokes of pixels", "[app]") {
  // Tablet strokes are pixels of a view: a distance from a 3D curve to them
  // would mix units, so the cells stay empty, in the table as in the CSV.
  const fs::path dir = test::fresh_dir("fidelity_pixels");
  const fs::path rec = dir / "cube_tablet.jsonl";
  REQUIRE(test::run_cli("record --input synthetic --param model=cube --param modality=tablet -o " + rec.string(),
                        dir / "record.txt") == 0);
  const auto r = test::run_captured(std::string(SKETCHLAB_CLI) + " fidelity " + rec.string() +
                                    " --corrector analytic --track ground_truth --csv-dir " + (dir / "csv").string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  std::istringstream out(r.output.substr(r.output.find("curve to its stroke's samples")));
  bool all = false;
  for (std::string line; std::getline(out, line);)
    if (line.rfind("all ", 0) == 0) all = line.find_first_of("0123456789") == std::string::npos;
  CHECK(all);
  std::istringstream csv(read_text_file(dir / "csv" / "cube_tablet.csv"));
  std::string line;
  std::getline(csv, line);
  std::size_t rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    const std::vector<std::string> c = cells_of(line);
    REQUIRE(c.size() >= 17);
    CHECK(c[16].size() > 0);                      // cpu_ms
    CHECK((c.size() < 18 || c[17].empty()));      // output_stroke_distance
    CHECK((c.size() < 19 || c[18].empty()));      // reference_stroke_distance
  }
  CHECK(rows > 0);
}
