#include "config/expression_vector_program.hpp"
#include "config/expression_printer.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
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

using Op = VectorProgram::Op;
using Instruction = VectorProgram::Instruction;

/// Builds the program in single-assignment form (instruction i defines value i; the inputs x and y
/// are instructions too). Equal instructions are emitted once, so the products and sums of GiNaC's
/// flattened nodes (operands in printed order) share their common prefixes, as the terms of a
/// function's derivatives do. Constants become immediate operands, and a product feeding a sum
/// becomes one multiply-add: fewer passes over the block.
class Compiler {
 public:
  enum : int { kOpX = 100, kOpY = 101 };  // pseudo-ops of the inputs, only in this form

  std::vector<Instruction> code;

  int slot(const GiNaC::ex& e) {
    if (auto it = memo_.find(e); it != memo_.end()) return it->second;
    const int s = compile(e);
    memo_.emplace(e, s);
    return s;
  }

 private:
  static constexpr int kMaxHornerDegree = 24, kMaxFactorDegree = 16;

  /// Immediate operands by their bits: a strict order even for NaN, and -0 apart from 0.
  using Key = std::tuple<int, int, int, int, int, std::uint64_t, std::uint64_t>;

  /// An arithmetic instruction, or the equal one already emitted.
  int pure(Instruction in) {
    const Key key{static_cast<int>(in.op), in.a, in.b, in.d, in.n, std::bit_cast<std::uint64_t>(in.c),
                  std::bit_cast<std::uint64_t>(in.c2)};
    if (auto it = pure_memo_.find(key); it != pure_memo_.end()) return it->second;
    code.push_back(in);
    const int s = static_cast<int>(code.size()) - 1;
    pure_memo_.emplace(key, s);
    return s;
  }
  int emit(const Instruction& in) {
    code.push_back(in);
    return static_cast<int>(code.size()) - 1;
  }
  int input(int pseudo_op) { return pure({static_cast<Op>(pseudo_op)}); }

  bool constant_value(int s, double& c) const {
    if (code[s].op != Op::constant) return false;
    c = code[s].c;
    return true;
  }
  int literal(double c) { return pure({Op::constant, -1, -1, -1, 0, c}); }

  int plus(int a, int b) {
    double ca, cb;
    const bool a_constant = constant_value(a, ca), b_constant = constant_value(b, cb);
    if (a_constant && b_constant) return literal(ca + cb);
    if (b_constant) return plus_constant(a, cb);
    if (a_constant) return plus_constant(b, ca);
    // Copies, not references: pure() may grow `code`.
    for (const auto& [product, other] : {std::pair{a, b}, std::pair{b, a}}) {
      const Instruction p = code[product];
      if (p.op == Op::mul) return pure({Op::mul_add, p.a, p.b, other});
      if (p.op == Op::mul_c) return pure({Op::mul_c_add, p.a, -1, other, 0, p.c});
    }
    return pure({Op::add, a, b});
  }

  int plus_constant(int a, double c) {
    if (c == 0) return a;
    const Instruction p = code[a];
    if (p.op == Op::mul) return pure({Op::mul_add_c, p.a, p.b, -1, 0, c});
    if (p.op == Op::mul_c) return pure({Op::affine, p.a, -1, -1, 0, p.c, c});
    return pure({Op::add_c, a, -1, -1, 0, c});
  }

  int times(int a, int b) {
    double ca, cb;
    const bool a_constant = constant_value(a, ca), b_constant = constant_value(b, cb);
    if (a_constant && b_constant) return literal(ca * cb);
    if (b_constant) return cb == 1 ? a : pure({Op::mul_c, a, -1, -1, 0, cb});
    if (a_constant) return ca == 1 ? b : pure({Op::mul_c, b, -1, -1, 0, ca});
    return pure({Op::mul, a, b});
  }

  int power_int(int base, int n) {
    if (n == 1) return base;
    return pure({Op::power_int, base, -1, -1, n});
  }

  int number(const GiNaC::numeric& n) {
    if (!n.is_real()) throw Unknown{};
    return literal(n.to_double());
  }

