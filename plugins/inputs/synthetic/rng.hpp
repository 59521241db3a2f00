#pragma once
// A seeded random source whose output is the same on every platform: the
// engine is std::mt19937_64 (fully specified by the standard) and the
// distributions are computed here, because std::*_distribution differ
// between standard libraries.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace sketchlab::synthetic {

// SplitMix64 finaliser: decorrelates seeds derived from (seed, index).
inline std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (index + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  // Standard normal (Box–Muller; the second value is discarded so the stream
  // position does not depend on call history).
  double normal() {
    const double u1 = 1.0 - uniform();  // (0, 1]
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  double normal(double sigma) { return sigma * normal(); }
  bool bernoulli(double p) { return uniform() < p; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace sketchlab::synthetic
