# bench_ibm_transfer_cost: opt-in benchmark of the immersed-boundary transfer cost per marker and
# its share of a coupled step (not a test); included from validation/CMakeLists.txt.
add_executable(bench_ibm_transfer_cost ${CMAKE_CURRENT_LIST_DIR}/ibm_transfer_cost.cpp)
target_link_libraries(bench_ibm_transfer_cost PRIVATE valsalva_validation CLI11::CLI11 fmt::fmt valsalva_warnings)