  int compile(const GiNaC::ex& e) {
    using namespace GiNaC;
    if (is_a<numeric>(e)) return number(ex_to<numeric>(e));
    if (is_a<symbol>(e)) {
      const std::string name = ex_to<symbol>(e).get_name();
      if (name == "x") return input(kOpX);
      if (name == "y") return input(kOpY);
      throw Unknown{};
    }
    if (is_a<constant>(e)) {
      const ex value = e.evalf();
      if (!is_a<numeric>(value)) throw Unknown{};
      return number(ex_to<numeric>(value));
    }
    if (is_a<add>(e)) return polynomial_or_sum(e);
    if (is_a<mul>(e)) return product(e);
    if (is_a<power>(e)) {
      const ex exponent = e.op(1);
      if (is_a<numeric>(exponent) && ex_to<numeric>(exponent).is_rational()) {
        const numeric n = ex_to<numeric>(exponent);
        if (n.is_integer() && abs(n) <= 64) {
          const int k = n.to_int();
          return k >= 0 ? power_int(slot(e.op(0)), k) : pure({Op::div_c, power_int(slot(e.op(0)), -k), -1, -1, 0, 1.0});
        }
        // b^n = b^f * b^k, k = floor(n): powers of one base that differ by integers (those of a
        // singular solution and its derivatives) take one pow and a multiply or divide each.
        const numeric k = n - fractional_part(n);
        if (abs(k) <= 8 && !k.is_zero()) {
          const int fraction = slot(power(e.op(0), fractional_part(n)));
          const int base = slot(e.op(0));
          return k > 0 ? times(fraction, power_int(base, k.to_int()))
                       : pure({Op::div, fraction, power_int(base, -k.to_int())});
        }
        if (n == numeric(1, 2)) return pure({Op::sqrt, slot(e.op(0))});
      }
      Instruction in{Op::power, slot(e.op(0)), slot(exponent)};
      in.array2 = array_pow();
      return emit(in);
    }
    if (is_a<function>(e) && !is_a<fderivative>(e)) {
      const std::string name = ex_to<function>(e).get_name();
      if (name == "atan2" && e.nops() == 2) {
        const int a = slot(e.op(0)), b = slot(e.op(1));
        Instruction in{Op::call2, a, b};
        in.f2 = [](double u, double v) { return std::atan2(u, v); };
        in.array2 = array_atan2();
        return emit(in);
      }
      const auto& table = unary_functions();
      auto it = table.find(name);
      if (it == table.end() || e.nops() != 1) throw Unknown{};
      Instruction in{Op::call1, slot(e.op(0))};
      in.f1 = it->second;
      in.array1 = array_function(name);
      return emit(in);
    }
    throw Unknown{};
  }

  /// The operands of a sum or product ordered by their printed text. GiNaC orders them by hashes
  /// seeded with addresses, which differ from run to run; this order makes the program, and so
  /// the rounding of every value, the same in every run.
  std::vector<GiNaC::ex> operands(const GiNaC::ex& e) {
    std::vector<std::pair<std::string, GiNaC::ex>> keyed;
    for (size_t i = 0; i < e.nops(); ++i) {
      const GiNaC::ex o = e.op(i);
      auto it = text_.find(o);
      if (it == text_.end()) {
        std::string text;
        try {
          text = mu_text(o);
        } catch (const Unsupported&) {
          throw Unknown{};
        }
        it = text_.emplace(o, std::move(text)).first;
      }
      keyed.emplace_back(it->second, o);
    }
    std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<GiNaC::ex> sorted;
    for (auto& [text, o] : keyed) sorted.push_back(o);
    return sorted;
  }

  /// n - floor(n) for a rational n.
  static GiNaC::numeric fractional_part(const GiNaC::numeric& n) {
    const GiNaC::numeric r = GiNaC::mod(n.numer(), n.denom());  // in [0, denom)
    return r / n.denom();
  }

  /// A product: the factors in x alone, those in y alone and the others each multiplied in
  /// their order (so the derivatives of a separable u = X(x) Y(y) share X, Y and their
  /// derivatives), then the numeric coefficient (an immediate operand, so a sum fuses it into a
  /// multiply-add). A negative power b^-m is the factor 1/b^m, computed once for all the terms
  /// (the derivatives of a singular solution divide by a few powers of one base in every term).
  int product(const GiNaC::ex& e) {
    using namespace GiNaC;
    int in_x = -1, in_y = -1, others = -1, coefficient = -1;
    auto join = [&](int& acc, int s) { acc = acc < 0 ? s : times(acc, s); };
    auto group = [&](const ex& f) -> int& {
      const bool x = f.has(x_symbol()), y = f.has(y_symbol());
      return x && !y ? in_x : (y && !x ? in_y : others);
    };
    for (const ex& f : operands(e)) {
      if (is_a<numeric>(f)) {
        coefficient = slot(f);
        continue;
      }
      if (is_a<power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_rational() &&
          ex_to<numeric>(f.op(1)).is_negative() && ex_to<numeric>(f.op(1)) >= -64) {
        // b^(f-m) = b^f (1/b^m) with f in [0, 1).
        const numeric n = ex_to<numeric>(f.op(1));
        const numeric fraction = fractional_part(n);
        if (!fraction.is_zero()) join(group(f), slot(power(f.op(0), fraction)));
        join(group(f), pure({Op::div_c, slot(power(f.op(0), fraction - n)), -1, -1, 0, 1.0}));
        continue;
      }
      join(group(f), slot(f));
    }
    int acc = -1;
    for (int part : {in_x, in_y, others})
      if (part >= 0) join(acc, part);
    if (coefficient >= 0) acc = acc < 0 ? coefficient : times(acc, coefficient);
    return acc;
  }

