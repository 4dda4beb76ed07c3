# bench_tgv_re1600: opt-in benchmark of the flow solver (not a test); included from
# validation/CMakeLists.txt.
add_executable(bench_tgv_re1600 ${CMAKE_CURRENT_LIST_DIR}/tgv_re1600.cpp)
target_link_libraries(bench_tgv_re1600 PRIVATE valsalva_validation CLI11::CLI11 MPI::MPI_CXX fmt::fmt
  valsalva_warnings)
# bench_taylor_green_study: one 2D Taylor-Green run with the discretisation choices open (a
# study tool, not a test).
add_executable(bench_taylor_green_study ${CMAKE_CURRENT_LIST_DIR}/taylor_green_study.cpp)
target_link_libraries(bench_taylor_green_study PRIVATE valsalva_validation CLI11::CLI11 fmt::fmt
  valsalva_warnings)
