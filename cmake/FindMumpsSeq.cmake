# Finds sequential MUMPS (Debian's libmumps-seq-dev), which ships no CMake config.
# The sequential build has its own stub mpi.h in include/mumps_seq, which must come first.
find_path(MUMPS_SEQ_MPI_INCLUDE_DIR mpi.h PATH_SUFFIXES mumps_seq NO_DEFAULT_PATH PATHS /usr/include)
find_path(MUMPS_INCLUDE_DIR dmumps_c.h)
find_library(DMUMPS_SEQ_LIBRARY dmumps_seq)
find_library(MUMPS_COMMON_SEQ_LIBRARY mumps_common_seq)
find_library(MPISEQ_SEQ_LIBRARY mpiseq_seq)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MumpsSeq DEFAULT_MSG MUMPS_SEQ_MPI_INCLUDE_DIR MUMPS_INCLUDE_DIR DMUMPS_SEQ_LIBRARY MUMPS_COMMON_SEQ_LIBRARY MPISEQ_SEQ_LIBRARY)
if(MumpsSeq_FOUND AND NOT TARGET Mumps::dmumps_seq)
  add_library(Mumps::dmumps_seq INTERFACE IMPORTED)
  target_include_directories(Mumps::dmumps_seq INTERFACE ${MUMPS_SEQ_MPI_INCLUDE_DIR} ${MUMPS_INCLUDE_DIR})
  target_link_libraries(Mumps::dmumps_seq INTERFACE ${DMUMPS_SEQ_LIBRARY} ${MUMPS_COMMON_SEQ_LIBRARY} ${MPISEQ_SEQ_LIBRARY})
endif()
