// Compiled with or without MPI: a build without it still tells that it was
// started by a launcher (cmd_run.cpp warns).
#include <cstdlib>

#include "mpi_run.hpp"

namespace sketchlab::cli {

bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(v)) return true;
  return false;
}

}  // namespace sketchlab::cli
