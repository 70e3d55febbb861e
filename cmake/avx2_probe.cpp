// Configure-time probe (CMakeLists.txt, RASTER_AVX2=AUTO): exits 0 when the CPU running it
// has AVX2, FMA and F16C, which the default build lets the compiler use everywhere. It does
// not compile for a target other than x86 (no such __builtin_cpu_supports names there),
// which AUTO reads as no, as it reads a non-zero exit.
int main() {
  __builtin_cpu_init();
  const bool all = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("f16c");
  return all ? 0 : 1;
}
