#include "strandfem/solver/mumps_processes.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <thread>
#include <type_traits>

#include "strandfem/solver/mumps_call.hpp"

#ifdef STRANDFEM_MUMPS_MPI
#define OMPI_SKIP_MPICXX 1  // the C interface only: the C++ bindings would need their own library
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace strandfem {
namespace {

constexpr int kSequentialCommunicator = -987654;  // the sequential build's stand-in for a Fortran communicator

#ifdef STRANDFEM_MUMPS_MPI
// What rank 0 sends before each of its MUMPS calls: which instance (its address on rank 0, unique while it lives),
// the precision, and the controls MUMPS reads on every process. The matrix, its order and the right-hand sides
// stay on rank 0, which distributes them itself (centralized input, ICNTL(5) = ICNTL(18) = 0).
struct Command {
  std::uint64_t instance = 0;
  int precision = 0;  // kSingle, kDouble or kRelease
  int job = 0, par = 1, sym = 0;
  int icntl[60] = {};
  double cntl[15] = {};
};
constexpr int kSingle = 0, kDouble = 1, kRelease = -1;
constexpr int kCommandTag = 4711;

void set_blas_threads(int threads) {
  using SetThreads = void (*)(int);
  if (const auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(threads);
}

bool within_this_process = false;  // factor_within_this_process()

int world_size() {
  if (within_this_process) return 1;
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

// True when mpiexec (Open MPI, or a PMI-based launcher) started this process.
bool launched_by_mpiexec() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv(name)) return true;
  return false;
}

void start_mpi_if_needed(int* argc, char*** argv, bool& started) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized) return;
  // A singleton (no mpiexec) keeps PMIx's data in its own memory: its default store is a shared-memory file,
  // which fails where files are limited (ulimit -f) and would end the run in MPI_Init.
  if (!launched_by_mpiexec()) setenv("PMIX_MCA_gds", "hash", 0);
  int provided = 0;
  // Only the main thread calls MPI (OpenMP regions never do).
  if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw std::runtime_error("MPI could not be started for MUMPS");
  started = true;
}

void finalize_at_exit() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

template <class Struct>
void announce(const Struct& id, int precision) {
  if (world_size() < 2) return;
  Command c;
  c.instance = reinterpret_cast<std::uintptr_t>(&id);
  c.precision = precision;
  c.job = id.job;
  c.par = id.par;
  c.sym = id.sym;
  for (int i = 0; i < 60; ++i) c.icntl[i] = id.icntl[i];
  for (int i = 0; i < 15; ++i) c.cntl[i] = id.cntl[i];
  for (int r = 1; r < world_size(); ++r) MPI_Send(&c, sizeof c, MPI_BYTE, r, kCommandTag, MPI_COMM_WORLD);
}

// A serving rank's copy of one of rank 0's MUMPS instances.
template <class Struct>
void serve_call(std::map<std::uint64_t, std::unique_ptr<Struct>>& instances, const Command& c) {
  auto& slot = instances[c.instance];
  if (c.job == -1) {
    slot = std::make_unique<Struct>();
    slot->comm_fortran = mumps_communicator();
    slot->par = c.par;
    slot->sym = c.sym;
  } else if (!slot) {
    throw std::logic_error("MUMPS call for an instance this rank does not hold");
  } else {
    for (int i = 0; i < 60; ++i) slot->icntl[i] = c.icntl[i];
    for (int i = 0; i < 15; ++i) slot->cntl[i] = static_cast<std::remove_reference_t<decltype(slot->cntl[0])>>(c.cntl[i]);
  }
  slot->job = c.job;
  if constexpr (std::is_same_v<Struct, DMUMPS_STRUC_C>)
    dmumps_c(slot.get());
  else
    smumps_c(slot.get());
  if (c.job == -2) instances.erase(c.instance);
}
#endif

}  // namespace

