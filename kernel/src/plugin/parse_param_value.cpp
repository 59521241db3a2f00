#include <charconv>
#include <cstdint>
#include <system_error>

#include "sketchlab/plugin/params.hpp"

namespace sketchlab {

ParamValue parse_param_value(const ParamSpec& spec, const std::string& text) {
  auto bad = [&](const char* expected) -> ParamError {
    return ParamError(spec.name, "parameter '" + spec.name + "': '" + text + "' is not " +
                                     expected + "; allowed: " + describe_allowed(spec));
  };
  const char* first = text.data();
  const char* last = text.data() + text.size();
  switch (spec.type) {
    case ParamType::boolean:
      if (text == "true" || text == "1" || text == "yes" || text == "on")
        return validate_param(spec, true);
      if (text == "false" || text == "0" || text == "no" || text == "off")
        return validate_param(spec, false);
      throw bad("a boolean");
    case ParamType::integer: {
      std::int64_t value = 0;
      // from_chars rejects a leading '+'; accept it as people write it.
      const char* start = (first != last && *first == '+') ? first + 1 : first;
      const auto [ptr, ec] = std::from_chars(start, last, value);
      if (text.empty() || ec != std::errc() || ptr != last) throw bad("an integer");
      return validate_param(spec, value);
    }
    case ParamType::real: {
      double value = 0.0;
      const char* start = (first != last && *first == '+') ? first + 1 : first;
      const auto [ptr, ec] = std::from_chars(start, last, value);
      if (text.empty() || ec != std::errc() || ptr != last) throw bad("a number");
      return validate_param(spec, value);
    }
    case ParamType::string:
    case ParamType::choice:
      return validate_param(spec, text);
  }
  throw bad("a known parameter type");
}

}  // namespace sketchlab
