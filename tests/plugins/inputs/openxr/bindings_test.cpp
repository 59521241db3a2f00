// Suggested bindings per interaction profile.
#include <catch2/catch.hpp>

#include <set>

#include "bindings.hpp"

using namespace sketchlab::openxr;

namespace {
const ProfileBindings& profile(const std::vector<ProfileBindings>& all, const std::string& name) {
  for (const auto& p : all)
    if (p.profile == "/interaction_profiles/" + name) return p;
  FAIL("no profile " << name);
  return all.front();
}
bool has(const ProfileBindings& p, const std::string& action, const std::string& path) {
  for (const auto& b : p.bindings)
    if (b.action == action && b.path == path) return true;
  return false;
}
}  // namespace

TEST_CASE("every profile binds drawing and both hand poses, each input path once", "[openxr]") {
  const auto all = suggested_bindings(InputSettings{});
  REQUIRE(all.size() == 4);
  for (const auto& p : all) {
    std::set<std::string> paths;
    bool draw = false;
    for (const auto& b : p.bindings) {
      CHECK(paths.insert(b.path).second);
      draw = draw || b.action == "draw";
    }
    CHECK(draw);
    CHECK(has(p, "hand_pose", "/user/hand/left/input/aim/pose"));
    CHECK(has(p, "hand_pose", "/user/hand/right/input/aim/pose"));
  }
}

TEST_CASE("Touch gets the configured buttons, other profiles fall back to what they have", "[openxr]") {
  const auto all = suggested_bindings(InputSettings{});
  const auto& touch = profile(all, "oculus/touch_controller");
  CHECK(has(touch, "draw", "/user/hand/right/input/trigger/value"));
  CHECK(has(touch, "grab", "/user/hand/left/input/squeeze/value"));
  CHECK(has(touch, "grab", "/user/hand/right/input/squeeze/value"));
  CHECK(has(touch, "undo", "/user/hand/left/input/x/click"));
  CHECK(has(touch, "redo", "/user/hand/left/input/y/click"));
  CHECK(has(touch, "mode", "/user/hand/right/input/a/click"));
  CHECK(has(touch, "delete", "/user/hand/right/input/b/click"));
  CHECK(has(touch, "add_patch", "/user/hand/right/input/thumbstick/click"));
  CHECK(has(touch, "toggle_correction", "/user/hand/left/input/menu/click"));
  const auto& simple = profile(all, "khr/simple_controller");
  CHECK(has(simple, "draw", "/user/hand/right/input/select/click"));
  CHECK(has(simple, "grab", "/user/hand/left/input/select/click"));
  CHECK(has(simple, "undo", "/user/hand/left/input/menu/click"));
  const auto& vive = profile(all, "htc/vive_controller");
  CHECK(has(vive, "grab", "/user/hand/left/input/squeeze/click"));
  CHECK(has(vive, "undo", "/user/hand/left/input/trackpad/click"));
  const auto& index = profile(all, "valve/index_controller");
  CHECK(has(index, "undo", "/user/hand/left/input/a/click"));
}

TEST_CASE("buttons are parameters, malformed names are refused with the allowed list", "[openxr]") {
  const auto specs = input_param_specs();
  std::map<std::string, sketchlab::ParamValue> given{{"undo_button", std::string("right/thumbstick")},
                                                     {"add_patch_button", std::string("left/thumbstick")}};
  const auto settings = settings_from_params(sketchlab::validate_params(specs, given));
  const auto all = suggested_bindings(settings);
  const auto& touch = profile(all, "oculus/touch_controller");
  CHECK(has(touch, "undo", "/user/hand/right/input/thumbstick/click"));
  CHECK(has(touch, "add_patch", "/user/hand/left/input/thumbstick/click"));
  given["redo_button"] = std::string("middle/x");
  CHECK_THROWS_WITH(settings_from_params(sketchlab::validate_params(specs, given)),
                    Catch::Contains("redo_button") && Catch::Contains("thumbstick"));
}
