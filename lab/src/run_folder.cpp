#include "sketchlab/lab/run_folder.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace sketchlab {

std::filesystem::path create_unique_folder(const std::filesystem::path& parent, const std::string& name) {
  std::error_code ec;
  std::filesystem::create_directories(parent, ec);
  if (ec) throw std::runtime_error(parent.string() + ": cannot create the folder: " + ec.message());
  for (int n = 1; n < 100000; ++n) {
    const std::filesystem::path dir = parent / (n == 1 ? name : name + "-" + std::to_string(n));
    // mkdir(2) is atomic: EEXIST means someone else owns that name.
    if (::mkdir(dir.c_str(), 0777) == 0) return dir;
    if (errno != EEXIST)
      throw std::runtime_error(dir.string() + ": cannot create the folder: " + std::strerror(errno));
  }
  throw std::runtime_error((parent / name).string() + ": 100000 folders of that name exist already");
}

}  // namespace sketchlab
