#include "cassie_subset.hpp"

#include <unistd.h>

#include <cstdio>

#include "sketchlab/io/text_file.hpp"

namespace sketchlab::cli {

std::string oracle_text(const std::map<StrokeId, CassieConstraintLog>& logs) {
  std::string out = "# stroke id, then x y z (m) of each constraint CASSIE applied (raw_data)\n";
  for (const auto& [id, log] : logs) {
    out += std::to_string(id);
    for (const Vec3& p : log.applied) {
      char buf[96];
      std::snprintf(buf, sizeof buf, " %.17g %.17g %.17g", p.x(), p.y(), p.z());
      out += buf;
    }
    out += '\n';
  }
  return out;
}

TemporaryFile::TemporaryFile(const std::string& stem, const std::string& text)
    : path_(std::filesystem::temp_directory_path() /
            ("sketchlab-" + std::to_string(::getpid()) + "-" + stem + ".txt")) {
  write_text_file(path_, text);
}

TemporaryFile::~TemporaryFile() {
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

}  // namespace sketchlab::cli
