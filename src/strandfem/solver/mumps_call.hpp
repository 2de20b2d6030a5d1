// A MUMPS call made by rank 0, which the serving ranks (mumps_processes.hpp) make with it.
#pragma once
#include <dmumps_c.h>
#include <smumps_c.h>

namespace strandfem {

// MUMPS' Fortran communicator: MPI_COMM_WORLD's (MPI is started here when nobody did, as in tests and benchmarks),
// or the sequential build's placeholder.
int mumps_communicator();
// Tells the serving ranks to make this call (with the host's JOB, PAR, SYM, ICNTL and CNTL), then makes it.
void mumps_call(DMUMPS_STRUC_C& id);
void mumps_call(SMUMPS_STRUC_C& id);

}  // namespace strandfem
