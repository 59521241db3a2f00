// The wrappers input_descriptor and controller_input_descriptor install
// (plugin_api.hpp): a live input tells "nothing yet" from "ended", and an
// exception escaping any call becomes the input's error, after which it
// ends for good.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "sketchlab/plugin/plugin_api.hpp"

using namespace sketchlab;

namespace {

// Two events with a pause between them, then a failure.
class Flaky : public Input {
 public:
  explicit Flaky(const Params&) {}
  RecordingHeader header() const override { return {}; }
  NextEvent next() override {
    switch (calls_++) {
      case 0: return Event{0.0, UndoEvent{}};
      case 1: return NextEvent::not_ready();
      case 2: return Event{1.0, RedoEvent{}};
      default: throw std::runtime_error("device lost");
    }
  }

 private:
  int calls_ = 0;
};

// A controller input whose frames fail once `fail` is set.
class Controllers : public ControllerInput {
 public:
  explicit Controllers(const Params&) {}
  RecordingHeader header() const override { return {}; }
  NextEvent next() override { return closed_ ? NextEvent::ended() : NextEvent::not_ready(); }
  void create_actions(XrHandleValue instance) override { instance_ = instance; }
  void attach(const XrSessionHandles&, const Workspace&, std::size_t) override {}
  void read_frame(std::int64_t, double seconds, bool) override {
    if (seconds > 1.0) throw std::runtime_error("xrSyncActions failed");
    ++frames_;
  }
  ControllerState state() const override {
    ControllerState s;
    s.view.stack = static_cast<std::size_t>(frames_);
    return s;
  }
  void close() override { closed_ = true; }

 private:
  XrHandleValue instance_ = 0;
  int frames_ = 0;
  bool closed_ = false;
};

}  // namespace

TEST_CASE("an input tells nothing yet from ended, and a failure ends it with its error", "[plugin]") {
  const PluginDescriptor d = input_descriptor<Flaky>("flaky", "1.0", "", {});
  std::string error;
  const std::unique_ptr<Input> input = d.make_input(Params{}, error);
  REQUIRE(input);
  CHECK(input->next().has_event());
  CHECK(input->next().state() == NextEvent::State::not_ready);
  CHECK(input->next().has_event());
  CHECK(input->error().empty());
  CHECK(input->next().is_ended());
  CHECK(input->error() == "device lost");
  CHECK(input->next().is_ended());  // for good
}

TEST_CASE("a controller input's failing frame becomes its error and ends it", "[plugin]") {
  const PluginDescriptor d = controller_input_descriptor<Flaky, Controllers>("controllers", "1.0", "", {});
  REQUIRE(d.make_input);
  REQUIRE(d.make_controller_input);
  std::string error;
  const std::unique_ptr<ControllerInput> input = d.make_controller_input(Params{}, error);
  REQUIRE(input);
  input->create_actions(xr_handle_value(reinterpret_cast<void*>(0x1234)));
  input->attach({}, Workspace{}, 1);
  input->read_frame(0, 0.0, true);
  input->read_frame(1, 0.5, true);
  CHECK(input->state().view.stack == 2);
  CHECK(input->next().state() == NextEvent::State::not_ready);
  input->read_frame(2, 2.0, true);
  CHECK(input->error() == "xrSyncActions failed");
  CHECK(input->next().is_ended());
  input->read_frame(3, 0.7, true);  // ignored once failed
  CHECK(input->state().view.stack == 2);
}

TEST_CASE("OpenXR handles travel as their 64-bit values", "[plugin]") {
  int object = 0;
  int* const handle = &object;
  CHECK(xr_handle<int*>(xr_handle_value(handle)) == handle);
  CHECK(xr_handle_value(static_cast<int*>(nullptr)) == 0);
  CHECK(xr_handle<std::uint64_t>(xr_handle_value(std::uint64_t{42})) == 42);
}
