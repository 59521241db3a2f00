// What `soapfilm_compare` and the soapfilm tools' `--param` say to a user who
// mistypes an argument (issue #16: a clear error, never a crash): the option
// or name and the allowed values, exit status 2, before any table.
#include <catch2/catch.hpp>

#include <filesystem>

#include "cli_helpers.hpp"
#include "sketchlab/plugin/params.hpp"
#include "soapfilm_params.hpp"

using namespace sketchlab;

namespace {

std::string compare() { return test::binary_path("bin/soapfilm_compare"); }

}  // namespace

TEST_CASE("a --param naming no soapfilm parameter lists the declared ones", "[soapfilm][cli]") {
  std::map<std::string, ParamValue> given;
  soapfilm::parse_param_assignment("edge_length=0.03", given);
  CHECK(std::get<double>(given.at("edge_length")) == 0.03);
  try {
    soapfilm::parse_param_assignment("edge_lenght=0.03", given);
    FAIL("accepted an unknown parameter");
  } catch (const ParamError& e) {
    CHECK(e.parameter == "edge_lenght");
    CHECK_THAT(e.what(), Catch::Contains("unknown parameter 'edge_lenght'") &&
                             Catch::Contains("declared: ") && Catch::Contains("edge_length"));
  }
  CHECK_THROWS_WITH(soapfilm::parse_param_assignment("edge_length", given), Catch::Contains("expected NAME=VALUE"));
  CHECK_THROWS_WITH(soapfilm::parse_param_assignment("edge_length=abc", given),
                    Catch::Contains("'abc' is not a number") && Catch::Contains("allowed: real in"));
}

TEST_CASE("soapfilm_compare refuses bad arguments naming them, before any table", "[soapfilm][cli]") {
  REQUIRE(std::filesystem::exists(compare()));
  const std::string data = test::source_path("data/cassie");
  const struct {
    std::string args, says;
  } cases[] = {
      {data + " hat --meets abc", "parameter '--meets': 'abc' is not a number; allowed: real >= 0 (m)"},
      {data + " hat --meets -1", "parameter '--meets': -1 is out of range; allowed: real >= 0 (m)"},
      {data + " hat --logged-meets 1x", "parameter '--logged-meets': '1x' is not a number"},
      {data + " hat --logged-on-curve nan", "parameter '--logged-on-curve'"},
      {data + " hat --param foo=1", "unknown parameter 'foo'; declared: "},
      {data + " no_such_session", "no session 'no_such_session' in " + data + "/sketch_history"},
      {data + "/no_such_dir", data + "/no_such_dir: no such directory"},
      // A folder of another layout (the recordings) is named with the one expected.
      {test::source_path("data/recordings"), "no session in " + test::source_path("data/recordings") +
                                                 "/sketch_history (DATA_DIR holds sketch_history/, sketch_graph/, "
                                                 "raw_data/: CASSIE's layout)"},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    const test::CliRun r = test::run_captured(compare() + " " + c.args);
    CHECK(r.status == 2);
    CHECK_THAT(r.output, Catch::Contains(c.says));
    CHECK_THAT(r.output, !Catch::Contains("| session |"));
  }
}
