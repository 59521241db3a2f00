#pragma once
// What a plugin library exports, and the helpers plugin authors use.
//
// A plugin is a shared library exporting one C symbol, `sketchlab_plugin_entry`,
// returning a PluginHeader. The host reads the header's ABI version and build
// fingerprint before touching anything else; only when both match does it use
// the C++ PluginDescriptor behind it. Factories and plugin objects never let an
// exception escape: the wrappers below turn exceptions into error strings.
//
// Plugin author's side (one per library, no static registrars):
//
//   sketchlab::PluginDescriptor describe() {
//     return sketchlab::corrector_descriptor<MyCorrector>("name", "1.0", "summary", specs);
//   }
//   SKETCHLAB_PLUGIN(describe)
//
// where MyCorrector derives from Corrector and has a constructor taking
// `const sketchlab::Params&` (already validated against `specs`).
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "sketchlab/plugin/budget.hpp"
#include "sketchlab/plugin/controller_input.hpp"
#include "sketchlab/plugin/corrector.hpp"
#include "sketchlab/plugin/export.hpp"
#include "sketchlab/plugin/input.hpp"
#include "sketchlab/plugin/pointer_input.hpp"
#include "sketchlab/plugin/params.hpp"
#include "sketchlab/plugin/surfacer.hpp"
#include "sketchlab/version.hpp"

namespace sketchlab {

// Bumped whenever any type crossing the plugin boundary changes layout.
// 2: Surfacer::recompute and RecomputeSurfaceEvent.
// 3: Stroke::draw_plane and Corrector::stroke_space.
// 4: the per-event time budget (budget.hpp): BudgetExceeded crosses the
//    boundary and the wrappers below turn it into the call's error;
//    Input::request_stop.
// 5: Input::next returns NextEvent (an event, not ready, or ended);
//    PluginDescriptor::make_pointer_input (live pointer inputs) and
//    PluginDescriptor::recording_param.
// 6: Input::finished() is gone (NextEvent says "ended");
//    PluginDescriptor::make_controller_input (controller_input.hpp);
//    CorrectionStats::outcomes.
inline constexpr std::uint32_t plugin_abi_version = 6;

enum class PluginKind { corrector, surfacer, input };
std::string_view to_string(PluginKind kind);
PluginKind plugin_kind_from_string(std::string_view name);  // throws, naming allowed values

extern "C" {
// Plain C layout: safe to read from a library built by anything.
struct PluginHeader {
  std::uint32_t abi_version;
  const char* fingerprint;  // must equal build_fingerprint() of the host
  const void* descriptor;   // const PluginDescriptor*, used only after the checks
};
}

template <class T>
using Factory = std::unique_ptr<T> (*)(const Params& params, std::string& error);

struct PluginDescriptor {
  PluginKind kind = PluginKind::corrector;
  std::string name;
  std::string version;
  std::string summary;
  std::vector<ParamSpec> params;
  // The one matching `kind` is set. On failure they return null and set error.
  Factory<Corrector> make_corrector = nullptr;
  Factory<Surfacer> make_surfacer = nullptr;
  Factory<Input> make_input = nullptr;
  // Also set, besides make_input, by input plugins whose objects a window
  // feeds with pointer events (pointer_input.hpp): the same object, typed.
  Factory<PointerInput> make_pointer_input = nullptr;
  // Also set by input plugins that an application rendering an OpenXR
  // session drives (controller_input.hpp); make_input then makes the input
  // that runs on its own (e.g. a headless session).
  Factory<ControllerInput> make_controller_input = nullptr;
  // Input plugins that play a recording file: the string parameter that
  // takes its path (an experiment sets it to each of its recordings). Empty
  // for inputs that do not play files.
  std::string recording_param = {};
};

namespace detail {
template <class F, class R>
R guarded(F&& f, R on_error, std::string R::*error_field) {
  try {
    return f();
  } catch (const BudgetExceeded& e) {
    on_error.*error_field = e.message();
  } catch (const std::exception& e) {
    on_error.*error_field = e.what();
  } catch (...) {
    on_error.*error_field = "unknown exception";
  }
  return on_error;
}

template <class T>
class GuardedCorrector final : public T {
 public:
  using T::T;
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    return guarded([&] { return T::correct(stroke, sketch); }, Correction{}, &Correction::error);
  }
};

template <class T>
class GuardedSurfacer final : public T {
 public:
  using T::T;
  SurfaceUpdate update(const Sketch& sketch, const Edit& last) override {
    return guarded([&] { return T::update(sketch, last); }, SurfaceUpdate{}, &SurfaceUpdate::error);
  }
  SurfaceUpdate command(const Sketch& sketch, const SurfaceCommand& command) override {
    return guarded([&] { return T::command(sketch, command); }, SurfaceUpdate{},
                   &SurfaceUpdate::error);
  }
  SurfaceUpdate recompute(const Sketch& sketch) override {
    return guarded([&] { return T::recompute(sketch); }, SurfaceUpdate{}, &SurfaceUpdate::error);
  }
};

template <class T>
class GuardedInput : public T {
 public:
  using T::T;
  NextEvent next() override {
    if (!error_.empty()) return NextEvent::ended();
    NextEvent event = NextEvent::ended();
    guard([&] { event = T::next(); });
    return error_.empty() ? std::move(event) : NextEvent::ended();
  }
  void request_stop() override {
    guard([&] { T::request_stop(); });
  }
  std::string error() const override { return error_.empty() ? T::error() : error_; }

