#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "cli_helpers.hpp"
#include "sketchlab/lab/run_folder.hpp"

using namespace sketchlab;
namespace fs = std::filesystem;

TEST_CASE("create_unique_folder never reuses a name that exists", "[lab][run_folder]") {
  const fs::path dir = test::fresh_dir("run_folder_names");
  CHECK(create_unique_folder(dir / "runs", "exp") == dir / "runs/exp");
  CHECK(create_unique_folder(dir / "runs", "exp") == dir / "runs/exp-2");
  std::ofstream(dir / "runs/exp-3") << "a file, not to be touched\n";
  CHECK(create_unique_folder(dir / "runs", "exp") == dir / "runs/exp-4");
  CHECK(fs::is_regular_file(dir / "runs/exp-3"));
}

TEST_CASE("concurrent callers asking for one name get distinct folders", "[lab][run_folder]") {
  const fs::path dir = test::fresh_dir("run_folder_race");
  std::mutex m;
  std::set<fs::path> got;
  std::vector<std::thread> threads;
  for (int i = 0; i < 8; ++i)
    threads.emplace_back([&] {
      const fs::path p = create_unique_folder(dir, "exp-20261202-081500");
      std::lock_guard lock(m);
      got.insert(p);
    });
  for (auto& t : threads) t.join();
  CHECK(got.size() == 8);
  for (const auto& p : got) CHECK(fs::is_directory(p));
}

TEST_CASE("create_unique_folder names the folder it cannot create", "[lab][run_folder]") {
  const fs::path dir = test::fresh_dir("run_folder_error");
  std::ofstream(dir / "plain") << "x";
  CHECK_THROWS_WITH(create_unique_folder(dir / "plain" / "runs", "exp"),
                    Catch::Contains((dir / "plain" / "runs").string()));
}
