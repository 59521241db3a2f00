#include <dlfcn.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#include "sketchlab/plugin/plugin_host.hpp"

using namespace sketchlab;
namespace fs = std::filesystem;

namespace {

const fs::path fixture_dir = SKETCHLAB_FIXTURE_PLUGIN_DIR;

fs::path fixture(const std::string& name) {
  return fixture_dir / ("sketchlab_corrector_" + name + ".so");
}

// The reason recorded for `file`; fails the test when there is none.
std::string reason_for(const PluginHost& host, const fs::path& file) {
  for (const auto& e : host.errors()) {
    if (e.path == file) return e.reason;
  }
  FAIL("no load error recorded for " << file);
  return {};
}

bool is_mapped(const fs::path& file) {
  // RTLD_NOLOAD only looks the library up; the handle it returns holds a
  // reference, released at once.
  void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_NOLOAD);
  if (handle) ::dlclose(handle);
  return handle != nullptr;
}

Stroke two_point_stroke(StrokeId id) {
  Stroke s;
  s.id = id;
  s.layer = Layer::shape;
  Sample a, b, c;
  a.position = Vec3(0, 0, 0);
  b.position = Vec3(0.05, 0.1, 0);
  c.position = Vec3(0.1, 0.2, 0.3);
  b.time = 0.1;
  c.time = 0.2;
  s.samples = {a, b, c};
  return s;
}

}  // namespace

TEST_CASE("the fixture directory: the good plugins load, each broken one is reported", "[plugin]") {
  PluginHost host;
  host.load_directories({fixture_dir});

  std::vector<std::string> loaded;
  for (const auto& p : host.plugins()) {
    CHECK(p.library);
    CHECK(p.path.parent_path() == fixture_dir);
    loaded.push_back(p.descriptor->name);
  }
  // Sorted by file name; the throwing plugins load (they fail only when used).
  CHECK(loaded == std::vector<std::string>{"correct_throws", "factory_throws", "good"});
  // Five broken here, eleven from descriptor_defect.cpp (next test case).
  CHECK(host.errors().size() == 16);

  CHECK(reason_for(host, fixture("wrong_abi")) ==
        "built for ABI 7, host has " + std::to_string(plugin_abi_version));
  CHECK(reason_for(host, fixture("wrong_fingerprint")) ==
        std::string("plugin built with sketchlab-0.0.1;othercc-1.0;otherlib-1;Debug, host is ") +
            build_fingerprint());
  CHECK(reason_for(host, fixture("no_entry")) ==
        "no entry point 'sketchlab_plugin_entry' (not a sketchlab plugin?)");
  CHECK(reason_for(host, fixture("name_mismatch")) ==
        "file name says corrector 'name_mismatch' but the plugin describes itself as corrector "
        "'other'");
  CHECK(reason_for(host, fixture("bad_default")) ==
        "invalid default: parameter 'delta': 0.5 is out of range; allowed: real in [0.001, 0.2] "
        "(m)");
}

TEST_CASE("each check of a plugin's header and descriptor refuses it with its own reason", "[plugin]") {
  // One fixture per check (tests/fixtures/plugins/descriptor_defect.cpp), in
  // the order the host makes them.
  const std::vector<std::pair<std::string, std::string>> expected{
      {"entry_throws", "entry point threw: no describing today"},
      {"null_header", "entry point returned no header"},
      {"no_fingerprint", "header has no build fingerprint"},
      {"no_descriptor", "header has no descriptor"},
      {"no_factory", "descriptor has no factory for its kind (corrector)"},
      {"pointer_on_corrector", "a pointer input factory on a non-input plugin"},
      {"controller_on_corrector", "a controller input factory on a non-input plugin"},
      {"bad_recording_param", "recording_param 'path' is not a string parameter of an input"},
      {"empty_param_name", "a parameter has an empty name"},
      {"duplicate_param", "parameter 'delta' is declared twice"},
      {"empty_choice", "choice parameter 'mode' has no choices"},
  };
  for (const auto& [name, reason] : expected) {
    INFO(name);
    PluginHost host;
    CHECK_FALSE(host.load_file(fixture(name)));
    CHECK(host.plugins().empty());
    CHECK(reason_for(host, fixture(name)) == reason);
    // A refused plugin cannot be made: the error says why it did not load.
    CHECK_THROWS_WITH(host.make_corrector(name, {}),
                      Catch::Contains("did not load: " + reason));
  }
}

