#include <catch2/catch.hpp>
#include <fstream>
#include <functional>

#include "sketchlab/config/config.hpp"

using namespace sketchlab;
namespace fs = std::filesystem;

namespace {

// A scratch directory per test case, emptied on creation.
struct Scratch {
  explicit Scratch(const std::string& name)
      : dir(fs::temp_directory_path() / ("sketchlab_test_config_" + name)) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  fs::path write(const std::string& rel, const std::string& text) const {
    const fs::path p = dir / rel;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p;
  }
  fs::path dir;
};

// Recordings used by the experiments below.
void add_recordings(const Scratch& s) {
  s.write("recs/b.jsonl", "{}\n");
  s.write("recs/a.jsonl", "{}\n");
  s.write("recs/a1.jsonl", "{}\n");
  s.write("recs/notes.txt", "x\n");
  s.write("recs/.hidden.jsonl", "{}\n");
  s.write("other/c.jsonl", "{}\n");
}

const std::string experiment_yaml =
    "experiment: compare\n"                        // 1
    "recordings:\n"                                // 2
    "  - recs/*.jsonl\n"                           // 3
    "  - other/c.jsonl\n"                          // 4
    "stacks:\n"                                    // 5
    "  - corrector:\n"                             // 6
    "      plugin: freehand\n"                     // 7
    "      params:\n"                              // 8
    "        delta: 0.02\n"                        // 9
    "        iterations: 5\n"                      // 10
    "        symmetric: true\n"                    // 11
    "        mode: snap\n"                         // 12
    "        label: \"7\"\n"                       // 13
    "  - name: tuned\n"                            // 14
    "    input: {plugin: replay}\n"                // 15
    "    corrector: freehand\n"                    // 16
    "    surfacer: {plugin: soapfilm, params: {samples: 8}}\n"  // 17
    "  - corrector: {plugin: freehand}\n"          // 18
    "outputs:\n"                                   // 19
    "  dir: out\n"                                 // 20
    "  ply: false\n";                              // 21

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  FAIL("no ConfigError thrown");
  return {};
}

}  // namespace

TEST_CASE("a valid experiment loads with globs expanded and names assigned", "[config]") {
  Scratch s("valid_experiment");
  add_recordings(s);
  const fs::path file = s.write("exp.yaml", experiment_yaml);
  const ExperimentConfig c = load_experiment(file);

  CHECK(c.name == "compare");
  CHECK(c.file == file);
  const auto dir = fs::absolute(s.dir).lexically_normal();
  CHECK(c.recordings == std::vector<fs::path>{dir / "other/c.jsonl", dir / "recs/a.jsonl",
                                              dir / "recs/a1.jsonl", dir / "recs/b.jsonl"});

  REQUIRE(c.stacks.size() == 3);
  // Unnamed stacks take the corrector name, made unique.
  CHECK(c.stacks[0].name == "freehand");
  CHECK(c.stacks[1].name == "tuned");
  CHECK(c.stacks[2].name == "freehand-2");

  const PluginChoice& p = c.stacks[0].corrector;
  CHECK(p.plugin == "freehand");
  CHECK(p.location.to_string() == file.string() + ":7");
  CHECK(p.params.at("delta") == ParamValue{0.02});
  CHECK(p.params.at("iterations") == ParamValue{std::int64_t{5}});
  CHECK(p.params.at("symmetric") == ParamValue{true});
  CHECK(p.params.at("mode") == ParamValue{std::string("snap")});
  CHECK(p.params.at("label") == ParamValue{std::string("7")});  // quoted: a string
  CHECK(p.param_locations.at("delta").line == 9);
  CHECK(p.param_locations.at("label").line == 13);
  CHECK_FALSE(c.stacks[0].input);
  CHECK_FALSE(c.stacks[0].surfacer);

  CHECK(c.stacks[1].input->plugin == "replay");
  CHECK(c.stacks[1].corrector.plugin == "freehand");
  CHECK(c.stacks[1].corrector.location.line == 16);
  REQUIRE(c.stacks[1].surfacer);
  CHECK(c.stacks[1].surfacer->params.at("samples") == ParamValue{std::int64_t{8}});

  CHECK(c.outputs.dir == "out");
  CHECK_FALSE(c.outputs.ply);  // turned off
  // Every other output is on by default.
  CHECK(c.outputs.obj);
  CHECK(c.outputs.sketch_json);
  CHECK(c.outputs.stroke_csv);
  CHECK(c.outputs.mlp);
  CHECK(c.outputs.pictures);
  CHECK(c.outputs.report);
  CHECK(c.outputs.timestamp);
}

