#include "sketchlab/lab/utc_timestamp.hpp"

#include <ctime>

namespace sketchlab {
namespace {

std::string utc_now(const char* format) {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, format, &tm);
  return buf;
}

}  // namespace

std::string utc_timestamp() { return utc_now("%Y%m%d-%H%M%S"); }

std::string utc_iso8601() { return utc_now("%Y-%m-%dT%H:%M:%SZ"); }

}  // namespace sketchlab
