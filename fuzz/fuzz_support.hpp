#pragma once
// What the harnesses share: files for the parsers that read paths, a reader
// of the fuzzer's bytes as numbers, and the one way a harness reports a
// broken property (abort, so libFuzzer saves the input as a crash).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>
#include <utility>

#include "sketchlab/io/warning.hpp"

namespace sketchlab::fuzz {

// A property every input must keep does not hold: print it and abort.
[[noreturn]] inline void broken(const std::string& what) {
  std::fprintf(stderr, "fuzz property broken: %s\n", what.c_str());
  std::abort();
}

// Warnings are expected (partial last lines...): keep the fuzzer's output
// readable.
inline void silence_warnings() {
  static const bool done = [] {
    set_warning_sink([](const std::string&) {});
    return true;
  }();
  (void)done;
}

// <tmp>/sketchlab-fuzz-<pid>: the process's own directory, so parallel
// fuzzing jobs do not meet.
inline const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::temp_directory_path() / ("sketchlab-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

// scratch_dir()/<name> (subdirectories made as needed) holding `text`.
inline std::filesystem::path write_file(const std::string& name, std::string_view text) {
  const auto path = scratch_dir() / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(text.data(), static_cast<std::streamsize>(text.size()));
  return path;
}

// A CASSIE session as one input: the sketch_history JSON, a line "#raw#",
// then the raw_data JSON ("{}" without that line).
inline std::pair<std::string_view, std::string_view> cassie_halves(std::string_view text) {
  const std::string_view separator = "\n#raw#\n";
  const auto cut = text.find(separator);
  if (cut == std::string_view::npos) return {text, "{}"};
  return {text.substr(0, cut), text.substr(cut + separator.size())};
}

// The fuzzer's bytes read front to back as small numbers; zeros once used up.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return pos_ >= size_; }
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  bool flag() { return byte() & 1; }
  // Mostly ordinary values in [-range, range], sometimes the awkward ones.
  double number(double range) {
    const std::uint8_t kind = byte();
    switch (kind % 16) {
      case 0: return std::numeric_limits<double>::quiet_NaN();
      case 1: return std::numeric_limits<double>::infinity();
      case 2: return 1e300 * (kind & 16 ? -1 : 1);
      case 3: return 5e-324;
      case 4: return 0.0;
      default: {
        const std::uint16_t v = static_cast<std::uint16_t>(byte() | (byte() << 8));
        return range * (static_cast<double>(v) / 32767.5 - 1.0);
      }
    }
  }
  std::string_view rest() {
    const std::string_view r(reinterpret_cast<const char*>(data_ + pos_), size_ - std::min(pos_, size_));
    pos_ = size_;
    return r;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace sketchlab::fuzz
