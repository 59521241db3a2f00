// Escaping of text placed in HTML or SVG (text and double-quoted attribute
// values), shared by the report, its plots and its provenance section.
#pragma once

#include <string>

namespace sketchlab {

// Returns s with <, >, & and " replaced by their character references.
std::string html_escape(const std::string& s);

}  // namespace sketchlab
