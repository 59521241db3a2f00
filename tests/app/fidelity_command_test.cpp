// `sketchlab fidelity`: the teacher-forced comparison over many sessions,
// summarised per CASSIE system, with a CSV per session.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

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
