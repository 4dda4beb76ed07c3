# bench_output_cost: opt-in benchmark of statistics, probes, field and checkpoint output cost per
# time step and of the statistics memory (not a test); included from validation/CMakeLists.txt.
add_executable(bench_output_cost ${CMAKE_CURRENT_LIST_DIR}/output_cost.cpp)
target_link_libraries(bench_output_cost PRIVATE valsalva_validation CLI11::CLI11 MPI::MPI_CXX fmt::fmt
  valsalva_warnings)
