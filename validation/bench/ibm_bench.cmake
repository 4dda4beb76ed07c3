# bench_ibm_transfer_cost: opt-in benchmark of the immersed-boundary transfer cost per marker and
# its share of a coupled step (not a test); included from validation/CMakeLists.txt.
add_executable(bench_ibm_transfer_cost ${CMAKE_CURRENT_LIST_DIR}/ibm_transfer_cost.cpp)
target_link_libraries(bench_ibm_transfer_cost PRIVATE valsalva_validation CLI11::CLI11 fmt::fmt valsalva_warnings)

# bench_marker_reuse: opt-in benchmark of immersed.reuse_distance on a scene (not a test).
add_executable(bench_marker_reuse ${CMAKE_CURRENT_LIST_DIR}/marker_reuse.cpp)
target_link_libraries(bench_marker_reuse PRIVATE valsalva_validation CLI11::CLI11 fmt::fmt valsalva_warnings)

# bench_contact_cost: opt-in benchmark of the leaflet contact in a valve scene (not a test).
add_executable(bench_contact_cost ${CMAKE_CURRENT_LIST_DIR}/contact_cost.cpp)
target_link_libraries(bench_contact_cost PRIVATE valsalva_validation CLI11::CLI11 fmt::fmt valsalva_warnings)
