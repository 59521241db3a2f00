#pragma once
// Warnings: input quirks the kernel skips and goes on with (a recording's
// partial last line, left by an interrupted write) are reported here rather
// than refused, each once, as "file:line: what was skipped". The default sink
// writes "warning: <message>" to stderr; tools and tests may install their
// own. Thread-safe: warn() may be called from any thread, the sink is called
// under a lock.
#include <functional>
#include <string>

namespace sketchlab {

using WarningSink = std::function<void(const std::string& message)>;

// Installs `sink` (an empty function restores the default); returns the
// previous one.
WarningSink set_warning_sink(WarningSink sink);

void warn(const std::string& message);

}  // namespace sketchlab
