// Agreement with CASSIE's own automatic patches on its final curve networks
// (data/cassie/sketch_graph + raw_data). The figures asserted are the ones
// this implementation reaches (README.md); a regression lowers them.
#include <catch2/catch.hpp>

#include "cassie_graph.hpp"
#include "test_paths.hpp"

using namespace sketchlab;

namespace {

soapfilm::FidelityReport run(const std::string& session) {
  return soapfilm::compare_with_cassie(test::source_path("data/cassie/sketch_graph/" + session + ".json"),
                                       soapfilm::load_cassie_session(test::source_path("data/cassie"), session),
                                       soapfilm::CycleSearchParams{});
}

}  // namespace

TEST_CASE("fidelity to CASSIE's automatic patches", "[soapfilm][slow]") {
  const auto hat = run("hat");
  const auto chair = run("chair");
  const auto lamp = run("01-2-1");
  const auto shoe = run("02-1-2");
  INFO("hat found " << hat.found << "/" << hat.cassie_automatic << " extra " << hat.extra);
  INFO("chair found " << chair.found << "/" << chair.cassie_automatic << " extra " << chair.extra);
  INFO("01-2-1 found " << lamp.found << "/" << lamp.cassie_automatic << " extra " << lamp.extra);
  CHECK(hat.cassie_automatic == 77);
  CHECK(chair.cassie_automatic == 222);
  CHECK(lamp.cassie_automatic == 11);
  CHECK(shoe.cassie_automatic == 0);  // Armature system: no patches
  // Found / missed / extra as measured (README.md).
  CHECK(hat.found >= 53);
  CHECK(chair.found >= 134);
  CHECK(lamp.found >= 5);
  CHECK(hat.found + hat.missed == hat.cassie_automatic);
  // Most extras are patches CASSIE's users had to add by hand.
  CHECK(hat.extra_matching_manual >= 14);
  CHECK(chair.extra_matching_manual >= 16);
  const double recall = double(hat.found + chair.found + lamp.found) /
                        double(hat.cassie_automatic + chair.cassie_automatic + lamp.cassie_automatic);
  CHECK(recall >= 0.6);
}
