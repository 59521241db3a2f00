// Same seed, same bytes; the bundled recordings regenerate exactly.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

#include "synthetic_params.hpp"
#include "synthetic_test_support.hpp"
#include "test_paths.hpp"

using namespace sketchlab;
using namespace sketchlab::synthetic;

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  REQUIRE(in.good());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::filesystem::path scratch_dir() {
  const std::filesystem::path dir = sketchlab::test::binary_path("tests/scratch/synthetic_cli");
  std::filesystem::create_directories(dir);
  return dir;
}

int run_cli(const std::string& args) {
  const std::string cmd = std::string("\"") + SKETCHLAB_CLI + "\" " + args + " > /dev/null";
  return std::system(cmd.c_str());
}

}  // namespace

TEST_CASE("the same seed gives byte-identical recordings, other seeds differ", "[synthetic][determinism]") {
  for (Modality m : {Modality::vr, Modality::tablet}) {
    SynthesisParams p;
    p.model = "chair";
    p.modality = m;
    p.seed = 3;
    const std::string a = support::to_text(synthesize_session(p));
    const std::string b = support::to_text(synthesize_session(p));
    CHECK(a == b);
    p.seed = 4;
    const std::string c = support::to_text(synthesize_session(p));
    CHECK(a != c);
    // Only the samples and timing differ: the ground truth is the same.
    CHECK(support::relations(synthesize_session(p)).size() ==
          support::relations(synthesize_session(SynthesisParams{p.model, "", p.size, 3, m})).size());
  }
}

TEST_CASE("command-line text converts to each parameter's type", "[synthetic][params]") {
  const auto specs = synthetic_param_specs();
  auto spec = [&](const std::string& name) {
    for (const auto& s : specs) if (s.name == name) return s;
    FAIL("no spec " << name);
    return ParamSpec{};
  };
  CHECK(parse_param_value(spec("seed"), "42") == ParamValue(std::int64_t{42}));
  CHECK(parse_param_value(spec("seed"), "+7") == ParamValue(std::int64_t{7}));
  CHECK(parse_param_value(spec("noise"), "0.5") == ParamValue(0.5));
  CHECK(parse_param_value(spec("noise"), "2") == ParamValue(2.0));
  CHECK(parse_param_value(spec("noise"), "1e-1") == ParamValue(0.1));
  CHECK(parse_param_value(spec("model"), "mug") == ParamValue(std::string("mug")));
  CHECK(parse_param_value(spec("mesh"), "a b.off") == ParamValue(std::string("a b.off")));
  ParamSpec flag{"flag", ParamType::boolean, false, {}, {}, {}, "", ""};
  CHECK(parse_param_value(flag, "true") == ParamValue(true));
  CHECK(parse_param_value(flag, "0") == ParamValue(false));
  CHECK_THROWS_WITH(parse_param_value(flag, "maybe"), Catch::Contains("'flag'") && Catch::Contains("true or false"));
  CHECK_THROWS_WITH(parse_param_value(spec("seed"), "1.5"), Catch::Contains("not an integer"));
  CHECK_THROWS_WITH(parse_param_value(spec("seed"), "-1"), Catch::Contains("out of range"));
  CHECK_THROWS_WITH(parse_param_value(spec("noise"), "lots"), Catch::Contains("not a number"));
  CHECK_THROWS_WITH(parse_param_value(spec("noise"), ""), Catch::Contains("not a number"));
  CHECK_THROWS_WITH(parse_param_value(spec("noise"), "11"), Catch::Contains("real in [0, 10]"));
  CHECK_THROWS_WITH(parse_param_value(spec("model"), "teapot"), Catch::Contains("not a choice") &&
                                                                   Catch::Contains("cube, rounded_box, mug"));
  CHECK_THROWS_AS(parse_param_value(spec("noise"), "0.5x"), ParamError);
}

TEST_CASE("record and synth write the same file through the plugin", "[synthetic][cli]") {
  const auto dir = scratch_dir();
  const auto a = dir / "record_cube.jsonl", b = dir / "synth_cube.jsonl";
  REQUIRE(run_cli("record --input synthetic --param model=cube --param seed=3 --param noise=0.5 -o \"" +
                  a.string() + "\" --overwrite") == 0);
  REQUIRE(run_cli("synth cube --seed 3 --noise 0.5 -o \"" + b.string() + "\" --overwrite") == 0);
  CHECK(slurp(a) == slurp(b));
  SynthesisParams p;
  p.seed = 3;
  p.noise = 0.5;
  CHECK(slurp(a) == support::to_text(synthesize_session(p)));
  // Existing files are kept unless --overwrite; bad parameters are errors.
  CHECK(run_cli("synth cube -o \"" + b.string() + "\" 2> /dev/null") != 0);
  CHECK(run_cli("synth cube --param vr_jitter=lots -o \"" + (dir / "x.jsonl").string() + "\" 2> /dev/null") != 0);
  CHECK(run_cli("record --input synthetic --param colour=red -o \"" + (dir / "y.jsonl").string() + "\" 2> /dev/null") != 0);
  CHECK_FALSE(std::filesystem::exists(dir / "x.jsonl"));
}

TEST_CASE("the bundled synthetic recordings regenerate byte for byte", "[synthetic][cli][data]") {
  const auto dir = scratch_dir();
  // data/synthetic/*.jsonl are VR sessions, data/synthetic/tablet/*.jsonl 2D
  // ones, MODEL_STYLE.jsonl drawn in the analytic (construction.hpp) and
  // JustDrawIt (multi_view.hpp) styles.
  struct Bundled {
    std::string file, args;
  };
  std::vector<Bundled> bundled;
  for (const std::string model : {"cube", "mug"}) bundled.push_back({model + ".jsonl", model});
  for (const std::string model : {"cube", "mug", "chair", "lamp"}) {
    bundled.push_back({"tablet/" + model + ".jsonl", model + " --modality tablet"});
    for (const std::string style : {"analytic", "justdrawit"})
      bundled.push_back({"tablet/" + model + "_" + style + ".jsonl", model + " --modality tablet --param style=" + style});
  }
  for (const Bundled& b : bundled) {
    INFO(b.file);
    const std::filesystem::path path = sketchlab::test::source_path("data/synthetic/" + b.file);
    REQUIRE(std::filesystem::exists(path));
    CHECK(std::filesystem::file_size(path) < 1000000);
    const auto out = dir / std::filesystem::path(b.file).filename();
    REQUIRE(run_cli("synth " + b.args + " --seed 1 -o \"" + out.string() + "\" --overwrite") == 0);
    CHECK(slurp(out) == slurp(path));
  }
}
