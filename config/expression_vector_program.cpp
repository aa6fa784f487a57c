#include "config/expression_vector_program.hpp"
#include "config/cpu_dispatch.hpp"

#include <cmath>
#include <map>
#include <string>
#include <tuple>

namespace iga::expression_detail {

namespace {

// The functions expression_printer knows, with the same meanings (csgn(0) = 0, step(0) = 1/2).
double sign_function(double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }
double step_function(double v) { return v > 0 ? 1.0 : (v < 0 ? 0.0 : 0.5); }

using Fn1 = double (*)(double);
const std::map<std::string, Fn1>& unary_functions() {
  static const std::map<std::string, Fn1> table = {
      {"sin", [](double v) { return std::sin(v); }},     {"cos", [](double v) { return std::cos(v); }},
      {"tan", [](double v) { return std::tan(v); }},     {"asin", [](double v) { return std::asin(v); }},
      {"acos", [](double v) { return std::acos(v); }},   {"atan", [](double v) { return std::atan(v); }},
      {"sinh", [](double v) { return std::sinh(v); }},   {"cosh", [](double v) { return std::cosh(v); }},
      {"tanh", [](double v) { return std::tanh(v); }},   {"asinh", [](double v) { return std::asinh(v); }},
      {"acosh", [](double v) { return std::acosh(v); }}, {"atanh", [](double v) { return std::atanh(v); }},
      {"exp", [](double v) { return std::exp(v); }},     {"log", [](double v) { return std::log(v); }},
      {"abs", [](double v) { return std::abs(v); }},     {"csgn", sign_function},
      {"step", step_function},                           {"tgamma", [](double v) { return std::tgamma(v); }},
      {"lgamma", [](double v) { return std::lgamma(v); }}};
  return table;
}

struct Unknown {};  // thrown inside the compiler: fall back to muParser

class Compiler {
 public:
  explicit Compiler(std::vector<VectorProgram::Instruction>& code) : code_(code) {}

  int slot(const GiNaC::ex& e) {
    if (auto it = memo_.find(e); it != memo_.end()) return it->second;
    const int s = compile(e);
    memo_.emplace(e, s);
    return s;
  }

 private:
  using Op = VectorProgram::Op;

  int emit(VectorProgram::Instruction in) {
    code_.push_back(in);
    return static_cast<int>(code_.size()) - 1;
  }

  /// a + b or a * b, computed once per pair of slots: the products and sums of GiNaC's flattened
  /// nodes (factors in canonical order) share their common prefixes, as the terms of a function's
  /// derivatives do (x²(1-x)²y²(1-y)² and its five derivatives: 62 instructions instead of 76).
  int binary(Op op, int a, int b) {
    const auto key = std::make_tuple(op, a, b);
    if (auto it = binary_memo_.find(key); it != binary_memo_.end()) return it->second;
    const int s = emit({op, a, b});
    binary_memo_.emplace(key, s);
    return s;
  }

  int number(const GiNaC::numeric& n) {
    if (!n.is_real()) throw Unknown{};
    return emit({Op::constant, -1, -1, 0, n.to_double()});
  }

  int compile(const GiNaC::ex& e) {
    using namespace GiNaC;
    if (is_a<numeric>(e)) return number(ex_to<numeric>(e));
    if (is_a<symbol>(e)) {
      const std::string name = ex_to<symbol>(e).get_name();
      if (name == "x") return emit({Op::x});
      if (name == "y") return emit({Op::y});
      throw Unknown{};
    }
    if (is_a<constant>(e)) {
      const ex value = e.evalf();
      if (!is_a<numeric>(value)) throw Unknown{};
      return number(ex_to<numeric>(value));
    }
    if (is_a<add>(e) || is_a<mul>(e)) {
      const Op op = is_a<add>(e) ? Op::add : Op::mul;
      int acc = slot(e.op(0));
      for (size_t i = 1; i < e.nops(); ++i) acc = binary(op, acc, slot(e.op(i)));
      return acc;
    }
    if (is_a<power>(e)) {
      const int base = slot(e.op(0));
      const ex exponent = e.op(1);
      if (is_a<numeric>(exponent)) {
        const numeric n = ex_to<numeric>(exponent);
        if (n.is_integer() && abs(n) <= 64) return emit({Op::power_int, base, -1, n.to_int()});
        if (n == numeric(1, 2)) return emit({Op::sqrt, base});
        if (n == numeric(-1, 2)) return emit({Op::power_int, emit({Op::sqrt, base}), -1, -1});
      }
      VectorProgram::Instruction in{Op::power, base, slot(exponent)};
      in.array2 = array_pow();
      return emit(in);
    }
    if (is_a<function>(e) && !is_a<fderivative>(e)) {
      const std::string name = ex_to<function>(e).get_name();
      if (name == "atan2" && e.nops() == 2) {
        const int a = slot(e.op(0)), b = slot(e.op(1));
        VectorProgram::Instruction in{Op::call2, a, b};
        in.f2 = [](double u, double v) { return std::atan2(u, v); };
        in.array2 = array_atan2();
        return emit(in);
      }
      const auto& table = unary_functions();
      auto it = table.find(name);
      if (it == table.end() || e.nops() != 1) throw Unknown{};
      VectorProgram::Instruction in{Op::call1, slot(e.op(0))};
      in.f1 = it->second;
      in.array1 = array_function(name);
      return emit(in);
    }
    throw Unknown{};
  }

