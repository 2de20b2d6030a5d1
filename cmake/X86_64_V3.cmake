# Sets STRANDFEM_INSTRUCTION_SET and, when x86-64-v3 is chosen, compiles every target with -march=x86-64-v3.
# One setting for all targets: Eigen's fixed-size types must be laid out alike in every translation unit.
set(STRANDFEM_INSTRUCTION_SET "x86-64")
if(STRANDFEM_X86_64_V3 STREQUAL "AUTO")
  include(CheckCXXSourceRuns)
  set(CMAKE_REQUIRED_FLAGS "-march=x86-64-v3")
  check_cxx_source_runs("
    int main() {
      __builtin_cpu_init();
      return (__builtin_cpu_supports(\"avx2\") && __builtin_cpu_supports(\"fma\") &&
              __builtin_cpu_supports(\"bmi2\") && __builtin_cpu_supports(\"movbe\")) ? 0 : 1;
    }" STRANDFEM_HOST_HAS_X86_64_V3)
  unset(CMAKE_REQUIRED_FLAGS)
  set(use_v3 ${STRANDFEM_HOST_HAS_X86_64_V3})
elseif(STRANDFEM_X86_64_V3 STREQUAL "ON")
  set(use_v3 TRUE)
elseif(STRANDFEM_X86_64_V3 STREQUAL "OFF")
  set(use_v3 FALSE)
else()
  message(FATAL_ERROR "STRANDFEM_X86_64_V3 is '${STRANDFEM_X86_64_V3}'; expected AUTO, ON or OFF")
endif()
if(use_v3)
  add_compile_options(-march=x86-64-v3)
  set(STRANDFEM_INSTRUCTION_SET "x86-64-v3")
endif()
message(STATUS "StrandFEM instruction set: ${STRANDFEM_INSTRUCTION_SET}")
