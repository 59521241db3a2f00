#pragma once
// Kernel version and the build fingerprint plugins must match: compiler,
// standard library, build type and kernel version. Two builds with equal
// fingerprints can pass C++ objects (std::string, std::vector, Eigen) across
// the plugin boundary.
#include <version>  // defines the standard library macros tested below

#define SKETCHLAB_KERNEL_VERSION "0.1.0"

#define SKETCHLAB_STR_(x) #x
#define SKETCHLAB_STR(x) SKETCHLAB_STR_(x)

#if defined(__clang__)
#define SKETCHLAB_COMPILER "clang-" SKETCHLAB_STR(__clang_major__) "." SKETCHLAB_STR(__clang_minor__)
#elif defined(__GNUC__)
#define SKETCHLAB_COMPILER "gcc-" SKETCHLAB_STR(__GNUC__) "." SKETCHLAB_STR(__GNUC_MINOR__)
#else
#define SKETCHLAB_COMPILER "unknown-compiler"
#endif

#if defined(_GLIBCXX_RELEASE)
#define SKETCHLAB_STDLIB "libstdc++-" SKETCHLAB_STR(_GLIBCXX_RELEASE)
#elif defined(_LIBCPP_VERSION)
#define SKETCHLAB_STDLIB "libc++-" SKETCHLAB_STR(_LIBCPP_VERSION)
#else
#define SKETCHLAB_STDLIB "unknown-stdlib"
#endif

// SKETCHLAB_BUILD_TYPE ("Release", "Debug+asan+ubsan", ...): CMake sets it
// for every target of the sketchlab build; code built against an installed
// sketchlab (out-of-tree plugins) gets the host's value from the configured
// header installed with the kernel (cmake/build_config.hpp.in), so its
// fingerprint matches the installed host without hand-set flags.
#ifndef SKETCHLAB_BUILD_TYPE
#include "sketchlab/build_config.hpp"
#endif

#define SKETCHLAB_BUILD_FINGERPRINT                                                  \
  "sketchlab-" SKETCHLAB_KERNEL_VERSION ";" SKETCHLAB_COMPILER ";" SKETCHLAB_STDLIB \
  ";" SKETCHLAB_BUILD_TYPE

namespace sketchlab {
// The host's fingerprint (compiled into the kernel library).
const char* build_fingerprint();
}  // namespace sketchlab
