# sketchlab_warnings(TARGET): warnings on for project code (not third-party
# headers, which are included as SYSTEM by their imported targets).
function(sketchlab_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow=local
                                           -Wno-missing-field-initializers)
endfunction()
