#pragma once
// One declaration per plugin parameter: a ParamTable<S> binds each parameter
// (name, type, range or choices, unit, doc with its citation) to the field of
// a settings struct S that holds it, and yields both the ParamSpec list a
// PluginDescriptor publishes and the reader that fills an S from validated
// Params. The default is the field's value in the struct the table was made
// with, so spec and struct cannot disagree.
//
//   const ParamTable<MySettings>& table() {
//     static const auto t = ParamTable<MySettings>()
//         .real("delta", &MySettings::delta, 0.001, 0.5, "m", "snap distance δ (§6.1)")
//         .integer("rounds", &MySettings::rounds, 0, 50, "", "smoothing rounds (§4.5)")
//         .choice("mode", &MySettings::mode, {{"fit", Mode::fit}, {"snap", Mode::snap}}, "...");
//     return t;
//   }
//   describe():     corrector_descriptor<C>("name", "1.0", "summary", table().specs())
//   constructor:    settings_ = table().read(params);
//
// A field is a member pointer or a callable returning a reference to the
// field inside an S (a vector component, a nested struct's member). Reals may
// be shown in another unit than they are stored in (`scale`: stored = shown
// × scale, e.g. degrees shown, radians stored; or any RealConversion). `check` adds a step run on the
// filled struct after every field is read (normalise a direction, reject a
// zero vector); it throws std::invalid_argument naming the parameters.
//
// Errors: bad values never reach read(): validate_params(table.specs(), …)
// (the plugin host does it) throws ParamError naming the parameter and
// describe_allowed(). read() of Params not validated against these specs
// throws std::out_of_range naming the parameter (a host bug).
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "sketchlab/plugin/params.hpp"

namespace sketchlab {

// The field `inner` of the member struct `outer` of S, as a table field
// (ParamTable<S>().real("delta", nested_field(&S::preprocess, &PreprocessParams::delta), ...)).
template <class S, class M, class T>
auto nested_field(M S::*outer, T M::*inner) {
  return [outer, inner](S& s) -> T& { return (s.*outer).*inner; };
}

// How a real parameter is shown (spec default, configs) and stored (field).
struct RealConversion {
  std::function<double(double)> to_shown;   // stored -> shown
  std::function<double(double)> to_stored;  // shown -> stored
};

template <class S>
class ParamTable {
 public:
  // The type of the field `Field` refers to in an S.
  template <class Field>
  using FieldType = std::remove_cvref_t<std::invoke_result_t<const Field&, S&>>;

  explicit ParamTable(S defaults = S{}) : defaults_(std::move(defaults)) {}

  template <class Field>
  ParamTable& real(std::string name, Field field, std::optional<double> min,
                   std::optional<double> max, std::string unit, std::string doc,
                   double scale = 1.0) {
    // x / 1 and x * 1 are exact: an unscaled field is shown and read as is.
    return real(std::move(name), field, min, max, std::move(unit), std::move(doc),
                RealConversion{[scale](double stored) { return stored / scale; },
                               [scale](double shown) { return shown * scale; }});
  }

  // A real shown in one unit and stored in another by a conversion that is
  // not a plain scale (a rounded display, a formula kept bit for bit).
  template <class Field>
  ParamTable& real(std::string name, Field field, std::optional<double> min,
                   std::optional<double> max, std::string unit, std::string doc,
                   RealConversion conversion) {
    S d = defaults_;
    const double shown = conversion.to_shown(ref<double>(field, d));
    add({std::move(name), ParamType::real, shown, min, max, {}, std::move(unit), std::move(doc)},
        [field, to_stored = std::move(conversion.to_stored)](S& s, const Params& p,
                                                             const std::string& n) {
          ref<double>(field, s) = to_stored(p.real(n));
        });
    return *this;
  }

  // Any integral field (int, std::int64_t, std::uint64_t, std::size_t...);
  // [min, max] must fit the field's type.
  template <class Field>
  ParamTable& integer(std::string name, Field field, std::optional<double> min,
                      std::optional<double> max, std::string unit, std::string doc) {
    S d = defaults_;
    auto& value = std::invoke(field, d);
    using I = std::remove_reference_t<decltype(value)>;
    static_assert(std::is_integral_v<I> && !std::is_same_v<I, bool>, "integer() binds an integral field");
    add({std::move(name), ParamType::integer, static_cast<std::int64_t>(value), min, max, {},
         std::move(unit), std::move(doc)},
        [field](S& s, const Params& p, const std::string& n) {
          std::invoke(field, s) = static_cast<I>(p.integer(n));
        });
    return *this;
  }

