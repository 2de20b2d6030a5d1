#include "strandfem/solver/blas_kernels.hpp"

#include <dlfcn.h>

namespace strandfem {

std::string blas_core_name() {
  // Looked up at run time: the BLAS behind MUMPS is whatever Debian's alternatives point to.
  using CoreName = char* (*)();
  const auto core_name = reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  if (!core_name) return "not OpenBLAS";
  const char* name = core_name();
  return name ? name : "unknown";
}

int blas_thread_count() {
  using ThreadCount = int (*)();
  const auto count = reinterpret_cast<ThreadCount>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  return count ? count() : 0;
}

bool cpu_has_skylakex_instructions() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
         __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
         __builtin_cpu_supports("avx512vl");
#else
  return false;
#endif
}

std::string preferred_openblas_core(const std::string& loaded_core, bool cpu_has_skylakex, bool user_set_core) {
  if (user_set_core || !cpu_has_skylakex) return "";
  if (loaded_core == "Haswell" || loaded_core == "Zen") return "SkylakeX";
  return "";
}

}  // namespace strandfem
