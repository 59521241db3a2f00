#pragma once
// Content hashes of input files, for provenance: a run records what exactly
// it read.
#include <cstdint>
#include <filesystem>
#include <string>

namespace sketchlab {

struct FileHash {
  std::uintmax_t bytes = 0;
  std::string sha256;  // 64 lowercase hex digits
};

// SHA-256 (FIPS 180-4, through OpenSSL's EVP) of the whole file. Throws
// std::runtime_error naming the file when it cannot be read.
FileHash hash_file(const std::filesystem::path& file);

}  // namespace sketchlab
