// The processes MUMPS factors on: one, or with the MPI build of MUMPS under `mpirun -np N`, rank 0 (which runs the
// analysis) and N - 1 ranks that serve its MUMPS calls.
#pragma once
#include <string>

namespace strandfem {

// Held by main() for the whole run. Under mpiexec it starts MPI (where the library has it) and ends it; on rank 0
// its destructor first releases the serving ranks. With more than one process every process runs one BLAS thread, since the
// processes are what use the cores in a factorization.
class MumpsProcesses {
 public:
  // each_alone: every process solves models of its own and factors them within itself (`strandfem sweep`, whose
  // processes take variants from a ProcessQueue); no rank serves another.
  MumpsProcesses(int& argc, char**& argv, bool each_alone = false);
  ~MumpsProcesses();
  MumpsProcesses(const MumpsProcesses&) = delete;
  MumpsProcesses& operator=(const MumpsProcesses&) = delete;
  int rank() const { return rank_; }
  int count() const { return count_; }
  // Whether ranks above 0 serve rank 0's MUMPS calls (more than one process, not each alone).
  bool serving() const { return serving_; }
  // On ranks above 0: takes part in every MUMPS call rank 0 makes until rank 0 releases it; returns the exit code.
  int serve();

 private:
  int rank_ = 0;
  int count_ = 1;
  bool serving_ = false;
  bool started_mpi_ = false;
};

// Number of processes the factorizations run on (1 without the MPI build or without mpirun).
int mumps_process_count();
// Every factorization of this process stays in it (MPI_COMM_SELF), whatever else runs under MPI: for the Python
// package, whose sweeps hand variants to MPI ranks (mpi4py) that each solve their own model. Process-wide, as MPI is.
void factor_within_this_process();
// Which MUMPS the library was built on: "MPI (<library version>)" or "sequential".
std::string mumps_build();

}  // namespace strandfem
