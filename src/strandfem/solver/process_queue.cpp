#include "strandfem/solver/process_queue.hpp"

#include <stdexcept>

#ifdef STRANDFEM_MUMPS_MPI
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace strandfem {

int process_rank() {
  int rank = 0;
#ifdef STRANDFEM_MUMPS_MPI
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
#endif
  return rank;
}

ProcessQueue::ProcessQueue(int items) : items_(items) {
#ifdef STRANDFEM_MUMPS_MPI
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) return;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &processes_);
  if (processes_ == 1) return;
  auto* window = new MPI_Win;
  const MPI_Aint bytes = rank_ == 0 ? static_cast<MPI_Aint>(sizeof(int)) : 0;
  if (MPI_Win_allocate(bytes, sizeof(int), MPI_INFO_NULL, MPI_COMM_WORLD, &counter_, window) != MPI_SUCCESS) {
    delete window;
    throw std::runtime_error("MPI could not share the sweep's variants among its processes");
  }
  window_ = window;
  if (rank_ == 0) {
    MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, *window);
    *counter_ = 0;
    MPI_Win_unlock(0, *window);
  }
  MPI_Barrier(MPI_COMM_WORLD);
#endif
}

ProcessQueue::~ProcessQueue() {
#ifdef STRANDFEM_MUMPS_MPI
  if (auto* window = static_cast<MPI_Win*>(window_)) {
    MPI_Win_free(window);
    delete window;
  }
#endif
}

int ProcessQueue::next() {
  int item = taken_;
#ifdef STRANDFEM_MUMPS_MPI
  if (auto* window = static_cast<MPI_Win*>(window_)) {
    const int one = 1;
    MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, *window);
    MPI_Fetch_and_op(&one, &item, MPI_INT, 0, 0, MPI_SUM, *window);
    MPI_Win_unlock(0, *window);
  } else {
    ++taken_;
  }
#else
  ++taken_;
#endif
  return item < items_ ? item : -1;
}

std::vector<int> ProcessQueue::largest(std::vector<int> values) const {
#ifdef STRANDFEM_MUMPS_MPI
  if (window_)
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
#endif
  return values;
}

}  // namespace strandfem