 protected:
  // Runs `f`; an exception becomes the input's error (the input then ends).
  template <class F>
  void guard(F&& f) {
    try {
      f();
    } catch (const std::exception& e) {
      error_ = e.what();
    } catch (...) {
      error_ = "unknown exception";
    }
  }
  bool failed() const { return !error_.empty(); }

 private:
  std::string error_;
};

template <class T>
class GuardedControllerInput final : public GuardedInput<T> {
 public:
  using GuardedInput<T>::GuardedInput;
  void create_actions(XrHandleValue instance) override {
    if (!this->failed()) this->guard([&] { T::create_actions(instance); });
  }
  void attach(const XrSessionHandles& session, const Workspace& workspace, std::size_t stack_count) override {
    if (!this->failed()) this->guard([&] { T::attach(session, workspace, stack_count); });
  }
  void read_frame(std::int64_t display_time, double seconds, bool focused) override {
    if (!this->failed()) this->guard([&] { T::read_frame(display_time, seconds, focused); });
  }
  ControllerState state() const override {
    try {
      return T::state();
    } catch (...) {
      return {};
    }
  }
  void close() override {
    this->guard([&] { T::close(); });
  }
};

template <class Base, template <class> class Guard, class T>
std::unique_ptr<Base> make_guarded(const Params& params, std::string& error) {
  try {
    return std::make_unique<Guard<T>>(params);
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    error = "unknown exception";
  }
  return nullptr;
}
}  // namespace detail

template <class T>
PluginDescriptor corrector_descriptor(std::string name, std::string version, std::string summary,
                                      std::vector<ParamSpec> params) {
  PluginDescriptor d{PluginKind::corrector, std::move(name), std::move(version),
                     std::move(summary), std::move(params)};
  d.make_corrector = &detail::make_guarded<Corrector, detail::GuardedCorrector, T>;
  return d;
}

template <class T>
PluginDescriptor surfacer_descriptor(std::string name, std::string version, std::string summary,
                                     std::vector<ParamSpec> params) {
  PluginDescriptor d{PluginKind::surfacer, std::move(name), std::move(version),
                     std::move(summary), std::move(params)};
  d.make_surfacer = &detail::make_guarded<Surfacer, detail::GuardedSurfacer, T>;
  return d;
}

template <class T>
PluginDescriptor input_descriptor(std::string name, std::string version, std::string summary,
                                  std::vector<ParamSpec> params) {
  PluginDescriptor d{PluginKind::input, std::move(name), std::move(version), std::move(summary),
                     std::move(params)};
  d.make_input = &detail::make_guarded<Input, detail::GuardedInput, T>;
  return d;
}

// An input plugin whose objects are PointerInputs (T derives from it): hosts
// get them typed through PluginHost::make_pointer_input.
template <class T>
PluginDescriptor pointer_input_descriptor(std::string name, std::string version, std::string summary,
                                          std::vector<ParamSpec> params) {
  static_assert(std::is_base_of_v<PointerInput, T>, "a pointer input plugin's class derives from PointerInput");
  PluginDescriptor d = input_descriptor<T>(std::move(name), std::move(version), std::move(summary),
                                           std::move(params));
  d.make_pointer_input = &detail::make_guarded<PointerInput, detail::GuardedInput, T>;
  return d;
}

// An input plugin that both runs on its own (T, an Input: make_input) and is
// driven by an application's OpenXR session (C, a ControllerInput:
// make_controller_input, hosts get it typed through
// PluginHost::make_controller_input). Both constructors take the same Params.
template <class T, class C>
PluginDescriptor controller_input_descriptor(std::string name, std::string version, std::string summary,
                                             std::vector<ParamSpec> params) {
  static_assert(std::is_base_of_v<ControllerInput, C>, "a controller input plugin's class derives from ControllerInput");
  PluginDescriptor d = input_descriptor<T>(std::move(name), std::move(version), std::move(summary),
                                           std::move(params));
  d.make_controller_input = &detail::make_guarded<ControllerInput, detail::GuardedControllerInput, C>;
  return d;
}

}  // namespace sketchlab

#define SKETCHLAB_PLUGIN(DESCRIBE_FN)                                                  \
  extern "C" SKETCHLAB_SYMBOL_EXPORT const ::sketchlab::PluginHeader* sketchlab_plugin_entry() { \
    static const ::sketchlab::PluginDescriptor descriptor = DESCRIBE_FN();             \
    static const ::sketchlab::PluginHeader header{::sketchlab::plugin_abi_version,      \
                                                  SKETCHLAB_BUILD_FINGERPRINT, &descriptor}; \
    return &header;                                                                    \
  }
