// Items of work shared out among the processes of one mpiexec job: a counter on rank 0 that every rank fetches and
// increments (one-sided MPI), so that a rank that finishes early takes the next item. One process counts alone.
#pragma once
#include <vector>

namespace strandfem {

// This process's rank in its mpiexec job (0 without MPI, or when MPI has not started).
int process_rank();

class ProcessQueue {
 public:
  // Collective over every process of the job when MPI runs: each must make its queue of the same items together.
  explicit ProcessQueue(int items);
  ~ProcessQueue();
  ProcessQueue(const ProcessQueue&) = delete;
  ProcessQueue& operator=(const ProcessQueue&) = delete;
  // The next item no process has taken, or -1 once all are taken.
  int next();
  // Collective: each entry's largest value over the processes, which fill the entries of their own items and leave
  // the others at the lowest int.
  std::vector<int> largest(std::vector<int> values) const;
  int rank() const { return rank_; }
  int processes() const { return processes_; }

 private:
  int items_ = 0;
  int taken_ = 0;  // one process alone
  int rank_ = 0;
  int processes_ = 1;
  void* window_ = nullptr;   // MPI_Win, when MPI runs
  int* counter_ = nullptr;   // its memory on this rank
};

}  // namespace strandfem