MumpsProcesses::MumpsProcesses(int& argc, char**& argv, bool each_alone) {
#ifdef STRANDFEM_MUMPS_MPI
  // Without mpiexec MPI starts only when a MUMPS solver is first made (mumps_communicator), so that commands
  // that factor nothing (`info`, bad input) do not pay for it.
  if (!launched_by_mpiexec()) return;
  start_mpi_if_needed(&argc, &argv, started_mpi_);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  count_ = world_size();
  if (count_ > 1) set_blas_threads(1);
  if (each_alone) factor_within_this_process();
  serving_ = count_ > 1 && !each_alone;
#else
  (void)argc;
  (void)argv;
  (void)each_alone;
#endif
}

MumpsProcesses::~MumpsProcesses() {
#ifdef STRANDFEM_MUMPS_MPI
  if (rank_ == 0 && serving_) {
    Command release;
    release.precision = kRelease;
    for (int r = 1; r < count_; ++r) MPI_Send(&release, sizeof release, MPI_BYTE, r, kCommandTag, MPI_COMM_WORLD);
  }
  if (started_mpi_) finalize_at_exit();
#endif
}

int MumpsProcesses::serve() {
#ifdef STRANDFEM_MUMPS_MPI
  std::map<std::uint64_t, std::unique_ptr<SMUMPS_STRUC_C>> single_instances;
  std::map<std::uint64_t, std::unique_ptr<DMUMPS_STRUC_C>> double_instances;
  while (true) {
    Command c;
    MPI_Request request;
    MPI_Irecv(&c, sizeof c, MPI_BYTE, 0, kCommandTag, MPI_COMM_WORLD, &request);
    // Polled with sleeps, not a blocking receive: Open MPI's blocking waits spin, and this rank would take a core
    // from rank 0's element threads between factorizations. The sleeps grow from 20 us to 0.5 ms, so that a solve
    // that follows the last within a GMRES iteration starts at once and a long assembly costs few wake-ups.
    int arrived = 0;
    MPI_Test(&request, &arrived, MPI_STATUS_IGNORE);
    for (int pause = 20; !arrived; pause = std::min(2 * pause, 500)) {
      std::this_thread::sleep_for(std::chrono::microseconds(pause));
      MPI_Test(&request, &arrived, MPI_STATUS_IGNORE);
    }
    if (c.precision == kRelease) return 0;
    if (c.precision == kDouble)
      serve_call(double_instances, c);
    else
      serve_call(single_instances, c);
  }
#else
  return 0;
#endif
}

int mumps_process_count() {
#ifdef STRANDFEM_MUMPS_MPI
  int initialized = 0;
  MPI_Initialized(&initialized);
  return initialized ? world_size() : 1;
#else
  return 1;
#endif
}

std::string mumps_build() {
#ifdef STRANDFEM_MUMPS_MPI
  char version[MPI_MAX_LIBRARY_VERSION_STRING] = {};
  int length = 0;
  MPI_Get_library_version(version, &length);
  std::string name(version, static_cast<std::size_t>(length));
  if (const auto comma = name.find(','); comma != std::string::npos) name.resize(comma);
  return "MPI (" + name + ")";
#else
  return "sequential";
#endif
}

void factor_within_this_process() {
#ifdef STRANDFEM_MUMPS_MPI
  within_this_process = true;
#endif
}

int mumps_communicator() {
#ifdef STRANDFEM_MUMPS_MPI
  bool started = false;
  start_mpi_if_needed(nullptr, nullptr, started);
  if (started) std::atexit(finalize_at_exit);
  return static_cast<int>(MPI_Comm_c2f(within_this_process ? MPI_COMM_SELF : MPI_COMM_WORLD));
#else
  return kSequentialCommunicator;
#endif
}

void mumps_call(DMUMPS_STRUC_C& id) {
#ifdef STRANDFEM_MUMPS_MPI
  announce(id, kDouble);
#endif
  dmumps_c(&id);
}

void mumps_call(SMUMPS_STRUC_C& id) {
#ifdef STRANDFEM_MUMPS_MPI
  announce(id, kSingle);
#endif
  smumps_c(&id);
}

}  // namespace strandfem
