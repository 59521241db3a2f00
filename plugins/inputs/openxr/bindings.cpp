#include "bindings.hpp"

#include <map>
#include <set>

namespace sketchlab::openxr {
namespace {

// Component -> input path suffix, per hand.
using Components = std::map<std::string, std::string>;

struct Profile {
  std::string path;
  Components hand[2];
  // Used when the settings' button is missing on this profile, first free one.
  std::map<std::string, std::vector<std::string>> fallback;
};

std::vector<Profile> profiles() {
  const Components simple{{"select", "select/click"}, {"menu", "menu/click"}};
  const Components touch_left{{"trigger", "trigger/value"}, {"squeeze", "squeeze/value"},
                              {"x", "x/click"},             {"y", "y/click"},
                              {"menu", "menu/click"},       {"thumbstick", "thumbstick/click"}};
  const Components touch_right{{"trigger", "trigger/value"}, {"squeeze", "squeeze/value"},
                               {"a", "a/click"},             {"b", "b/click"},
                               {"thumbstick", "thumbstick/click"}};
  const Components index{{"trigger", "trigger/value"}, {"squeeze", "squeeze/value"},
                         {"a", "a/click"},             {"b", "b/click"},
                         {"thumbstick", "thumbstick/click"}, {"trackpad", "trackpad/force"}};
  const Components vive{{"trigger", "trigger/value"}, {"squeeze", "squeeze/click"},
                        {"menu", "menu/click"},       {"trackpad", "trackpad/click"}};
  return {
      {"/interaction_profiles/khr/simple_controller", {simple, simple},
       {{"draw", {"right/select"}}, {"grab", {"left/select"}}, {"undo", {"left/menu"}},
        {"mode", {"right/menu"}}}},
      {"/interaction_profiles/oculus/touch_controller", {touch_left, touch_right}, {}},
      {"/interaction_profiles/valve/index_controller", {index, index},
       {{"undo", {"left/a"}}, {"redo", {"left/b"}}, {"toggle_correction", {"left/thumbstick"}}}},
      {"/interaction_profiles/htc/vive_controller", {vive, vive},
       {{"undo", {"left/trackpad"}}, {"redo", {"left/menu"}}, {"mode", {"right/menu"}},
        {"delete", {"right/trackpad"}}}},
  };
}

std::string hand_path(Hand hand) { return hand == Hand::left ? "/user/hand/left" : "/user/hand/right"; }

}  // namespace

std::vector<ProfileBindings> suggested_bindings(const InputSettings& settings) {
  std::vector<ProfileBindings> out;
  for (const Profile& profile : profiles()) {
    ProfileBindings pb{profile.path, {}};
    std::set<std::string> used;
    // Binds `button` ("left/x") to `action` when the profile has it and it
    // is free; returns whether it did.
    auto bind = [&](const std::string& action, const std::string& button) {
      const auto [hand, component] = parse_button(button, action);
      const Components& c = profile.hand[static_cast<int>(hand)];
      const auto it = c.find(component);
      if (it == c.end()) return false;
      const std::string path = hand_path(hand) + "/input/" + it->second;
      if (!used.insert(path).second) return false;
      pb.bindings.push_back({action, path});
      return true;
    };
    auto bind_with_fallback = [&](const std::string& action, const std::string& button) {
      if (bind(action, button)) return;
      if (const auto f = profile.fallback.find(action); f != profile.fallback.end())
        for (const auto& b : f->second)
          if (bind(action, b)) return;
    };
    bind_with_fallback("draw", settings.draw_button);
    bool grab = false;
    for (Hand hand : {Hand::left, Hand::right})
      grab = bind("grab", std::string(hand == Hand::left ? "left/" : "right/") + settings.grab_component) || grab;
    if (!grab)
      if (const auto f = profile.fallback.find("grab"); f != profile.fallback.end())
        for (const auto& b : f->second) bind("grab", b);
    for (std::size_t i = 0; i < command_count; ++i)
      bind_with_fallback(std::string(to_string(static_cast<Command>(i))), settings.buttons[i]);
    for (Hand hand : {Hand::left, Hand::right})
      pb.bindings.push_back({"hand_pose", hand_path(hand) + "/input/aim/pose"});
    out.push_back(std::move(pb));
  }
  return out;
}

}  // namespace sketchlab::openxr
