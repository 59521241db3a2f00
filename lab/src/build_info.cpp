#include "sketchlab/lab/build_info.hpp"

#include "sketchlab/version.hpp"

namespace sketchlab {

BuildInfo build_info() {
  BuildInfo b;
  b.version = SKETCHLAB_KERNEL_VERSION;
  b.git_commit = lab_detail::git_commit();
  b.fingerprint = build_fingerprint();
  b.build_type = lab_detail::build_type();
  b.compiler = lab_detail::compiler();
  b.flags = lab_detail::compile_flags();
  return b;
}

}  // namespace sketchlab
