#include <catch2/catch.hpp>

#include <fstream>

#include "cli_helpers.hpp"
#include "sketchlab/lab/file_hash.hpp"

using namespace sketchlab;
namespace fs = std::filesystem;

TEST_CASE("hash_file gives the SHA-256 of the file's bytes", "[lab][provenance]") {
  const fs::path dir = test::fresh_dir("file_hash");
  std::ofstream(dir / "abc", std::ios::binary) << "abc";
  std::ofstream(dir / "empty", std::ios::binary);
  // FIPS 180-4 examples (the one-block message "abc"; the empty message).
  const FileHash abc = hash_file(dir / "abc");
  CHECK(abc.sha256 == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(abc.bytes == 3);
  CHECK(hash_file(dir / "empty").sha256 == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  // Larger than the read buffer: the same bytes give the same hash, one more byte another.
  std::string big(200000, 'x');
  std::ofstream(dir / "big", std::ios::binary) << big;
  std::ofstream(dir / "big2", std::ios::binary) << big << 'x';
  CHECK(hash_file(dir / "big").bytes == 200000);
  CHECK(hash_file(dir / "big").sha256 != hash_file(dir / "big2").sha256);
  CHECK_THROWS_WITH(hash_file(dir / "missing"), Catch::Contains((dir / "missing").string()));
}