  /// A sum term by term: c * r as one multiply-add into the partial sum, the constant term
  /// joined to the first product.
  int sum(const GiNaC::ex& e) {
    using namespace GiNaC;
    std::vector<int> terms;
    int constant_term = -1;
    for (const ex& t : operands(e)) {
      if (is_a<numeric>(t)) {
        constant_term = slot(t);
      } else if (is_a<mul>(t) && is_a<numeric>(t.op(t.nops() - 1))) {
        const ex c = t.op(t.nops() - 1);
        terms.push_back(times(slot(t / c), slot(c)));
      } else {
        terms.push_back(slot(t));
      }
    }
    int acc = terms.empty() ? constant_term : terms[0];
    if (constant_term >= 0 && !terms.empty()) acc = plus(acc, constant_term);
    for (size_t i = 1; i < terms.size(); ++i) acc = plus(acc, terms[i]);
    return acc;
  }

  /// Number of instructions from `first` on that `root` needs (its new cost).
  int new_instructions(int root, int first) const {
    std::vector<char> seen(code.size(), 0);
    std::vector<int> stack{root};
    int n = 0;
    while (!stack.empty()) {
      const int s = stack.back();
      stack.pop_back();
      if (s < first || seen[s]) continue;
      seen[s] = 1;
      ++n;
      for (int operand : {code[s].a, code[s].b, code[s].d})
        if (operand >= 0) stack.push_back(operand);
    }
    return n;
  }

  /// A sum that is a polynomial in x and y with numeric coefficients: compiled as written,
  /// factored, and in nested Horner form (x outside, then y outside), keeping whichever adds the
  /// fewest instructions. Expanded sources (Δ²u of a polynomial comes back as a sum of monomials) need a
  /// third of the passes; factored derivatives usually stay as written.
  int polynomial_or_sum(const GiNaC::ex& e) {
    using namespace GiNaC;
    if (trial_ || !e.is_polynomial(lst{x_symbol(), y_symbol()})) return sum(e);
    // Degrees of the unexpanded form bound those of the expansion: keep expanding and factoring
    // cheap (the data of a config have small degrees).
    const int degree = e.degree(x_symbol()) + e.degree(y_symbol());
    if (degree > kMaxHornerDegree) return sum(e);
    const ex expanded = e.expand();
    const int first = static_cast<int>(code.size());
    trial_ = true;
    struct Candidate {
      Compiler compiler;
      int root;
    };
    std::optional<Candidate> best;
    int best_cost = 0;
    auto consider = [&](auto&& build) {
      Compiler trial = *this;
      int root;
      try {
        root = build(trial);
      } catch (const Unknown&) {
        return;
      }
      const int cost = trial.new_instructions(root, first);
      if (!best || cost < best_cost) best = Candidate{std::move(trial), root}, best_cost = cost;
    };
    consider([&](Compiler& c) { return c.sum(e); });
    if (degree <= kMaxFactorDegree) consider([&](Compiler& c) {
      // Factored: the derivatives of a product of powers of linear factors share those factors.
      GiNaC::ex factored;
      try {
        factored = GiNaC::factor(expanded);
      } catch (const std::exception&) {
        throw Unknown{};
      }
      if (!GiNaC::is_a<GiNaC::mul>(factored) && !GiNaC::is_a<GiNaC::power>(factored)) throw Unknown{};
      return c.slot(factored);
    });
    consider([&](Compiler& c) { return c.horner(expanded, x_symbol(), y_symbol()); });
    consider([&](Compiler& c) { return c.horner(expanded, y_symbol(), x_symbol()); });
    if (!best) throw Unknown{};
    *this = std::move(best->compiler);
    trial_ = false;
    return best->root;
  }

