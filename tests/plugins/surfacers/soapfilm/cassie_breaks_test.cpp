// CASSIE's automatic patch deletions inferred from its log (cassie_breaks.hpp).
#include <catch2/catch.hpp>

#include "cassie_breaks.hpp"

using namespace sketchlab;
using soapfilm::CassiePatch;
using soapfilm::CassieSession;
using soapfilm::CassieStroke;

namespace {

CassieSession square_then_cross() {
  // Strokes 1-4 (a square) at t = 1..4, patch 10 over them at 4; stroke 5
  // across it at t = 5.
  CassieSession s;
  for (int i = 1; i <= 5; ++i) {
    CassieStroke st;
    st.id = i;
    st.created = i;
    s.strokes.push_back(st);
  }
  s.patches.push_back({10, true, {1, 2, 3, 4}, 4.0, std::nullopt, std::nullopt});
  return s;
}

}  // namespace

TEST_CASE("a patch whose two halves CASSIE made at a later stroke is inferred broken there", "[soapfilm]") {
  CassieSession s = square_then_cross();
  s.patches.push_back({11, true, {5, 1, 2, 3}, 5.0, std::nullopt, std::nullopt});
  s.patches.push_back({12, true, {5, 3, 4}, 5.01, std::nullopt, std::nullopt});
  const auto broken = soapfilm::inferred_breaks(s);
  REQUIRE(broken.size() == 1);
  CHECK(broken.at(10) == 5.0);
}

TEST_CASE("no break is inferred from one half, halves missing a stroke, or manual halves", "[soapfilm]") {
  CassieSession one = square_then_cross();
  one.patches.push_back({11, true, {5, 1, 2, 3}, 5.0, std::nullopt, std::nullopt});
  CHECK(soapfilm::inferred_breaks(one).empty());

  CassieSession partial = square_then_cross();
  partial.patches.push_back({11, true, {5, 1, 2}, 5.0, std::nullopt, std::nullopt});
  partial.patches.push_back({12, true, {5, 2, 3}, 5.0, std::nullopt, std::nullopt});
  CHECK(soapfilm::inferred_breaks(partial).empty());  // stroke 4 in neither

  CassieSession manual = square_then_cross();
  manual.patches.push_back({11, false, {5, 1, 2}, 5.0, std::nullopt, std::nullopt});
  manual.patches.push_back({12, true, {5, 3, 4}, 5.0, std::nullopt, std::nullopt});
  CHECK(soapfilm::inferred_breaks(manual).empty());

  // Patches over old strokes only (no stroke of that event) are not halves.
  CassieSession old_only = square_then_cross();
  old_only.patches.push_back({11, true, {1, 2}, 5.0, std::nullopt, std::nullopt});
  old_only.patches.push_back({12, true, {3, 4}, 5.0, std::nullopt, std::nullopt});
  CHECK(soapfilm::inferred_breaks(old_only).empty());
}

TEST_CASE("halves made at the patch's own event or before do not break it", "[soapfilm]") {
  CassieSession s = square_then_cross();
  s.patches.front().created = 5.0;  // made at stroke 5's event, with the others
  s.patches.push_back({11, true, {5, 1, 2, 3}, 5.0, std::nullopt, std::nullopt});
  s.patches.push_back({12, true, {5, 3, 4}, 5.0, std::nullopt, std::nullopt});
  const auto broken = soapfilm::inferred_breaks(s);
  CHECK(broken.count(10) == 0);
}