TEST_CASE("a valid stack file loads, named after the file by default", "[config]") {
  Scratch s("valid_stack");
  const fs::path file = s.write("cassie-default.yaml",
                                "corrector:\n"
                                "  plugin: cassie\n"
                                "  params: {delta: 0.05, use_grid: false, seed: -3, eps: 1e-3}\n"
                                "surfacer: soapfilm\n");
  const StackConfig st = load_stack(file);
  CHECK(st.name == "cassie-default");
  CHECK(st.corrector.plugin == "cassie");
  CHECK(st.corrector.params.at("use_grid") == ParamValue{false});
  CHECK(st.corrector.params.at("seed") == ParamValue{std::int64_t{-3}});
  CHECK(st.corrector.params.at("eps") == ParamValue{1e-3});
  REQUIRE(st.surfacer);
  CHECK(st.surfacer->plugin == "soapfilm");
  CHECK(st.surfacer->location.line == 4);
}

TEST_CASE("an unknown key names file, line and the allowed keys", "[config]") {
  Scratch s("unknown_key");
  add_recordings(s);
  const fs::path file = s.write("exp.yaml",
                                "recordings: [recs/a.jsonl]\n"
                                "stacks:\n"
                                "  - corector: {plugin: freehand}\n");
  CHECK(error_of([&] { load_experiment(file); }) ==
        file.string() + ":3: unknown key 'corector' in a stack (allowed: name, input, corrector, "
                        "surfacer, time_budget)");

  const fs::path top = s.write("top.yaml", "recordings: [recs/a.jsonl]\nstack: []\n");
  CHECK(error_of([&] { load_experiment(top); }) ==
        top.string() + ":2: unknown key 'stack' in an experiment (allowed: experiment, "
                       "recordings, stacks, outputs, sweep)");

  const fs::path plugin = s.write("stack.yaml", "corrector: {plugin: x, parms: {}}\n");
  CHECK(error_of([&] { load_stack(plugin); }) ==
        plugin.string() + ":1: unknown key 'parms' in a corrector choice (allowed: plugin, params)");
}

TEST_CASE("a value of the wrong type names file, line and what is allowed", "[config]") {
  Scratch s("wrong_type");
  add_recordings(s);
  const fs::path file = s.write("exp.yaml",
                                "recordings: [recs/a.jsonl]\n"
                                "stacks: [{corrector: freehand}]\n"
                                "outputs:\n"
                                "  ply: maybe\n");
  CHECK(error_of([&] { load_experiment(file); }) ==
        file.string() + ":4: 'outputs.ply' must be a boolean, not 'maybe' (allowed: true, false)");

  const fs::path stacks = s.write("stacks.yaml",
                                  "recordings: [recs/a.jsonl]\n"
                                  "stacks: {corrector: freehand}\n");
  CHECK_THAT(error_of([&] { load_experiment(stacks); }),
             Catch::StartsWith(stacks.string() + ":2: 'stacks' must be a non-empty list of stacks, "
                                                 "not a map (each with keys: name, input"));

  const fs::path param = s.write("param.yaml", "corrector: {plugin: x, params: {delta: [1, 2]}}\n");
  CHECK(error_of([&] { load_stack(param); }) ==
        param.string() + ":1: parameter 'corrector.params.delta' must be a single value, not a "
                         "list (allowed: true, false, a number or a string)");
}

TEST_CASE("a stack without a corrector is an error naming the stack's line", "[config]") {
  Scratch s("missing_corrector");
  add_recordings(s);
  const fs::path file = s.write("exp.yaml",
                                "recordings: [recs/a.jsonl]\n"
                                "stacks:\n"
                                "  - corrector: freehand\n"
                                "  - name: lonely\n"
                                "    surfacer: soapfilm\n");
  CHECK(error_of([&] { load_experiment(file); }) ==
        file.string() + ":4: the stack has no 'corrector' (allowed: name, input, corrector, "
                        "surfacer, time_budget)");
  const fs::path no_stacks = s.write("none.yaml", "recordings: [recs/a.jsonl]\n");
  CHECK_THAT(error_of([&] { load_experiment(no_stacks); }),
             Catch::Contains("the experiment has no 'stacks' (allowed: experiment, recordings"));
}

