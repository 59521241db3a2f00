# sketchlab_warnings(TARGET): warnings on for project code (not third-party
# headers, which are included as SYSTEM by their imported targets).
function(sketchlab_warnings target)
  # -Wno-restrict: GCC 12 reports false positives inside libstdc++'s
  # std::string at -O2 (GCC bug 105651).
  # (clang, for the fuzzing build, has neither -Wshadow=local nor -Wrestrict;
  # the order keeps GCC's command lines, hence ccache's hits, unchanged.)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic $<$<CXX_COMPILER_ID:GNU>:-Wshadow=local>
                                           -Wno-missing-field-initializers $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)
endfunction()
