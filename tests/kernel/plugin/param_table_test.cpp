#include "sketchlab/plugin/param_table.hpp"

#include <catch2/catch.hpp>
#include <numbers>

#include "sketchlab/types.hpp"

using namespace sketchlab;

namespace {

enum class Mode { fit, snap };

struct Settings {
  double delta = 0.02;
  double angle = std::numbers::pi / 4;  // radians, shown in degrees
  int rounds = 5;
  std::uint64_t seed = 7;
  bool mirror = false;
  Mode mode = Mode::snap;
  std::string label = "x";
  std::string rule = "b";
  Vec3 normal = Vec3::UnitZ();
};

constexpr double degrees = std::numbers::pi / 180.0;

const ParamTable<Settings>& table() {
  static const auto t =
      ParamTable<Settings>()
          .real("delta", &Settings::delta, 0.001, 0.2, "m", "snap distance")
          .real("angle", &Settings::angle, 0.0, 90.0, "deg", "corner angle", degrees)
          .integer("rounds", &Settings::rounds, 1, 100, "", "solver rounds")
          .integer("seed", &Settings::seed, 0, {}, "", "random seed")
          .boolean("mirror", &Settings::mirror, "use the mirror plane")
          .choice("mode", &Settings::mode, {{"fit", Mode::fit}, {"snap", Mode::snap}}, "how")
          .string("label", &Settings::label, "free text")
          .choice("rule", &Settings::rule, std::vector<std::string>{"a", "b", "c"}, "which rule")
          .real("normal_z", [](Settings& s) -> double& { return s.normal.z(); }, -1, 1, "",
                "normal, z component")
          .check([](Settings& s) {
            if (s.normal.norm() < 1e-9) throw std::invalid_argument("normal_z: the normal is zero");
            s.normal.normalize();
          });
  return t;
}

const ParamSpec& spec(const std::string& name) {
  for (const auto& s : table().specs())
    if (s.name == name) return s;
  FAIL("no spec " << name);
  throw std::logic_error("unreachable");
}

std::string error_message_for(const std::map<std::string, ParamValue>& given) {
  try {
    validate_params(table().specs(), given);
  } catch (const ParamError& e) {
    return e.what();
  }
  FAIL("validate_params accepted invalid parameters");
  return {};
}

}  // namespace

TEST_CASE("a parameter table's specs list each declaration in order, defaults from the struct",
          "[params]") {
  const auto& specs = table().specs();
  std::vector<std::string> names;
  for (const auto& s : specs) names.push_back(s.name);
  CHECK(names == std::vector<std::string>{"delta", "angle", "rounds", "seed", "mirror", "mode",
                                          "label", "rule", "normal_z"});
  CHECK(spec("delta").type == ParamType::real);
  CHECK(std::get<double>(spec("delta").default_value) == 0.02);
  CHECK(*spec("delta").min == 0.001);
  CHECK(*spec("delta").max == 0.2);
  CHECK(spec("delta").unit == "m");
  CHECK(spec("delta").doc == "snap distance");
  // Shown in degrees: the default is the stored radians over the scale.
  CHECK(std::get<double>(spec("angle").default_value) == std::numbers::pi / 4 / degrees);
  CHECK(spec("rounds").type == ParamType::integer);
  CHECK(std::get<std::int64_t>(spec("rounds").default_value) == 5);
  CHECK(std::get<std::int64_t>(spec("seed").default_value) == 7);
  CHECK(!spec("seed").max);
  CHECK(std::get<bool>(spec("mirror").default_value) == false);
  CHECK(spec("mode").type == ParamType::choice);
  CHECK(spec("mode").choices == std::vector<std::string>{"fit", "snap"});
  CHECK(std::get<std::string>(spec("mode").default_value) == "snap");
  CHECK(spec("label").type == ParamType::string);
  CHECK(std::get<std::string>(spec("rule").default_value) == "b");
  CHECK(std::get<double>(spec("normal_z").default_value) == 1.0);
  // Every default is valid against its own spec (the plugin host's check).
  for (const auto& s : specs) CHECK_NOTHROW(validate_param(s, s.default_value));
}

