# sketchlab_warnings(TARGET): warnings on for project code (not third-party
# headers, which are included as SYSTEM by their imported targets).
function(sketchlab_warnings target)
  # -Wno-restrict: GCC 12 reports false positives inside libstdc++'s
  # std::string at -O2 (GCC bug 105651).
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow=local
                                           -Wno-missing-field-initializers -Wno-restrict)
endfunction()
