# bench_structure_forces: opt-in benchmark of the structure module (not a test); included from
# validation/CMakeLists.txt.
add_executable(bench_structure_forces ${CMAKE_CURRENT_LIST_DIR}/structure_forces.cpp)
target_link_libraries(bench_structure_forces PRIVATE valsalva_structure valsalva_validation CLI11::CLI11 fmt::fmt valsalva_warnings)
