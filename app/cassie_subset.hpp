#pragma once
// `sketchlab fidelity --cassie-subset`: CASSIE's own constraint decisions
// handed to the corrector (the cassie corrector's `oracle` parameter,
// plugins/correctors/cassie/constraint_oracle.hpp), so that the remaining
// difference is the curve's geometry, not which constraints were chosen.
#include <filesystem>
#include <map>
#include <string>

#include "sketchlab/lab/cassie_import.hpp"

namespace sketchlab::cli {

// The oracle file's text: per logged stroke, its id and the x y z (m) of
// every constraint CASSIE applied (a mirrored twin's log already reflected:
// add_mirrored_twin_logs), one line each, by id.
std::string oracle_text(const std::map<StrokeId, CassieConstraintLog>& logs);

// A file holding `text` in the system's temporary directory, removed with
// the object.
class TemporaryFile {
 public:
  TemporaryFile(const std::string& stem, const std::string& text);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace sketchlab::cli
