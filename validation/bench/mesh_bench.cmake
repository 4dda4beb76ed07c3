# bench_mesh_pipeline: opt-in benchmark of mesh read, metrics and partition (not a test).
add_executable(bench_mesh_pipeline ${CMAKE_CURRENT_LIST_DIR}/mesh_pipeline.cpp)
target_link_libraries(bench_mesh_pipeline PRIVATE valsalva_io valsalva_flow valsalva::gmsh CLI11::CLI11
  fmt::fmt MPI::MPI_CXX valsalva_warnings)
