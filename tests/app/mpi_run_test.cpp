// `mpirun -n N sketchlab run`: the cases spread over the ranks give the
// single-process run's files byte for byte; a case that crashes its rank is
// reported with the rank and its host while the others finish; a job ended
// by a dying rank is finished by --resume. Built with MPI only.
#include <catch2/catch.hpp>

#ifdef SKETCHLAB_MPIEXEC
#include <filesystem>
#include <fstream>
#include <regex>

#include "cli_helpers.hpp"
#include "run_sweeps.hpp"
#include "sketchlab/io/text_file.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;

namespace {

// CI and this machine run as root, which mpirun refuses without these; the
// timeout keeps a hung job from hanging the suite.
std::string mpirun(int ranks, const std::string& flags = "") {
  std::string env = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ";
#ifdef SKETCHLAB_SANITIZED
  // Debian's OpenMPI 4.1.4 leaves ~90 kB per process at MPI_Finalize (a
  // ten-line MPI_Init/MPI_Finalize program under ASan shows it), mostly from
  // its MCA components, which it dlcloses before exit: LeakSanitizer reports
  // them as "<unknown module>", which no suppression can name. The ranks are
  // checked for memory errors and UB, not leaks (the single-process runs of
  // the same cases are).
  env += "LSAN_OPTIONS=detect_leaks=0 ";
#endif
  return env + "timeout 300 " + std::string(SKETCHLAB_MPIEXEC) + " --oversubscribe -n " + std::to_string(ranks) +
         " " + flags + " ";
}

test::CliRun run_in(const fs::path& dir, const std::string& command) {
  fs::create_directories(dir);
  return test::run_captured("cd " + dir.string() + " && " + command);
}

// The crash sweep (run_sweeps.hpp) in <base>/run under `ranks` ranks with
// --enable-recovery (the job goes on when a rank dies: mpi_run.hpp), the
// fixture corrector set to `crash` (SKETCHLAB_FIXTURE_CRASH), -j 1.
test::CliRun run_crash_sweep(const fs::path& base, int ranks, const std::string& crash, const std::string& args) {
  test::write_crash_sweep(base);
  return run_in(base / "run", "SKETCHLAB_PLUGIN_PATH=" + test::crash_plugin_dir() + " " +
                                  mpirun(ranks, "--enable-recovery -x SKETCHLAB_PLUGIN_PATH -x SKETCHLAB_FIXTURE_CRASH=" +
                                                    crash) +
                                  SKETCHLAB_CLI + " run --no-timings -j 1 " + args + " ../sweep.yaml");
}

}  // namespace

TEST_CASE("mpirun -n 1, 2, 3 writes the single-process run's bytes", "[app][mpi]") {
  const fs::path base = test::fresh_dir("mpi_identical");
  test::write_sweep(base);
  const std::string run = std::string(SKETCHLAB_CLI) + " run --no-timings ../sweep.yaml";
  const auto single = run_in(base / "single", run + " -j 2");
  INFO(single.output);
  REQUIRE(single.status == 0);
  for (int n : {1, 2, 3}) {
    const fs::path dir = base / ("n" + std::to_string(n));
    const auto ranked = run_in(dir, mpirun(n) + run);
    INFO(n << " ranks: " << ranked.output);
    REQUIRE(ranked.status == 0);
    CHECK(test::finished_cases(dir / "runs/sweep") == 8);
    CHECK(test::differing_files(base / "single/runs/sweep", dir / "runs/sweep").empty());
  }
}

TEST_CASE("a case that crashes its rank is reported with the rank's name and the other cases finish", "[app][mpi]") {
  const fs::path base = test::fresh_dir("mpi_crash");
  const auto r = run_crash_sweep(base, 3, "1", "");
  INFO(r.output);
  // (mpirun --enable-recovery of OpenMPI 4.1 exits 0 whatever its ranks do:
  // the run's own report is what tells.)
  // Each crashing case takes its rank down: two cases, two worker ranks, so
  // the second may find no rank left (then its and the remaining cases are
  // reported as not run); the cases run before finish either way.
  CHECK(std::regex_search(r.output, std::regex("rank [12] on [^ :]+: died")));
  CHECK(std::regex_search(r.output, std::regex("LOST rank [12] on [^ :]+: died")));
  CHECK(std::regex_search(r.output, std::regex("chair x crash: lost: rank [12] on [^ ]+ died")));
  const fs::path run = base / "run/runs/sweep";
  const std::string csv = read_text_file(run / "metrics.csv");
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 9);  // header + 8 cases
  for (const char* c : {"chair/free@fit_error=0.25", "chair/free@fit_error=0.5"}) {
    INFO(c);
    CHECK(fs::exists(run / c / "case_result.json"));
    CHECK(fs::exists(run / c / "sketch.json"));
  }
  CHECK_FALSE(fs::exists(run / "chair/crash/case_result.json"));
  CHECK(fs::exists(run / "report.html"));
}

TEST_CASE("a rank alive but silent past --rank-timeout is reported and its job still ends", "[app][mpi]") {
  const fs::path base = test::fresh_dir("mpi_silent");
  // The crashing case stops its rank (SIGSTOP): its process is there, so
  // only its silence tells; the job must still end (no hang on it).
  const auto r = run_crash_sweep(base, 2, "stop", "--rank-timeout 5");
  INFO(r.output);
  CHECK(std::regex_search(r.output, std::regex("LOST rank 1 on [^ :]+: died \\(silent for 5 s\\)")));
  CHECK(r.output.find("chair x crash: lost: rank 1") != std::string::npos);
  const fs::path run = base / "run/runs/sweep";
  CHECK(test::finished_cases(run) == 2);
  CHECK(fs::exists(run / "metrics.csv"));
}

TEST_CASE("a job ended by a dying rank is finished by --resume under mpirun, byte for byte", "[app][mpi][resume]") {
  const fs::path base = test::fresh_dir("mpi_resume");
  test::write_crash_sweep(base);
  const std::string env = "SKETCHLAB_PLUGIN_PATH=" + test::crash_plugin_dir() + " ";
  const std::string run = std::string(SKETCHLAB_CLI) + " run --no-timings ";
  const auto whole = run_in(base / "reference", env + run + "../sweep.yaml");
  REQUIRE(whole.status == 0);

  // Without --enable-recovery mpirun ends the job when the crashing case
  // kills its rank: rank 0 says what to resume (before the job ends or, when
  // it notices the death first, in its report of the lost cases).
  const auto ended = run_in(base / "resumed", env + mpirun(2, "-x SKETCHLAB_PLUGIN_PATH -x SKETCHLAB_FIXTURE_CRASH=1") +
                                                  run + "-j 1 ../sweep.yaml");
  INFO(ended.output);
  CHECK(ended.status != 0);
  CHECK(ended.output.find("sketchlab run --resume runs/sweep") != std::string::npos);
  const fs::path folder = base / "resumed/runs/sweep";
  CHECK(test::finished_cases(folder) == 2);

  const auto resumed = run_in(base / "resumed", env + mpirun(3, "-x SKETCHLAB_PLUGIN_PATH") + run +
                                                    "--resume runs/sweep ../sweep.yaml");
  INFO(resumed.output);
  REQUIRE(resumed.status == 0);
  CHECK(test::finished_cases(folder) == 8);
  CHECK(test::differing_files(base / "reference/runs/sweep", folder).empty());
}
#endif
