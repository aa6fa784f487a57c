#pragma once
/// @file
/// Internal to SymbolicFunction: prints GiNaC expressions as muParser text, either as one flat
/// string (for str()) or as a Program that shares common subexpressions (for evaluation). Every
/// function here touches GiNaC objects, so callers hold the GiNaC lock of expression.cpp.

#include <ginac/ginac.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "config/expression_evaluator.hpp"

namespace iga::expression_detail {

/// The variables x and y, shared by parsing, differentiation and printing. Real symbols: with
/// complex ones GiNaC keeps conjugate(x) in derivatives of abs(). Leaked on purpose, so static
/// SymbolicFunctions may be destroyed in any order at exit.
const GiNaC::realsymbol& sym_x();
const GiNaC::realsymbol& sym_y();
/// z: only in functions parsed with SymbolicFunction::parse_xyz (surfaces in 3D).
const GiNaC::realsymbol& sym_z();

/// Why an expression cannot be turned into muParser text (turned into an InputError by the caller).
struct Unsupported : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Shortest round-trip form, no locale.
std::string number(double value);

/// `e` as one muParser expression. Throws Unsupported.
std::string mu_text(const GiNaC::ex& e);

/// `e` as muParser statements: repeated function calls, sums and powers are hoisted into temporaries
/// and every statement is kept short. Throws Unsupported.
Program mu_program(const GiNaC::ex& e);

/// Several expressions as one program that computes their common subexpressions once; the value
/// of expression i is left in temporary Program::results[i]. Throws Unsupported.
Program mu_program(const std::vector<GiNaC::ex>& es);

}  // namespace iga::expression_detail