  /// p = Σ_i outer^i q_i(inner), each q_i by Horner's rule in `inner`, then Horner's rule in `outer`.
  int horner(const GiNaC::ex& p, const GiNaC::ex& outer, const GiNaC::ex& inner) {
    const int n = p.degree(outer);
    std::vector<int> q(n + 1, -1);
    for (int i = 0; i <= n; ++i) {
      const GiNaC::ex qi = p.coeff(outer, i);
      if (qi.is_zero()) continue;
      const int m = qi.degree(inner);
      std::vector<double> c(m + 1, 0.0);
      std::vector<bool> present(m + 1, false);
      for (int j = 0; j <= m; ++j) {
        const GiNaC::ex cij = qi.coeff(inner, j).evalf();
        if (!GiNaC::is_a<GiNaC::numeric>(cij) || !GiNaC::ex_to<GiNaC::numeric>(cij).is_real()) throw Unknown{};
        c[j] = GiNaC::ex_to<GiNaC::numeric>(cij).to_double();
        present[j] = !cij.is_zero();
      }
      q[i] = horner_rule(slot(inner), [&](int j) { return present[j] ? literal(c[j]) : -1; }, m);
    }
    return horner_rule(slot(outer), [&](int i) { return q[i]; }, n);
  }

  /// Σ_{j ≤ m} v^j coefficient(j) by Horner's rule (coefficient -1: absent), a power of v taken
  /// out of the lowest terms.
  template <class Coefficient>
  int horner_rule(int v, Coefficient coefficient, int m) {
    int lowest = 0;
    while (lowest < m && coefficient(lowest) < 0) ++lowest;
    int acc = coefficient(m);
    for (int j = m - 1; j >= lowest; --j) {
      acc = times(acc, v);
      if (const int cj = coefficient(j); cj >= 0) acc = plus(acc, cj);
    }
    return lowest == 0 ? acc : times(acc, power_int(v, lowest));
  }

  static GiNaC::ex x_symbol() { return sym_x(); }
  static GiNaC::ex y_symbol() { return sym_y(); }

  std::map<GiNaC::ex, int, GiNaC::ex_is_less> memo_;
  std::map<Key, int> pure_memo_;
  std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> text_;  ///< operands() keys
  bool trial_ = false;  ///< inside one candidate of polynomial_or_sum: no nested choices
};
}  // namespace

std::optional<VectorProgram> vector_program(const std::vector<GiNaC::ex>& es) {
  Compiler compiler;
  std::vector<int> roots;
  try {
    for (const GiNaC::ex& e : es) roots.push_back(compiler.slot(e));
  } catch (const Unknown&) {
    return std::nullopt;
  }
  const std::vector<Instruction>& ssa = compiler.code;
  const int n = static_cast<int>(ssa.size());
  auto operands = [](const Instruction& in) { return std::array<int, 3>{in.a, in.b, in.d}; };

  // What the results need, and where each value is read for the last time (results: never).
  std::vector<char> live(n, 0);
  for (int r : roots) live[r] = 1;
  for (int i = n - 1; i >= 0; --i)
    if (live[i])
      for (int s : operands(ssa[i]))
        if (s >= 0) live[s] = 1;
  constexpr int kForever = std::numeric_limits<int>::max();
  std::vector<int> last_use(n, -1);
  for (int i = 0; i < n; ++i)
    if (live[i])
      for (int s : operands(ssa[i]))
        if (s >= 0) last_use[s] = std::max(last_use[s], i);
  for (int r : roots) last_use[r] = kForever;

  // Slots reused as soon as their value is dead, so the working set stays in the first-level cache.
  // Every operation is elementwise, so an instruction may overwrite an operand it reads last.
  VectorProgram program;
  std::vector<int> slot_of(n, -1), free_slots;
  for (int i = 0; i < n; ++i) {
    if (!live[i]) continue;
    const Instruction& in = ssa[i];
    if (static_cast<int>(in.op) == Compiler::kOpX || static_cast<int>(in.op) == Compiler::kOpY) {
      slot_of[i] = static_cast<int>(in.op) == Compiler::kOpX ? VectorProgram::kInputX : VectorProgram::kInputY;
      continue;
    }
    Instruction out = in;
    for (int* s : {&out.a, &out.b, &out.d})
      if (*s >= 0) *s = slot_of[*s];
    for (int s : operands(in))
      if (s >= 0 && last_use[s] == i && slot_of[s] >= 0 &&
          std::find(free_slots.begin(), free_slots.end(), slot_of[s]) == free_slots.end())
        free_slots.push_back(slot_of[s]);
    if (free_slots.empty()) {
      out.out = program.slots_++;
    } else {
      out.out = free_slots.back();
      free_slots.pop_back();
    }
    slot_of[i] = out.out;
    program.code_.push_back(out);
  }
  for (int r : roots) program.results_.push_back(slot_of[r]);
  return program;
}

}  // namespace iga::expression_detail
