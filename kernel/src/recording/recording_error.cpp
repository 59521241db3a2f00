#include <utility>

#include "sketchlab/recording/recording.hpp"

namespace sketchlab {

namespace {
std::string located(const std::string& file, std::size_t line, const std::string& reason) {
  return file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + reason;
}
}  // namespace

RecordingError::RecordingError(std::string file_, std::size_t line_, std::string reason_)
    : std::runtime_error(located(file_, line_, reason_)),
      file(std::move(file_)),
      line(line_),
      reason(std::move(reason_)) {}

}  // namespace sketchlab
