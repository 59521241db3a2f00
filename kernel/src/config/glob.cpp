#include <glob.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "config_internal.hpp"

namespace sketchlab::config_detail {

namespace fs = std::filesystem;

// glob(3) (POSIX): *, ? and [...] in any component, file names starting with
// '.' only when the pattern says so; its own sort is locale-dependent, ours
// is by path.
std::vector<fs::path> expand_pattern(const std::string& pattern, const fs::path& base) {
  if (pattern.empty()) throw std::runtime_error("empty recording name");
  const fs::path full = (fs::path(pattern).is_absolute() ? fs::path(pattern) : base / pattern)
                            .lexically_normal();
  if (full.filename().empty()) throw std::runtime_error("'" + pattern + "' names a directory, not a file");

  std::vector<fs::path> files;
  std::error_code ec;
  if (full.string().find_first_of("*?[") == std::string::npos) {
    if (!fs::is_regular_file(full, ec)) {
      throw std::runtime_error("recording '" + pattern + "' does not exist (looked for " +
                               full.string() + ")");
    }
    files.push_back(full);
    return files;
  }
  glob_t g{};
  const std::unique_ptr<glob_t, void (*)(glob_t*)> owner(&g, globfree);
  const int rc = glob(full.c_str(), GLOB_NOSORT, nullptr, &g);
  if (rc == GLOB_NOSPACE) throw std::runtime_error("'" + pattern + "': out of memory expanding it");
  if (rc == 0)
    for (std::size_t i = 0; i < g.gl_pathc; ++i)
      if (fs::is_regular_file(g.gl_pathv[i], ec)) files.push_back(fs::path(g.gl_pathv[i]).lexically_normal());
  if (files.empty()) {
    throw std::runtime_error("'" + pattern + "' matches no file (looked in " + full.parent_path().string() + ")");
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace sketchlab::config_detail
