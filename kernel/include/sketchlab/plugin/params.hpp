#pragma once
// Plugin parameters: specs a plugin declares, and validated values.
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace sketchlab {

enum class ParamType { boolean, integer, real, string, choice };
std::string_view to_string(ParamType type);

using ParamValue = std::variant<bool, std::int64_t, double, std::string>;

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::real;
  ParamValue default_value;
  std::optional<double> min, max;    // inclusive; integer and real only
  std::vector<std::string> choices;  // choice only
  std::string unit;                  // "m", "rad", "px", "" ...
  std::string doc;
};

// "real in [0, 1] (m)", "one of: a, b", ... for error messages and listings.
std::string describe_allowed(const ParamSpec& spec);
std::string format_value(const ParamValue& value);

// Values for every declared parameter, already validated against the specs.
class Params {
 public:
  Params() = default;
  explicit Params(std::map<std::string, ParamValue> values) : values_(std::move(values)) {}

  // Typed access; throws std::out_of_range naming the parameter if absent or
  // of another type (a plugin asking for what it did not declare is a bug).
  bool boolean(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;
  double real(const std::string& name) const;
  const std::string& string(const std::string& name) const;  // string or choice

  const std::map<std::string, ParamValue>& values() const { return values_; }

 private:
  const ParamValue& get(const std::string& name) const;
  std::map<std::string, ParamValue> values_;
};

// Checks one value against its spec and returns it normalised (an integer
// given for a real parameter becomes a double). Throws ParamError naming the
// parameter and describe_allowed(spec) on a wrong type, a non-finite real, a
// value out of [min, max] or a choice not in the list.
ParamValue validate_param(const ParamSpec& spec, const ParamValue& value);

// Fills defaults and checks each given value against the specs. Integer values
// are accepted for real parameters. Throws ParamError naming the parameter
// and the allowed values on an unknown name, wrong type or out-of-range value.
Params validate_params(const std::vector<ParamSpec>& specs,
                       const std::map<std::string, ParamValue>& given);

// Converts text given on a command line ("k=v") to the spec's type and
// validates it: boolean "true"/"false" (also 1/0, yes/no, on/off), integer
// (decimal, whole text), real (decimal or exponent form, whole text), string
// and choice as given. Throws ParamError naming the parameter and the
// allowed values when the text does not parse or the value is out of range.
ParamValue parse_param_value(const ParamSpec& spec, const std::string& text);

struct ParamError : std::runtime_error {
  ParamError(std::string parameter_name, const std::string& message)
      : std::runtime_error(message), parameter(std::move(parameter_name)) {}
  std::string parameter;
};

}  // namespace sketchlab