  template <class Field>
  ParamTable& boolean(std::string name, Field field, std::string doc) {
    S d = defaults_;
    add({std::move(name), ParamType::boolean, ref<bool>(field, d), {}, {}, {}, "", std::move(doc)},
        [field](S& s, const Params& p, const std::string& n) { ref<bool>(field, s) = p.boolean(n); });
    return *this;
  }

  template <class Field>
  ParamTable& string(std::string name, Field field, std::string doc) {
    S d = defaults_;
    add({std::move(name), ParamType::string, ref<std::string>(field, d), {}, {}, {}, "",
         std::move(doc)},
        [field](S& s, const Params& p, const std::string& n) {
          ref<std::string>(field, s) = p.string(n);
        });
    return *this;
  }

  // A choice stored as any value type E (an enum, a string...): each allowed
  // name with the value it stands for, listed in this order. The default is
  // the name of the field's default value (which must be one of them).
  template <class Field>
  ParamTable& choice(std::string name, Field field,
                     std::vector<std::pair<std::string, FieldType<Field>>> names, std::string doc) {
    using E = FieldType<Field>;
    S d = defaults_;
    const E& current = std::invoke(field, d);
    std::vector<std::string> choices;
    const std::string* default_name = nullptr;
    for (const auto& [text, value] : names) {
      choices.push_back(text);
      if (!default_name && value == current) default_name = &text;
    }
    if (!default_name)
      throw std::logic_error("choice parameter '" + name + "': the field's default has no name");
    add({std::move(name), ParamType::choice, *default_name, {}, {}, std::move(choices), "",
         std::move(doc)},
        [field, names](S& s, const Params& p, const std::string& n) {
          const std::string& given = p.string(n);
          for (const auto& [text, value] : names) {
            if (text == given) {
              std::invoke(field, s) = value;
              return;
            }
          }
          throw std::out_of_range("parameter '" + n + "': '" + given + "' is not a choice");
        });
    return *this;
  }

  // A string choice whose names are the stored values.
  template <class Field, class = std::enable_if_t<std::is_same_v<FieldType<Field>, std::string>>>
  ParamTable& choice(std::string name, Field field, const std::vector<std::string>& names,
                     std::string doc) {
    std::vector<std::pair<std::string, std::string>> pairs;
    for (const auto& n : names) pairs.emplace_back(n, n);
    return choice(std::move(name), field, std::move(pairs), std::move(doc));
  }

  ParamTable& check(std::function<void(S&)> step) {
    checks_.push_back(std::move(step));
    return *this;
  }

  const std::vector<ParamSpec>& specs() const { return specs_; }
  const S& defaults() const { return defaults_; }

  // The table's defaults with every declared field set from `params`.
  S read(const Params& params) const { return read(params, defaults_); }
  // `base` with every declared field set from `params` (fields the table
  // does not declare keep base's values).
  S read(const Params& params, S base) const {
    for (std::size_t i = 0; i < readers_.size(); ++i) readers_[i](base, params, specs_[i].name);
    for (const auto& step : checks_) step(base);
    return base;
  }

 private:
  using Reader = std::function<void(S&, const Params&, const std::string&)>;

  template <class T, class Field>
  static T& ref(const Field& field, S& s) {
    auto& r = std::invoke(field, s);
    static_assert(std::is_same_v<std::remove_reference_t<decltype(r)>, T>,
                  "the field's type does not match the parameter's type");
    return r;
  }

  void add(ParamSpec spec, Reader reader) {
    for (const auto& s : specs_)
      if (s.name == spec.name)
        throw std::logic_error("parameter '" + spec.name + "' is declared twice");
    specs_.push_back(std::move(spec));
    readers_.push_back(std::move(reader));
  }

  S defaults_;
  std::vector<ParamSpec> specs_;
  std::vector<Reader> readers_;
  std::vector<std::function<void(S&)>> checks_;
};

}  // namespace sketchlab
