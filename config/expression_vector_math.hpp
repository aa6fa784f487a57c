#pragma once
/// @file
/// Internal to VectorProgram: elementary functions over arrays of points through glibc's vector
/// math library (libmvec, linked with libm): two values per call with SSE, four with AVX2 when the
/// CPU has it. They are 4 to 13 times faster than a loop over std::sin and the like, which made
/// transcendental exact solutions the largest cost of error norms and load vectors; their results
/// are within 4 ulp (glibc's bound), far below any discretization error they enter.

#include <string>

namespace iga::expression_detail {

/// out[k] = f(a[k]) for k < count.
using ArrayFunction1 = void (*)(const double* a, double* out, int count);
/// out[k] = f(a[k], b[k]) for k < count.
using ArrayFunction2 = void (*)(const double* a, const double* b, double* out, int count);

/// The array version of the unary function `name` (GiNaC's name: sin, cos, exp, log, ...), or null
/// when libmvec has none (the caller then loops over the scalar function).
ArrayFunction1 array_function(const std::string& name);
/// pow(a, b) and atan2(a, b) over arrays.
ArrayFunction2 array_pow();
ArrayFunction2 array_atan2();

}  // namespace iga::expression_detail