TEST_CASE("a file that is not a library is refused before the loader sees it", "[plugin]") {
  const fs::path dir = fs::temp_directory_path() / "sketchlab_test_plugin_host_garbage";
  fs::create_directories(dir);
  const fs::path file = dir / "sketchlab_corrector_garbage.so";
  {
    std::ofstream out(file);
    out << std::string(256, 'x');
  }
  PluginHost host;
  CHECK_FALSE(host.load_file(file));
  REQUIRE(host.errors().size() == 1);
  CHECK(host.errors()[0].path == file);
  CHECK(host.errors()[0].reason == "not an ELF shared library (no ELF header)");
  fs::remove_all(dir);
}

TEST_CASE("a library the loader refuses reports the loader's message", "[plugin]") {
  // A valid ELF shared object that is no plugin and needs a missing library.
  const fs::path dir = fs::temp_directory_path() / "sketchlab_test_plugin_host_needs";
  fs::create_directories(dir);
  const fs::path file = dir / "sketchlab_corrector_needs.so";
  fs::copy_file(fixture("good"), file, fs::copy_options::overwrite_existing);
  // Rename the kernel dependency in the dynamic string table: same length, so
  // every offset stays valid.
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto at = bytes.find("libsketchlab.so");
  REQUIRE(at != std::string::npos);
  bytes.replace(at, 15, "libnot_there.so");
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  PluginHost host;
  CHECK_FALSE(host.load_file(file));
  REQUIRE(host.errors().size() == 1);
  CHECK_THAT(host.errors()[0].reason, Catch::StartsWith("cannot load library: ") &&
                                          Catch::Contains("libnot_there.so"));
  fs::remove_all(dir);
}

