// Configure-time probe (CMakeLists.txt, RASTER_AVX512=AUTO): exits 0 when the CPU running
// it has the AVX-512 subsets the build would let the compiler use, and the OS saves their
// registers (__builtin_cpu_supports checks both).
int main() {
  __builtin_cpu_init();
  const bool all = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                   __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq");
  return all ? 0 : 1;
}