TEST_CASE("a recording glob that matches nothing is named with its line", "[config]") {
  Scratch s("bad_glob");
  add_recordings(s);
  const fs::path file = s.write("exp.yaml",
                                "recordings:\n"
                                "  - recs/a?.jsonl\n"
                                "  - recs/*.csv\n"
                                "stacks: [{corrector: freehand}]\n");
  const std::string e = error_of([&] { load_experiment(file); });
  CHECK_THAT(e, Catch::StartsWith(file.string() + ":3: 'recs/*.csv' matches no file (looked in "));

  const fs::path missing = s.write("missing.yaml",
                                   "recordings: recs/zzz.jsonl\nstacks: [{corrector: freehand}]\n");
  CHECK_THAT(error_of([&] { load_experiment(missing); }),
             Catch::StartsWith(missing.string() + ":1: recording 'recs/zzz.jsonl' does not exist"));

  // glob(3): wildcards in directories and character classes too.
  const fs::path wild_dir = s.write("wild.yaml",
                                    "recordings: ['*/[ac]*.jsonl']\nstacks: [{corrector: freehand}]\n");
  const auto w = load_experiment(wild_dir);
  REQUIRE(w.recordings.size() == 3);
  CHECK(w.recordings[0] == fs::absolute(s.dir / "other/c.jsonl").lexically_normal());
  CHECK(w.recordings[1].filename() == "a.jsonl");
  CHECK(w.recordings[2].filename() == "a1.jsonl");  // not .hidden.jsonl

  // '?' matches exactly one character: recs/a?.jsonl is a1 only.
  const fs::path one = s.write("one.yaml", "recordings: ['recs/a?.jsonl']\nstacks: [{corrector: x}]\n");
  const auto c = load_experiment(one);
  REQUIRE(c.recordings.size() == 1);
  CHECK(c.recordings[0].filename() == "a1.jsonl");
}

TEST_CASE("duplicate explicit stack names are an error naming both places", "[config]") {
  Scratch s("duplicate_names");
  add_recordings(s);
  const fs::path file = s.write("exp.yaml",
                                "recordings: [recs/a.jsonl]\n"
                                "stacks:\n"
                                "  - {name: a, corrector: freehand}\n"
                                "  - {name: a, corrector: cassie}\n");
  CHECK(error_of([&] { load_experiment(file); }) ==
        file.string() + ":4: stack name 'a' is already used by the stack at " + file.string() +
            ":3 (stack names must be unique)");
}

TEST_CASE("parse_override splits the key path and keeps the value text", "[config]") {
  const Override o = parse_override("stacks.0.corrector.params.delta=0.03");
  CHECK(o.path == std::vector<std::string>{"stacks", "0", "corrector", "params", "delta"});
  CHECK(o.value == "0.03");
  CHECK(parse_override("outputs.dir=a=b").value == "a=b");
  CHECK_THROWS_WITH(parse_override("outputs.dir"),
                    "command line: override 'outputs.dir' has no '=' (expected key.path=value)");
  CHECK_THROWS_AS(parse_override("=3"), ConfigError);
  CHECK_THROWS_WITH(parse_override("a..b=3"), Catch::Contains("empty key segment"));
}

TEST_CASE("overrides change values, create keys, and are located on the command line", "[config]") {
  Scratch s("overrides");
  add_recordings(s);
  const fs::path file = s.write("exp.yaml", experiment_yaml);
  const ExperimentConfig c = load_experiment(
      file, {parse_override("stacks.0.corrector.params.delta=0.03"),
             parse_override("outputs.dir=/tmp/x"), parse_override("outputs.obj=true"),
             parse_override("stacks.2.surfacer.plugin=soapfilm"),
             parse_override("stacks.1.corrector={plugin: cassie, params: {k: 2}}"),
             parse_override("experiment=renamed")});
  CHECK(c.name == "renamed");
  CHECK(c.stacks[0].corrector.params.at("delta") == ParamValue{0.03});
  CHECK(c.stacks[0].corrector.param_locations.at("delta").to_string() == "command line");
  CHECK(c.stacks[0].corrector.param_locations.at("iterations").line == 10);  // untouched
  CHECK(c.outputs.dir == "/tmp/x");
  CHECK(c.outputs.obj);
  REQUIRE(c.stacks[2].surfacer);
  CHECK(c.stacks[2].surfacer->plugin == "soapfilm");
  CHECK(c.stacks[2].surfacer->location.to_string() == "command line");
  CHECK(c.stacks[1].corrector.plugin == "cassie");
  CHECK(c.stacks[1].corrector.params.at("k") == ParamValue{std::int64_t{2}});
}

