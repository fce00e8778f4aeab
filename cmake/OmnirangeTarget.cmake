# omnirange_target_defaults(<target>): C++17 and the warnings every target is built with.
function(omnirange_target_defaults target)
  target_compile_features(${target} PUBLIC cxx_std_17)
  set_target_properties(${target} PROPERTIES CXX_EXTENSIONS OFF)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()
