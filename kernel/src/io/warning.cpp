#include "sketchlab/io/warning.hpp"

#include <iostream>
#include <mutex>

namespace sketchlab {

namespace {

std::mutex& sink_mutex() {
  static std::mutex m;
  return m;
}

WarningSink& current_sink() {
  static WarningSink sink;
  return sink;
}

}  // namespace

WarningSink set_warning_sink(WarningSink sink) {
  std::lock_guard lock(sink_mutex());
  WarningSink previous = std::move(current_sink());
  current_sink() = std::move(sink);
  return previous;
}

void warn(const std::string& message) {
  std::lock_guard lock(sink_mutex());
  if (current_sink())
    current_sink()(message);
  else
    std::cerr << "warning: " << message << "\n";
}

}  // namespace sketchlab
