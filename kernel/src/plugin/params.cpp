#include "sketchlab/plugin/params.hpp"

#include <charconv>
#include <cmath>
#include <set>

namespace sketchlab {

namespace {

// Shortest text that reads back to the same double (0.001, not 0.00100000).
std::string format_real(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

std::string_view type_noun(const ParamValue& value) {
  switch (value.index()) {
    case 0: return "a boolean";
    case 1: return "an integer";
    case 2: return "a real";
    default: return "a string";
  }
}

[[noreturn]] void fail(const ParamSpec& spec, const std::string& what) {
  throw ParamError(spec.name, "parameter '" + spec.name + "': " + what +
                                  "; allowed: " + describe_allowed(spec));
}

void check_range(const ParamSpec& spec, double value, const ParamValue& shown) {
  if ((spec.min && value < *spec.min) || (spec.max && value > *spec.max)) {
    fail(spec, format_value(shown) + " is out of range");
  }
}

}  // namespace

std::string_view to_string(ParamType type) {
  switch (type) {
    case ParamType::boolean: return "boolean";
    case ParamType::integer: return "integer";
    case ParamType::real: return "real";
    case ParamType::string: return "string";
    case ParamType::choice: return "choice";
  }
  return "unknown";
}

std::string format_value(const ParamValue& value) {
  switch (value.index()) {
    case 0: return std::get<bool>(value) ? "true" : "false";
    case 1: return std::to_string(std::get<std::int64_t>(value));
    case 2: return format_real(std::get<double>(value));
    default: return "\"" + std::get<std::string>(value) + "\"";
  }
}

std::string describe_allowed(const ParamSpec& spec) {
  std::string text;
  switch (spec.type) {
    case ParamType::boolean: text = "true or false"; break;
    case ParamType::string: text = "any string"; break;
    case ParamType::choice: {
      text = "one of: ";
      for (std::size_t i = 0; i < spec.choices.size(); ++i) {
        if (i > 0) text += ", ";
        text += spec.choices[i];
      }
      break;
    }
    case ParamType::integer:
    case ParamType::real: {
      text = to_string(spec.type);
      if (spec.min && spec.max) {
        text += " in [" + format_real(*spec.min) + ", " + format_real(*spec.max) + "]";
      } else if (spec.min) {
        text += " >= " + format_real(*spec.min);
      } else if (spec.max) {
        text += " <= " + format_real(*spec.max);
      }
      break;
    }
  }
  if (!spec.unit.empty()) text += " (" + spec.unit + ")";
  return text;
}

ParamValue validate_param(const ParamSpec& spec, const ParamValue& value) {
  switch (spec.type) {
    case ParamType::boolean:
      if (!std::holds_alternative<bool>(value)) {
        fail(spec, format_value(value) + " is " + std::string(type_noun(value)));
      }
      return value;
    case ParamType::integer: {
      if (!std::holds_alternative<std::int64_t>(value)) {
        fail(spec, format_value(value) + " is " + std::string(type_noun(value)));
      }
      check_range(spec, static_cast<double>(std::get<std::int64_t>(value)), value);
      return value;
    }
    case ParamType::real: {
      double real = 0.0;
      if (const auto* i = std::get_if<std::int64_t>(&value)) {
        real = static_cast<double>(*i);
      } else if (const auto* d = std::get_if<double>(&value)) {
        real = *d;
      } else {
        fail(spec, format_value(value) + " is " + std::string(type_noun(value)));
      }
      if (!std::isfinite(real)) fail(spec, format_value(real) + " is not a finite number");
      check_range(spec, real, value);
      return real;
    }
    case ParamType::string:
      if (!std::holds_alternative<std::string>(value)) {
        fail(spec, format_value(value) + " is " + std::string(type_noun(value)));
      }
      return value;
    case ParamType::choice: {
      const auto* s = std::get_if<std::string>(&value);
      if (!s) fail(spec, format_value(value) + " is " + std::string(type_noun(value)));
      for (const auto& choice : spec.choices) {
        if (choice == *s) return value;
      }
      fail(spec, format_value(value) + " is not a choice");
    }
  }
  fail(spec, "has an unknown type");
}

Params validate_params(const std::vector<ParamSpec>& specs,
                       const std::map<std::string, ParamValue>& given) {
  std::map<std::string, const ParamSpec*> by_name;
  for (const auto& spec : specs) by_name.emplace(spec.name, &spec);

  // Given names are checked in map (sorted) order so the first error reported
  // does not depend on how the caller built the map.
  for (const auto& [name, value] : given) {
    if (by_name.count(name) == 0) {
      std::string declared;
      for (const auto& spec : specs) declared += (declared.empty() ? "" : ", ") + spec.name;
      throw ParamError(name, "unknown parameter '" + name + "'; " +
                                 (declared.empty() ? std::string("this plugin has no parameters")
                                                   : "declared: " + declared));
    }
  }

  std::map<std::string, ParamValue> values;
  for (const auto& spec : specs) {
    auto it = given.find(spec.name);
    values[spec.name] = validate_param(spec, it != given.end() ? it->second : spec.default_value);
  }
  return Params(std::move(values));
}

const ParamValue& Params::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) {
    throw std::out_of_range("parameter '" + name + "' was not declared by the plugin");
  }
  return it->second;
}

namespace {
template <class T>
const T& typed(const ParamValue& value, const std::string& name, std::string_view wanted) {
  if (const auto* v = std::get_if<T>(&value)) return *v;
  throw std::out_of_range("parameter '" + name + "' is " + std::string(type_noun(value)) +
                          ", not " + std::string(wanted));
}
}  // namespace

bool Params::boolean(const std::string& name) const {
  return typed<bool>(get(name), name, "a boolean");
}
std::int64_t Params::integer(const std::string& name) const {
  return typed<std::int64_t>(get(name), name, "an integer");
}
double Params::real(const std::string& name) const {
  return typed<double>(get(name), name, "a real");
}
const std::string& Params::string(const std::string& name) const {
  return typed<std::string>(get(name), name, "a string");
}

}  // namespace sketchlab
