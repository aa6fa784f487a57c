#pragma once
/// @file
/// Hot loops compiled for the x86-64 baseline and for newer CPUs, chosen at run time: by GCC's
/// function multiversioning when the same source serves every copy (IGA_AVX2_CLONES,
/// IGA_X86_64_V3_V4_CLONES), or by hand with cpu_has_avx2() / cpu_has_avx2_fma() when the copies
/// must differ (the exact products of double-double arithmetic, double_double.hpp).

/// IGA_AVX2_CLONES: compile a function twice, for the baseline and for AVX2, the copy chosen when
/// the program is loaded. Clang (the fuzz and sanitizer builds) emits target_clones symbols a
/// GCC-built caller does not find, and these builds need no speed: there the macro is empty.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define IGA_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define IGA_AVX2_CLONES
#endif

/// IGA_X86_64_V3_V4_CLONES: three copies, baseline, x86-64-v3 (AVX2 + FMA) and x86-64-v4 (AVX-512),
/// for kernels that are chains of multiply-adds (Horner's rule) and rely on no separate rounding of
/// a product (unlike double-double arithmetic). Empty under Clang, as above.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define IGA_X86_64_V3_V4_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define IGA_X86_64_V3_V4_CLONES
#endif

namespace iga {

/// True when the CPU has AVX2 (for kernels picked by hand, e.g. libmvec's 4-wide entry points).
inline bool cpu_has_avx2() {
#if defined(__x86_64__)
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
#else
  return false;
#endif
}

/// True when the CPU has AVX2 and FMA and the build does not already target them (then the
/// baseline copy uses FMA itself).
inline bool cpu_has_avx2_fma() {
#if defined(__x86_64__) && !defined(__FMA__)
  static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return has;
#else
  return false;
#endif
}

}  // namespace iga
