#pragma once
/// @file
/// IGA_AVX2_CLONES: compile a function twice, for the x86-64 baseline and for AVX2, the copy
/// chosen when the program is loaded (GCC's function multiversioning). Clang (the fuzz and
/// sanitizer builds) emits target_clones symbols a GCC-built caller does not find, and these
/// builds need no speed: there the macro is empty.

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define IGA_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define IGA_AVX2_CLONES
#endif