TEST_CASE("a bad override is an error naming the override", "[config]") {
  Scratch s("bad_override");
  add_recordings(s);
  const fs::path file = s.write("exp.yaml", experiment_yaml);
  CHECK(error_of([&] { load_experiment(file, {parse_override("stacks.5.name=x")}); }) ==
        "command line: override 'stacks.5.name=x': '5' is not an index of 'stacks' (allowed: 0 "
        "to 2)");
  CHECK(error_of([&] { load_experiment(file, {parse_override("stacks.first.name=x")}); }) ==
        "command line: override 'stacks.first.name=x': 'first' is not an index of 'stacks' "
        "(allowed: 0 to 2)");
  CHECK(error_of([&] { load_experiment(file, {parse_override("experiment.x=1")}); }) ==
        "command line: override 'experiment.x=1': 'experiment' is a scalar, so it has no key 'x'");
  CHECK_THAT(error_of([&] { load_experiment(file, {parse_override("outputs.dir=[a, b")}); }),
             Catch::StartsWith("command line: override 'outputs.dir=[a, b': value is not valid YAML"));
  // A well-formed override with an invalid value is reported at the command line.
  CHECK(error_of([&] { load_experiment(file, {parse_override("outputs.ply=sometimes")}); }) ==
        "command line: 'outputs.ply' must be a boolean, not 'sometimes' (allowed: true, false)");
  CHECK(error_of([&] { load_experiment(file, {parse_override("outputs.colour=red")}); }) ==
        "command line: unknown key 'colour' in the outputs (allowed: dir, sketch_json, stroke_csv, "
        "ply, obj, mlp, pictures, report, timestamp)");
}

TEST_CASE("recordings from an override are relative to the working directory", "[config]") {
  Scratch s("override_recordings");
  add_recordings(s);
  const fs::path file = s.write("sub/exp.yaml", "recordings: [x.jsonl]\nstacks: [{corrector: f}]\n");
  const fs::path cwd = fs::current_path();
  fs::current_path(s.dir);
  ExperimentConfig c;
  REQUIRE_NOTHROW(c = load_experiment(file, {parse_override("recordings=[recs/b.jsonl]")}));
  fs::current_path(cwd);
  REQUIRE(c.recordings.size() == 1);
  CHECK(c.recordings[0] == fs::absolute(s.dir / "recs/b.jsonl").lexically_normal());
}

TEST_CASE("unreadable files and invalid YAML are errors naming the file", "[config]") {
  Scratch s("unreadable");
  CHECK_THAT(error_of([&] { load_stack(s.dir / "nope.yaml"); }),
             Catch::EndsWith("nope.yaml: cannot read the file"));
  const fs::path bad = s.write("bad.yaml", "corrector: {plugin: x\nsurfacer: y\n");
  CHECK_THAT(error_of([&] { load_stack(bad); }), Catch::StartsWith(bad.string() + ":"));
  CHECK_THAT(error_of([&] { load_stack(bad); }), Catch::Contains("invalid YAML"));
}

TEST_CASE("rethrow_param_error points at the parameter's line", "[config]") {
  PluginChoice choice;
  choice.plugin = "freehand";
  choice.location = {"exp.yaml", 7};
  choice.params["delta"] = 0.5;
  choice.param_locations["delta"] = {"exp.yaml", 9};
  const std::string message =
      "parameter 'delta': 0.5 is out of range; allowed: real in [0.001, 0.2] (m)";
  CHECK(error_of([&] { rethrow_param_error(ParamError("delta", message), choice); }) ==
        "exp.yaml:9: plugin 'freehand': " + message);
  // A parameter the config did not set (e.g. added by the caller) falls back
  // to the plugin key.
  CHECK_THAT(error_of([&] { rethrow_param_error(ParamError("path", "bad path"), choice); }),
             Catch::StartsWith("exp.yaml:7: plugin 'freehand': bad path"));
}
