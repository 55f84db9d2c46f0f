# Settings every rig runner shares (gt-harness, gt-compute): C++17, Release by default, the Vulkan
# setup library, and a binary whose only runtime dependency is the Vulkan loader.
# include() it from a runner's CMakeLists.txt, then gt_rig_tool(TARGET) after add_executable.
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)
if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release)
endif()

find_package(Vulkan REQUIRED)
if(NOT TARGET gt-vkcommon)
  add_subdirectory(${CMAKE_CURRENT_LIST_DIR} ${CMAKE_CURRENT_BINARY_DIR}/vkcommon)
endif()

function(gt_rig_tool target)
  target_link_libraries(${target} PRIVATE gt-vkcommon Vulkan::Vulkan)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-missing-field-initializers)  # {sType} then zero: intended
  # libstdc++/libgcc statically: the binary may be carried to a machine with another C++ runtime.
  target_link_options(${target} PRIVATE -static-libstdc++ -static-libgcc)
endfunction()
