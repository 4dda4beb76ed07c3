# bench_womersley_study: one inlet-driven (or periodic) Womersley pipe run with the set-up
# choices open, and the edge lengths of the pipe meshes (a study tool, not a test).
add_executable(bench_womersley_study ${CMAKE_CURRENT_LIST_DIR}/womersley_study.cpp
  ${CMAKE_CURRENT_LIST_DIR}/womersley_run.cpp)
target_link_libraries(bench_womersley_study PRIVATE valsalva_validation CLI11::CLI11 fmt::fmt valsalva_warnings)