  std::vector<VectorProgram::Instruction>& code_;
  std::map<GiNaC::ex, int, GiNaC::ex_is_less> memo_;
  std::map<std::tuple<Op, int, int>, int> binary_memo_;
};

/// v^n by squaring (n may be negative).
double integer_power(double v, int n) {
  unsigned m = static_cast<unsigned>(n < 0 ? -n : n);
  double result = 1.0, base = v;
  while (m) {
    if (m & 1u) result *= base;
    base *= base;
    m >>= 1u;
  }
  return n < 0 ? 1.0 / result : result;
}

}  // namespace

std::optional<VectorProgram> vector_program(const std::vector<GiNaC::ex>& es) {
  VectorProgram program;
  try {
    Compiler compiler(program.code_);
    for (const GiNaC::ex& e : es) program.results_.push_back(compiler.slot(e));
  } catch (const Unknown&) {
    return std::nullopt;
  }
  return program;
}

// Compiled twice, the AVX2 body chosen at load time where the CPU has it: the arithmetic loops
// then run four points per instruction instead of two.
IGA_AVX2_CLONES
void VectorProgram::run(const double* x, const double* y, int count, std::vector<double>& work, double* values,
                        int stride) const {
  work.resize(code_.size() * kBlock);
  for (size_t i = 0; i < code_.size(); ++i) {
    const Instruction& in = code_[i];
    double* out = &work[i * kBlock];
    const double* a = in.a >= 0 ? &work[static_cast<size_t>(in.a) * kBlock] : nullptr;
    const double* b = in.b >= 0 ? &work[static_cast<size_t>(in.b) * kBlock] : nullptr;
    switch (in.op) {
      case Op::constant:
        for (int k = 0; k < count; ++k) out[k] = in.c;
        break;
      case Op::x:
        for (int k = 0; k < count; ++k) out[k] = x[k];
        break;
      case Op::y:
        for (int k = 0; k < count; ++k) out[k] = y[k];
        break;
      case Op::add:
        for (int k = 0; k < count; ++k) out[k] = a[k] + b[k];
        break;
      case Op::mul:
        for (int k = 0; k < count; ++k) out[k] = a[k] * b[k];
        break;
      case Op::power_int:
        // The common small exponents as straight products (they vectorize; the loop does not).
        if (in.n == 2) {
          for (int k = 0; k < count; ++k) out[k] = a[k] * a[k];
        } else if (in.n == 3) {
          for (int k = 0; k < count; ++k) out[k] = a[k] * a[k] * a[k];
        } else if (in.n == 4) {
          for (int k = 0; k < count; ++k) {
            const double square = a[k] * a[k];
            out[k] = square * square;
          }
        } else if (in.n == -1) {
          for (int k = 0; k < count; ++k) out[k] = 1.0 / a[k];
        } else {
          for (int k = 0; k < count; ++k) out[k] = integer_power(a[k], in.n);
        }
        break;
      case Op::sqrt:
        for (int k = 0; k < count; ++k) out[k] = std::sqrt(a[k]);
        break;
      case Op::power:
        if (in.array2) {
          in.array2(a, b, out, count);
        } else {
          for (int k = 0; k < count; ++k) out[k] = std::pow(a[k], b[k]);
        }
        break;
      case Op::call1:
        if (in.array1) {
          in.array1(a, out, count);
        } else {
          for (int k = 0; k < count; ++k) out[k] = in.f1(a[k]);
        }
        break;
      case Op::call2:
        if (in.array2) {
          in.array2(a, b, out, count);
        } else {
          for (int k = 0; k < count; ++k) out[k] = in.f2(a[k], b[k]);
        }
        break;
    }
  }
  for (size_t i = 0; i < results_.size(); ++i) {
    const double* r = &work[static_cast<size_t>(results_[i]) * kBlock];
    for (int k = 0; k < count; ++k) values[i + static_cast<size_t>(k) * stride] = r[k];
  }
}

}  // namespace iga::expression_detail
