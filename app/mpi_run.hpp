#pragma once
// `sketchlab run` over the ranks of an MPI job (mpirun, srun), with the MPI
// C API (OpenMPI in Debian; compiled in when CMake finds MPI, see
// app/CMakeLists.txt). Rank 0 plans the run (creates the run folder on the
// shared file system, or takes the --resume folder), hands out cases one at
// a time to the ranks that ask for one (dynamic scheduling: a rank asks when
// one of its -j threads is free), gathers each case's record
// (case_result.json) and its final sketch, draws the progress line, and
// writes the MeshLab projects, pictures, report and provenance as a
// single-process run does: --no-timings outputs are byte-identical for any
// number of ranks. Ranks 1..N-1 run the cases and write each case's own
// folder, which no other rank touches. Rank 0 runs no case, so a case that
// crashes its rank cannot take the results with it.
//
// A rank that dies (a crashing case, a lost host) is reported by host and
// rank, and the cases it was running are reported as lost; the others
// finish. That needs the launcher to let the job go on (`mpirun
// --enable-recovery`, `srun -K0 --no-kill`); OpenMPI 4.1 has no failure
// notification (no ULFM), so rank 0 notices a death by the rank's process
// being gone (same host) or by its silence: each rank sends a heartbeat
// every second once it has planned the run, and one silent for `rank_timeout_s`
// (before its first word: at least 120 s) counts as dead. When the
// launcher ends the whole job instead, rank 0 says which run folder to
// --resume.
#include "sketchlab/lab/experiment_runner.hpp"

namespace sketchlab::cli {

class ProgressLine;

// True when this process was started by an MPI launcher (OpenMPI's mpirun,
// srun with PMIx or PMI-2, MPICH's hydra), judged from its environment, so
// that a plain `sketchlab run` never initialises MPI (mpi_launcher.cpp,
// also in builds without MPI; the rest of this header needs MPI).
bool launched_by_mpi();

struct MpiRunOptions {
  double rank_timeout_s = 60.0;
};

// Initialises MPI (funnelled: only the calling thread uses it), runs the
// experiment over the job's ranks and finalises MPI. With one rank, the run
// is the single-process one. `options.jobs` 0 picks, per rank, the cores it
// may use (its CPU affinity, shared among the ranks on its host). On rank 0
// returns the summary and sets `lost` to "rank R on HOST: why" for each rank
// that died or could not run; elsewhere returns nothing. Errors before the
// cases start (bad config on rank 0) are thrown on rank 0; other ranks then
// return nothing.
std::optional<RunSummary> run_over_mpi(const ExperimentConfig& config, const PluginHost& host,
                                       RunOptions options, const MpiRunOptions& mpi,
                                       ProgressLine& progress, std::vector<std::string>& lost);

// On rank 0, once the summary is printed: when ranks were lost, MPI_Finalize
// would wait for them forever (and a rank declared dead for its silence may
// still be hung), so the job ends with MPI_Abort and `exit_code`. Otherwise
// does nothing. (OpenMPI 4.1's `mpirun --enable-recovery` exits 0 even
// then: the LOST and FAILED lines and metrics.csv's ok column tell.)
void end_mpi_job(const std::vector<std::string>& lost, int exit_code);

}  // namespace sketchlab::cli
