#include <algorithm>
#include <stdexcept>

#include "config_internal.hpp"

namespace sketchlab::config_detail {

namespace fs = std::filesystem;

bool glob_match(std::string_view pattern, std::string_view name) {
  if (!name.empty() && name[0] == '.' && (pattern.empty() || pattern[0] != '.')) return false;
  // Iterative matcher with one backtrack point (the last '*'): linear in
  // practice, no recursion blow-up on patterns like "*a*a*a*b".
  std::size_t p = 0, n = 0, star = std::string_view::npos, resume = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::vector<fs::path> expand_pattern(const std::string& pattern, const fs::path& base) {
  if (pattern.empty()) throw std::runtime_error("empty recording name");
  const fs::path full = (fs::path(pattern).is_absolute() ? fs::path(pattern) : base / pattern)
                            .lexically_normal();
  const fs::path dir = full.parent_path();
  const std::string leaf = full.filename().string();
  if (dir.string().find_first_of("*?") != std::string::npos) {
    throw std::runtime_error("'" + pattern +
                             "': wildcards are allowed only in the file name, not in directories");
  }
  if (leaf.empty()) throw std::runtime_error("'" + pattern + "' names a directory, not a file");

  std::vector<fs::path> files;
  std::error_code ec;
  if (leaf.find_first_of("*?") == std::string::npos) {
    if (!fs::is_regular_file(full, ec)) {
      throw std::runtime_error("recording '" + pattern + "' does not exist (looked for " +
                               full.string() + ")");
    }
    files.push_back(full);
    return files;
  }
  if (fs::is_directory(dir, ec)) {
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      if (it->is_regular_file(ec) && glob_match(leaf, it->path().filename().string())) {
        files.push_back(it->path().lexically_normal());
      }
    }
  }
  if (files.empty()) {
    throw std::runtime_error("'" + pattern + "' matches no file (looked in " + dir.string() + ")");
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace sketchlab::config_detail
