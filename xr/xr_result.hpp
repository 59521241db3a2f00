#pragma once
// OpenXR results as readable errors.
#include <openxr/openxr.h>

#include <stdexcept>
#include <string>

namespace sketchlab::openxr {

// "XR_ERROR_FORM_FACTOR_UNAVAILABLE" (or the number for unknown values).
std::string result_name(XrResult result);

struct XrError : std::runtime_error {
  XrError(XrResult r, const std::string& what) : std::runtime_error(what), result(r) {}
  XrResult result;
};

// Throws XrError("<call> failed: <result name>") when XR_FAILED(result).
inline void check(XrResult result, const char* call) {
  if (XR_FAILED(result)) throw XrError(result, std::string(call) + " failed: " + result_name(result));
}

}  // namespace sketchlab::openxr
