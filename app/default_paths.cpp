#include "default_paths.hpp"

#include <stdexcept>
#include <vector>

namespace sketchlab::cli {

std::filesystem::path default_experiment() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  std::vector<fs::path> candidates;
  if (!ec) candidates.push_back(exe.parent_path() / "../share/sketchlab/configs/default.yaml");
  candidates.push_back(fs::path(SKETCHLAB_SOURCE_DIR) / "configs/default.yaml");
  for (const auto& c : candidates)
    if (fs::exists(c)) return fs::weakly_canonical(c);
  std::string tried;
  for (const auto& c : candidates) tried += " " + c.string();
  throw std::runtime_error("no default experiment found; tried:" + tried);
}

}  // namespace sketchlab::cli
