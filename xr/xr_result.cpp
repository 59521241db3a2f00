#include "xr_result.hpp"

#include <openxr/openxr_reflection.h>

namespace sketchlab::openxr {

std::string result_name(XrResult result) {
  switch (result) {
#define SKETCHLAB_XR_RESULT_CASE(name, value) \
  case name: return #name;
    XR_LIST_ENUM_XrResult(SKETCHLAB_XR_RESULT_CASE)
#undef SKETCHLAB_XR_RESULT_CASE
    default: return "XrResult " + std::to_string(static_cast<int>(result));
  }
}

}  // namespace sketchlab::openxr
