// Which OpenBLAS kernels the factorizations run on, and the faster choice on AVX-512 CPUs that OpenBLAS 0.3.21
// (Debian 12) does not recognize.
#pragma once
#include <string>

namespace strandfem {

// The kernel set OpenBLAS loaded ("Haswell", "SkylakeX", ...), read back from the library itself; "not OpenBLAS"
// when the BLAS in use is another one.
std::string blas_core_name();

// The threads OpenBLAS runs its kernels on, read back from the library; 0 when the BLAS is another one.
int blas_thread_count();

// True when the CPU has the AVX-512 subsets that OpenBLAS' SkylakeX kernels use (F, CD, BW, DQ, VL).
bool cpu_has_skylakex_instructions();

// The OPENBLAS_CORETYPE to run with instead of `loaded_core`, or "" to keep it. OpenBLAS 0.3.21 takes AMD Zen 4/5
// for Haswell or Zen and runs AVX2 kernels although the CPU has AVX-512: there the SkylakeX kernels factor a
// Cardinal 1 m tangent about a fifth faster (docs/performance.md). A value the user set is kept.
std::string preferred_openblas_core(const std::string& loaded_core, bool cpu_has_skylakex, bool user_set_core);

}  // namespace strandfem
