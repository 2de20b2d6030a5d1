# Finds the MPI build of MUMPS (Debian's libmumps-dev, on Open MPI), which ships no CMake config.
find_package(MPI COMPONENTS C QUIET)
find_path(MUMPS_MPI_INCLUDE_DIR dmumps_c.h)
find_library(DMUMPS_MPI_LIBRARY dmumps)
find_library(SMUMPS_MPI_LIBRARY smumps)
find_library(MUMPS_COMMON_MPI_LIBRARY mumps_common)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MumpsMpi DEFAULT_MSG MPI_C_FOUND MUMPS_MPI_INCLUDE_DIR DMUMPS_MPI_LIBRARY SMUMPS_MPI_LIBRARY
                                  MUMPS_COMMON_MPI_LIBRARY)
if(MumpsMpi_FOUND AND NOT TARGET Mumps::mumps_mpi)
  add_library(Mumps::mumps_mpi INTERFACE IMPORTED)
  target_include_directories(Mumps::mumps_mpi INTERFACE ${MUMPS_MPI_INCLUDE_DIR})
  target_link_libraries(Mumps::mumps_mpi INTERFACE ${DMUMPS_MPI_LIBRARY} ${SMUMPS_MPI_LIBRARY} ${MUMPS_COMMON_MPI_LIBRARY} MPI::MPI_C)
endif()
