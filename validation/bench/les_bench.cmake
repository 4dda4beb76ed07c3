# bench_les_cost: opt-in benchmark of the subgrid-viscosity cost per time step (not a test);
# included from validation/CMakeLists.txt.
add_executable(bench_les_cost ${CMAKE_CURRENT_LIST_DIR}/les_cost.cpp)
target_link_libraries(bench_les_cost PRIVATE valsalva_validation CLI11::CLI11 fmt::fmt valsalva_warnings)
target_compile_definitions(bench_les_cost PRIVATE VALSALVA_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
# bench_sgs_kernel: one pointwise subgrid kernel call (time, or instructions under callgrind).
add_executable(bench_sgs_kernel ${CMAKE_CURRENT_LIST_DIR}/sgs_kernel.cpp)
target_link_libraries(bench_sgs_kernel PRIVATE valsalva_les CLI11::CLI11 MPI::MPI_CXX fmt::fmt valsalva_warnings)
# bench_cbc_study: one CBC decaying-turbulence run with every set-up choice open (sensitivities).
add_executable(bench_cbc_study ${CMAKE_CURRENT_LIST_DIR}/cbc_study.cpp)
target_link_libraries(bench_cbc_study PRIVATE valsalva_validation CLI11::CLI11 fmt::fmt valsalva_warnings)
target_compile_definitions(bench_cbc_study PRIVATE VALSALVA_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
