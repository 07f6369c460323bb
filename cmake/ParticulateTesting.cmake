# Helpers shared by all test folders.
#
# particulate_add_test(NAME <name> SOURCES <files...> LIBRARIES <targets...>
#                      LABELS <labels...> [ARGS <args...>] [MPI <ranks>]
#                      [TIMEOUT <seconds>] [DEALII])
# builds one executable per test and registers it with CTest. Labels follow
# the GUIDE: unit, regression, mpi, validation, performance, gpu. A test that
# exits with 77 is reported as skipped (used by the gpu tests on machines
# without a device).
function(particulate_add_test)
  cmake_parse_arguments(T "DEALII" "NAME;MPI;TIMEOUT"
    "SOURCES;LIBRARIES;LABELS;ARGS" ${ARGN})
  add_executable(${T_NAME} ${T_SOURCES})
  # plain signature: deal_ii_setup_target() uses it too
  target_link_libraries(${T_NAME} ${T_LIBRARIES})
  if(T_DEALII)
    deal_ii_setup_target(${T_NAME})
  endif()
  if(T_MPI)
    set(_cmd ${DEAL_II_MPIEXEC} ${DEAL_II_MPIEXEC_NUMPROC_FLAG} ${T_MPI}
      ${DEAL_II_MPIEXEC_PREFLAGS} $<TARGET_FILE:${T_NAME}>
      ${DEAL_II_MPIEXEC_POSTFLAGS})
  else()
    set(_cmd $<TARGET_FILE:${T_NAME}>)
  endif()
  add_test(NAME ${T_NAME} COMMAND ${_cmd} ${T_ARGS}
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(${T_NAME} PROPERTIES
    LABELS "${T_LABELS}" SKIP_RETURN_CODE 77
    ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1;PARTICULATE_SOURCE_DIR=${PROJECT_SOURCE_DIR};PARTICULATE_CGAL_DATA_DIR=${PARTICULATE_CGAL_DATA_DIR}")
  if(T_MPI)
    set_tests_properties(${T_NAME} PROPERTIES PROCESSORS ${T_MPI})
  endif()
  if(T_TIMEOUT)
    set_tests_properties(${T_NAME} PROPERTIES TIMEOUT ${T_TIMEOUT})
  endif()
endfunction()
