#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "sketchlab/plugin/params.hpp"
#include "sketchlab/plugin/plugin_api.hpp"

using namespace sketchlab;

namespace {

std::vector<ParamSpec> specs() {
  return {
      {"delta", ParamType::real, 0.02, 0.001, 0.2, {}, "m", "snap distance"},
      {"iterations", ParamType::integer, std::int64_t{5}, 1.0, 100.0, {}, "", "solver rounds"},
      {"symmetric", ParamType::boolean, false, {}, {}, {}, "", "use the mirror plane"},
      {"mode", ParamType::choice, std::string("fit"), {}, {}, {"fit", "snap"}, "", "how"},
      {"label", ParamType::string, std::string("x"), {}, {}, {}, "", "free text"},
  };
}

// The ParamError thrown by validate_params(specs(), given).
ParamError error_for(const std::map<std::string, ParamValue>& given) {
  try {
    validate_params(specs(), given);
  } catch (const ParamError& e) {
    return e;
  }
  FAIL("validate_params accepted invalid parameters");
  throw std::logic_error("unreachable");
}

}  // namespace

TEST_CASE("validate_params fills every default and keeps given values", "[params]") {
  const Params p = validate_params(specs(), {{"delta", 0.05}, {"mode", std::string("snap")}});
  CHECK(p.values().size() == specs().size());
  CHECK(p.real("delta") == 0.05);
  CHECK(p.integer("iterations") == 5);
  CHECK(p.boolean("symmetric") == false);
  CHECK(p.string("mode") == "snap");
  CHECK(p.string("label") == "x");
}

TEST_CASE("an integer is accepted for a real parameter and stored as a real", "[params]") {
  std::vector<ParamSpec> s = {{"scale", ParamType::real, 1.0, 0.0, 10.0, {}, "", ""}};
  const Params p = validate_params(s, {{"scale", std::int64_t{3}}});
  CHECK(std::holds_alternative<double>(p.values().at("scale")));
  CHECK(p.real("scale") == 3.0);
}

TEST_CASE("an unknown parameter names itself and the declared ones", "[params]") {
  const ParamError e = error_for({{"delat", 0.05}});
  CHECK(e.parameter == "delat");
  CHECK(std::string(e.what()) ==
        "unknown parameter 'delat'; declared: delta, iterations, symmetric, mode, label");
}

TEST_CASE("a value out of range names the parameter and its range", "[params]") {
  const ParamError e = error_for({{"delta", 0.5}});
  CHECK(e.parameter == "delta");
  CHECK(std::string(e.what()) ==
        "parameter 'delta': 0.5 is out of range; allowed: real in [0.001, 0.2] (m)");
  const ParamError low = error_for({{"iterations", std::int64_t{0}}});
  CHECK(std::string(low.what()) ==
        "parameter 'iterations': 0 is out of range; allowed: integer in [1, 100]");
}

TEST_CASE("range bounds are inclusive", "[params]") {
  CHECK_NOTHROW(validate_params(specs(), {{"delta", 0.2}, {"iterations", std::int64_t{1}}}));
  CHECK_NOTHROW(validate_params(specs(), {{"delta", 0.001}, {"iterations", std::int64_t{100}}}));
}

TEST_CASE("a value of the wrong type names the parameter and the expected type", "[params]") {
  const ParamError s = error_for({{"delta", std::string("far")}});
  CHECK(s.parameter == "delta");
  CHECK(std::string(s.what()) ==
        "parameter 'delta': \"far\" is a string; allowed: real in [0.001, 0.2] (m)");
  const ParamError r = error_for({{"iterations", 2.5}});
  CHECK(std::string(r.what()) == "parameter 'iterations': 2.5 is a real; allowed: integer in [1, 100]");
  const ParamError b = error_for({{"symmetric", std::int64_t{1}}});
  CHECK(std::string(b.what()) == "parameter 'symmetric': 1 is an integer; allowed: true or false");
  const ParamError l = error_for({{"label", true}});
  CHECK(std::string(l.what()) == "parameter 'label': true is a boolean; allowed: any string");
}

TEST_CASE("non-finite reals are rejected even without a range", "[params]") {
  std::vector<ParamSpec> s = {{"w", ParamType::real, 1.0, {}, {}, {}, "", ""}};
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    try {
      validate_params(s, {{"w", bad}});
      FAIL("accepted a non-finite value");
    } catch (const ParamError& e) {
      CHECK(e.parameter == "w");
      CHECK_THAT(e.what(), Catch::Contains("is not a finite number; allowed: real"));
    }
  }
}

TEST_CASE("a choice outside the list names the choices", "[params]") {
  const ParamError e = error_for({{"mode", std::string("guess")}});
  CHECK(e.parameter == "mode");
  CHECK(std::string(e.what()) ==
        "parameter 'mode': \"guess\" is not a choice; allowed: one of: fit, snap");
}

TEST_CASE("describe_allowed covers open ranges and units", "[params]") {
  ParamSpec s{"r", ParamType::real, 1.0, 0.0, {}, {}, "rad", ""};
  CHECK(describe_allowed(s) == "real >= 0 (rad)");
  s.min.reset();
  s.max = 3.5;
  CHECK(describe_allowed(s) == "real <= 3.5 (rad)");
  s.max.reset();
  s.unit.clear();
  CHECK(describe_allowed(s) == "real");
  CHECK(format_value(ParamValue{0.1}) == "0.1");
  CHECK(format_value(ParamValue{std::int64_t{-3}}) == "-3");
}

TEST_CASE("asking a Params for an undeclared or mistyped value throws", "[params]") {
  const Params p = validate_params(specs(), {});
  CHECK_THROWS_AS(p.real("nope"), std::out_of_range);
  CHECK_THROWS_WITH(p.integer("delta"), "parameter 'delta' is a real, not an integer");
}

TEST_CASE("plugin kinds round-trip through their names", "[params]") {
  for (auto kind : {PluginKind::corrector, PluginKind::surfacer, PluginKind::input}) {
    CHECK(plugin_kind_from_string(to_string(kind)) == kind);
  }
  CHECK_THROWS_WITH(plugin_kind_from_string("filter"),
                    "unknown plugin kind 'filter'; allowed: corrector, surfacer, input");
}
