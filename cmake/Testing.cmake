# valsalva_add_test(NAME SOURCES s.cpp... LIBS lib... LABELS quick|validation NP 1 [2 3])
# Builds one doctest executable (MPI-aware main in tests/test_main.cpp) and registers one CTest
# test per rank count; rank counts above 1 run through mpiexec and get the label "mpi".
# Binding off: Open MPI binds each rank to a core by default (2 ranks or fewer), and every mpiexec
# of a `ctest -j` run starts at core 0, so two 1-rank tests side by side shared core 0 while core
# 1 stayed idle (taskset showed both validate runs on core 0).
set(VALSALVA_MPIEXEC_ENV "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1;OMPI_MCA_hwloc_base_binding_policy=none")
function(valsalva_add_test NAME)
  cmake_parse_arguments(T "" "TIMEOUT" "SOURCES;LIBS;LABELS;NP" ${ARGN})
  if(NOT T_NP)
    set(T_NP 1)
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 600)
  endif()
  add_executable(${NAME} ${T_SOURCES} ${PROJECT_SOURCE_DIR}/tests/test_main.cpp)
  target_link_libraries(${NAME} PRIVATE ${T_LIBS} doctest::doctest MPI::MPI_CXX valsalva_warnings)
  target_compile_definitions(${NAME} PRIVATE VALSALVA_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  set_target_properties(${NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  foreach(np IN LISTS T_NP)
    set(labels ${T_LABELS})
    if(np GREATER 1)
      list(APPEND labels mpi)
      add_test(NAME ${NAME}_np${np}
        COMMAND ${MPIEXEC_EXECUTABLE} --oversubscribe ${MPIEXEC_NUMPROC_FLAG} ${np} $<TARGET_FILE:${NAME}>)
    else()
      add_test(NAME ${NAME}_np${np} COMMAND $<TARGET_FILE:${NAME}>)
    endif()
    set_tests_properties(${NAME}_np${np} PROPERTIES LABELS "${labels}" TIMEOUT ${T_TIMEOUT}
      PROCESSORS ${np} ENVIRONMENT "${VALSALVA_MPIEXEC_ENV}" WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  endforeach()
endfunction()

# valsalva_reserve_rank_slots(): for every test of the calling directory, PROCESSORS = the ranks
# it runs on, so that `ctest -j N` counts them. Ranks from the name (the largest of its "npK",
# e.g. cli_restart_np1_to_np2: 2), at least 2 for a test labelled "mpi". Why: Open MPI's ranks
# busy-wait and do not know that another test shares the cores, so a 2-rank test run beside
# another test on a 2-core machine ran 2-3 times slower than alone (validate_poiseuille_pipe_quick:
# 95 s at 1 rank, 247 s at 2 in the same `ctest -j2`).
function(valsalva_reserve_rank_slots)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(test IN LISTS tests)
    string(REGEX MATCHALL "np[0-9]+" counts "${test}")
    set(ranks 1)
    foreach(count IN LISTS counts)
      string(SUBSTRING "${count}" 2 -1 n)
      if(n GREATER ranks)
        set(ranks ${n})
      endif()
    endforeach()
    get_test_property(${test} LABELS labels)
    if("mpi" IN_LIST labels AND ranks LESS 2)
      set(ranks 2)
    endif()
    if(ranks GREATER 1)
      set_tests_properties(${test} PROPERTIES PROCESSORS ${ranks})
    endif()
  endforeach()
endfunction()