TEST_CASE("a parameter table's reader agrees with its specs", "[params]") {
  SECTION("the defaults read back as the struct's defaults") {
    const Settings s = table().read(validate_params(table().specs(), {}));
    const Settings d;
    CHECK(s.delta == d.delta);
    CHECK(s.angle == Approx(d.angle).epsilon(1e-15));
    CHECK(s.rounds == d.rounds);
    CHECK(s.seed == d.seed);
    CHECK(s.mirror == d.mirror);
    CHECK(s.mode == d.mode);
    CHECK(s.label == d.label);
    CHECK(s.rule == d.rule);
    CHECK(s.normal == d.normal);
  }
  SECTION("each given value lands in the field its name declares, and only there") {
    const Settings s = table().read(validate_params(
        table().specs(), {{"delta", 0.05}, {"angle", 30.0}, {"rounds", std::int64_t{9}},
                          {"seed", std::int64_t{123456789012}}, {"mirror", true},
                          {"mode", std::string("fit")}, {"label", std::string("hello")},
                          {"rule", std::string("c")}, {"normal_z", -0.5}}));
    CHECK(s.delta == 0.05);
    CHECK(s.angle == 30.0 * degrees);
    CHECK(s.rounds == 9);
    CHECK(s.seed == 123456789012u);
    CHECK(s.mirror);
    CHECK(s.mode == Mode::fit);
    CHECK(s.label == "hello");
    CHECK(s.rule == "c");
    // The check step ran on the filled struct: normalised.
    CHECK(s.normal == Vec3(0, 0, -1));
  }
  SECTION("read onto a base keeps the fields the table does not declare") {
    Settings base;
    base.normal = Vec3(3, 0, 4);  // only z is declared
    const Settings s = table().read(validate_params(table().specs(), {{"normal_z", 0.0}}), base);
    CHECK(s.normal == Vec3(1, 0, 0));
  }
  SECTION("a check step's error reaches the caller") {
    Settings base;
    base.normal = Vec3::Zero();
    CHECK_THROWS_WITH(table().read(validate_params(table().specs(), {{"normal_z", 0.0}}), base),
                      "normal_z: the normal is zero");
  }
}

TEST_CASE("bad values for a table's parameters name the parameter and the allowed values",
          "[params]") {
  CHECK(error_message_for({{"delta", 0.5}}) ==
        "parameter 'delta': 0.5 is out of range; allowed: real in [0.001, 0.2] (m)");
  CHECK(error_message_for({{"angle", 91.0}}) ==
        "parameter 'angle': 91 is out of range; allowed: real in [0, 90] (deg)");
  CHECK(error_message_for({{"rounds", 2.5}}) ==
        "parameter 'rounds': 2.5 is a real; allowed: integer in [1, 100]");
  CHECK(error_message_for({{"seed", std::int64_t{-1}}}) ==
        "parameter 'seed': -1 is out of range; allowed: integer >= 0");
  CHECK(error_message_for({{"mirror", std::string("yes")}}) ==
        "parameter 'mirror': \"yes\" is a string; allowed: true or false");
  CHECK(error_message_for({{"mode", std::string("guess")}}) ==
        "parameter 'mode': \"guess\" is not a choice; allowed: one of: fit, snap");
  CHECK(error_message_for({{"label", 1.0}}) == "parameter 'label': 1 is a real; allowed: any string");
  CHECK(error_message_for({{"rounds_", std::int64_t{1}}}) ==
        "unknown parameter 'rounds_'; declared: delta, angle, rounds, seed, mirror, mode, label, "
        "rule, normal_z");
  // Text from a command line goes through the same spec.
  CHECK_THROWS_WITH(parse_param_value(spec("rounds"), "many"),
                    Catch::Contains("'rounds'") && Catch::Contains("integer in [1, 100]"));
}

TEST_CASE("a table refuses a name declared twice and a choice default without a name",
          "[params]") {
  CHECK_THROWS_WITH(ParamTable<Settings>()
                        .real("delta", &Settings::delta, 0, 1, "m", "")
                        .real("delta", &Settings::angle, 0, 1, "m", ""),
                    "parameter 'delta' is declared twice");
  CHECK_THROWS_WITH(ParamTable<Settings>().choice("mode", &Settings::mode,
                                                  std::vector<std::pair<std::string, Mode>>{
                                                      {"fit", Mode::fit}},
                                                  ""),
                    "choice parameter 'mode': the field's default has no name");
}
