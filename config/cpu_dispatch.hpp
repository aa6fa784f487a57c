#pragma once
/// @file
/// Hot loops compiled for the x86-64 baseline and for newer CPUs, chosen at run time. Two ways:
/// IGA_AVX2_CLONES, when the same source serves both (GCC's function multiversioning), and
/// cpu_has_avx2_fma() with two explicit copies, when the copies must differ (the exact products
/// of double-double arithmetic, double_double.hpp).

/// IGA_AVX2_CLONES: compile a function twice, for the baseline and for AVX2, the copy chosen when
/// the program is loaded. Clang (the fuzz and sanitizer builds) emits target_clones symbols a
/// GCC-built caller does not find, and these builds need no speed: there the macro is empty.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define IGA_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define IGA_AVX2_CLONES
#endif

namespace iga {

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