TEST_CASE("a truncated library is refused before dlopen, whatever its length", "[plugin][reliability]") {
  // Issue 17, D1 (reproducer P1): half a plugin on the search path made
  // dlopen map segments past the end of the file, and the host died of
  // SIGBUS. Every prefix of a real plugin must be refused with a reason.
  const fs::path dir = fs::temp_directory_path() / "sketchlab_test_plugin_host_truncated";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string bytes;
  {
    std::ifstream in(fixture("good"), std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  REQUIRE(bytes.size() > 4096);
  std::vector<std::size_t> lengths = {0, 3, 63, 64, bytes.size() / 2, bytes.size() - 1};
  for (int k = 1; k < 40; ++k) lengths.push_back(bytes.size() * k / 40);
  PluginHost host;
  for (std::size_t n : lengths) {
    const fs::path file = dir / ("sketchlab_corrector_cut" + std::to_string(n) + ".so");
    std::ofstream(file, std::ios::binary) << bytes.substr(0, n);
    CHECK_FALSE(host.load_file(file));
    const std::string reason = reason_for(host, file);
    INFO(n << " bytes: " << reason);
    CHECK((reason.rfind("truncated or damaged: ", 0) == 0 ||
           reason == "not an ELF shared library (no ELF header)"));
  }
  CHECK(host.plugins().empty());
  fs::remove_all(dir);
}

TEST_CASE("entries named like plugins that are not files are reported, not skipped", "[plugin]") {
  const fs::path dir = fs::temp_directory_path() / "sketchlab_test_plugin_host_dirs";
  fs::remove_all(dir);
  fs::create_directories(dir / "sketchlab_corrector_folder.so");
  PluginHost host;
  host.load_directories({dir});
  REQUIRE(host.errors().size() == 1);
  CHECK(host.errors()[0].path == dir / "sketchlab_corrector_folder.so");
  CHECK(host.errors()[0].reason == "is a directory, not a plugin library");
  fs::remove_all(dir);
}

TEST_CASE("the probe loads each library in a child first: a crash at load time is reported", "[plugin]") {
  PluginLoadOptions options;
  options.probe = true;
  PluginHost host(options);
  const fs::path crashing =
      fixture_dir / "crashes_at_load" / "sketchlab_corrector_crashes_at_load.so";
  CHECK_FALSE(host.load_file(crashing));
  CHECK(reason_for(host, crashing) ==
        "loading it killed the probe process with signal " + std::to_string(SIGBUS) + " (" +
            strsignal(SIGBUS) + ")");
  CHECK_FALSE(is_mapped(crashing));
  // Well-behaved plugins pass the probe and load as usual.
  CHECK(host.load_file(fixture("good")));
  CHECK_FALSE(host.load_file(fixture("wrong_abi")));
  CHECK(reason_for(host, fixture("wrong_abi")) ==
        "built for ABI 7, host has " + std::to_string(plugin_abi_version));
}

TEST_CASE("file names must follow sketchlab_<kind>_<name>.so and duplicates are skipped", "[plugin]") {
  PluginHost host;
  CHECK_FALSE(host.load_file(fixture_dir / "sketchlab_filter_good.so"));
  CHECK_THAT(host.errors().back().reason, Catch::StartsWith("file name is not sketchlab_"));

  CHECK(host.load_file(fixture("good")));
  CHECK_FALSE(host.load_file(fixture("good")));
  CHECK(host.plugins().size() == 1);
  CHECK(host.errors().back().reason ==
        "corrector 'good' is already loaded from " + fixture("good").string() +
            "; this copy is ignored");
}

TEST_CASE("a missing directory is reported, not fatal", "[plugin]") {
  PluginHost host;
  host.load_directories({fixture_dir / "does_not_exist", fixture_dir});
  CHECK(host.find(PluginKind::corrector, "good") != nullptr);
  CHECK(host.errors().front().path == fixture_dir / "does_not_exist");
  CHECK(host.errors().front().reason == "not a directory");
}

TEST_CASE("make_corrector validates parameters and passes them to the plugin", "[plugin]") {
  PluginHost host;
  REQUIRE(host.load_file(fixture("good")));
  const auto& specs = host.find(PluginKind::corrector, "good")->descriptor->params;
  CHECK(specs.size() == 5);

  auto corrector = host.make_corrector(
      "good", {{"count", std::int64_t{7}}, {"scale", 0.1}, {"flag", true}});
  Sketch sketch;
  const Stroke stroke = two_point_stroke(3);
  const Correction c = corrector->correct(stroke, sketch);
  CHECK(c.error.empty());
  CHECK(c.stats.iterations == 7);
  CHECK(c.stats.extra.at("scale") == 0.1);
  CHECK(c.stats.extra.at("flag") == 1.0);
  CHECK(c.stats.extra.at("label_length") == 4.0);  // default "echo"
  REQUIRE(c.edit.curves_added.size() == 1);
  const auto& curve = c.edit.curves_added[0];
  CHECK(curve.source_stroke == 3);
  CHECK(curve.curve.control_points.front() == stroke.samples.front().position);
  CHECK(curve.curve.control_points.back() == stroke.samples.back().position);
}

TEST_CASE("parameter errors from make_corrector name the parameter", "[plugin]") {
  PluginHost host;
  REQUIRE(host.load_file(fixture("good")));
  auto param_error = [&](const std::map<std::string, ParamValue>& params) {
    try {
      host.make_corrector("good", params);
    } catch (const ParamError& e) {
      return std::make_pair(e.parameter, std::string(e.what()));
    }
    FAIL("make_corrector accepted invalid parameters");
    return std::make_pair(std::string(), std::string());
  };
  CHECK(param_error({{"sacle", 0.1}}) ==
        std::make_pair(std::string("sacle"),
                       std::string("unknown parameter 'sacle'; declared: flag, count, scale, label, "
                                   "mode")));
  CHECK(param_error({{"count", std::string("many")}}) ==
        std::make_pair(std::string("count"),
                       std::string("parameter 'count': \"many\" is a string; allowed: integer in "
                                   "[0, 10]")));
  CHECK(param_error({{"scale", 1.5}}) ==
        std::make_pair(std::string("scale"),
                       std::string("parameter 'scale': 1.5 is out of range; allowed: real in "
                                   "[0.001, 0.2] (m)")));
}

TEST_CASE("unknown plugins and failing factories give PluginError", "[plugin]") {
  PluginHost host;
  host.load_directories({fixture_dir});
  CHECK_THROWS_MATCHES(host.make_corrector("cassie", {}), PluginError,
                       Catch::Message("unknown corrector 'cassie'; available: correct_throws, "
                                      "factory_throws, good"));
  CHECK_THROWS_MATCHES(host.make_surfacer("good", {}), PluginError,
                       Catch::Message("unknown surfacer 'good'; no surfacer plugins are loaded"));
  CHECK_THROWS_MATCHES(host.make_corrector("factory_throws", {}), PluginError,
                       Catch::Message("plugin 'factory_throws' failed to start: model file missing"));
  // A plugin that failed its checks is named with the reason.
  CHECK_THROWS_WITH(host.make_corrector("wrong_abi", {}),
                    Catch::Contains("did not load: built for ABI 7, host has " +
                                   std::to_string(plugin_abi_version)));
}

TEST_CASE("an exception inside correct() becomes Correction::error", "[plugin]") {
  PluginHost host;
  REQUIRE(host.load_file(fixture("correct_throws")));
  auto corrector = host.make_corrector("correct_throws", {});
  Sketch sketch;
  Correction c;
  REQUIRE_NOTHROW(c = corrector->correct(two_point_stroke(5), sketch));
  CHECK(c.error == "solver diverged on stroke 5");
  CHECK(c.edit.empty());
}

TEST_CASE("objects keep their library loaded after the host is gone", "[plugin]") {
  const fs::path file = fixture("good");
  REQUIRE_FALSE(is_mapped(file));
  std::shared_ptr<Corrector> corrector;
  {
    PluginHost host;
    REQUIRE(host.load_file(file));
    corrector = host.make_corrector("good", {});
  }
  CHECK(is_mapped(file));
  Sketch sketch;
  const Correction c = corrector->correct(two_point_stroke(1), sketch);
  CHECK(c.error.empty());
  CHECK(c.edit.curves_added.size() == 1);
  corrector.reset();
  // The last reference was the object's: the library is unloaded with it.
  CHECK_FALSE(is_mapped(file));
}

TEST_CASE("default search paths: existing directories, canonical, without duplicates", "[plugin]") {
  const std::string value = (fixture_dir / "does_not_exist").string() + "::" + fixture_dir.string() +
                            ":" + (fixture_dir / ".." / fixture_dir.filename()).string();
  ::setenv("SKETCHLAB_PLUGIN_PATH", value.c_str(), 1);
  const auto dirs = PluginHost::default_search_paths();
  ::unsetenv("SKETCHLAB_PLUGIN_PATH");

  const fs::path canonical_fixtures = fs::canonical(fixture_dir);
  CHECK(std::count(dirs.begin(), dirs.end(), canonical_fixtures) == 1);
  for (const auto& d : dirs) {
    CHECK(fs::is_directory(d));
    CHECK(d == fs::canonical(d));
  }
  // SKETCHLAB_PLUGIN_PATH first (a user's plugin overrides a bundled one),
  // the build tree's plugin directory after it.
  REQUIRE_FALSE(dirs.empty());
  CHECK(dirs.front() == canonical_fixtures);
  if (fs::is_directory(SKETCHLAB_BUILD_PLUGIN_DIR)) {
    CHECK(dirs.back() == fs::canonical(SKETCHLAB_BUILD_PLUGIN_DIR));
  }
}
