# libvalsalva_mpi_counts.so: the MPI call counter of the scaling study (LD_PRELOAD, not linked
# into anything); included from validation/CMakeLists.txt.
add_library(valsalva_mpi_counts SHARED ${CMAKE_CURRENT_LIST_DIR}/mpi_counts.c)
target_link_libraries(valsalva_mpi_counts PRIVATE MPI::MPI_C)
set_target_properties(valsalva_mpi_counts PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/lib)
