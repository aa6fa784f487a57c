#include "config/expression_printer.hpp"

#include <algorithm>
#include <charconv>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

namespace iga::expression_detail {

const GiNaC::realsymbol& sym_x() {
  static const auto* s = new GiNaC::realsymbol("x");
  return *s;
}
const GiNaC::realsymbol& sym_z() {
  static const auto* s = new GiNaC::realsymbol("z");
  return *s;
}

const GiNaC::realsymbol& sym_y() {
  static const auto* s = new GiNaC::realsymbol("y");
  return *s;
}

std::string number(double value) {
  char buf[40];
  auto end = std::to_chars(buf, buf + sizeof buf, value).ptr;  // shortest round-trip form, no locale
  return std::string(buf, end);
}

namespace {

std::string ginac_text(const GiNaC::ex& e) {
  std::ostringstream out;
  out << e;
  return out.str();
}

/// Prints GiNaC expressions for muParser. We print ourselves instead of using GiNaC's output: GiNaC
/// writes floats as "(2.5)", rationals as "1/2*x" and leaves precedence of unary minus and "^" to the
/// reader. Here every sign and power is printed so that any reasonable precedence rules agree.
class MuPrinter {
 public:
  /// program = false: one flat string (for mu_text); true: also hoist repeated function calls and
  /// powers into temporaries and keep every statement short (for mu_program).
  explicit MuPrinter(bool program) : program_(program) {}

  /// The flat text of `e` (memoised): the key that orders the operands of sums and products.
  /// GiNaC orders them by hashes seeded with addresses of type information, which differ from run
  /// to run under address randomisation; printing in GiNaC's order made muParser round the same
  /// expression differently in different runs.
  const std::string& key(const GiNaC::ex& e) {
    auto it = keys_.find(e);
    if (it != keys_.end()) return it->second;
    std::string text = program_ ? flat_printer().key(e) : print_node(e).text;
    return keys_.emplace(e, std::move(text)).first->second;
  }

  std::string flat(const GiNaC::ex& e) { return print(e).text; }

  Program compile(const GiNaC::ex& e) {
    count_uses(e);
    statements_.clear();
    const std::string result = print(e).text;
    return finish(result);
  }

  /// Several expressions in one program: subexpressions shared between them (u and its
  /// derivatives share their sines and cosines) are computed once; expression i is left in
  /// temporary results[i].
  Program compile_many(const std::vector<GiNaC::ex>& es) {
    for (const GiNaC::ex& e : es) count_uses(e);
    statements_.clear();
    std::vector<int> results;
    for (const GiNaC::ex& e : es) {
      const std::string text = print(e).text;
      results.push_back(temporaries_);
      new_temporary(text);
    }
    Program program = finish("");
    program.results = std::move(results);
    return program;
  }

 private:
  void count_uses(const GiNaC::ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
      // A negative power is printed as a denominator, i.e. through its positive counterpart.
      const GiNaC::ex key = is_negative_power(*it) ? GiNaC::power(it->op(0), -it->op(1)) : *it;
      if (worth_sharing(key)) ++uses_[key];
    }
  }

  /// The statements so far, then `result` (none when empty), cut into stages.
  Program finish(const std::string& result) {
    Program program;
    program.temporaries = temporaries_;
    std::string stage;
    auto append = [&](const std::string& s) {
      if (!stage.empty() && stage.size() + s.size() + 2 > kStageLength)
        program.stages.push_back(std::move(stage)), stage.clear();
      stage += (stage.empty() ? "" : ", ") + s;
    };
    for (const std::string& s : statements_) append(s);
    if (!result.empty()) append(result);
    program.stages.push_back(stage);
    return program;
  }

  // Precedence of what a printed piece is, from loosest to tightest.
  enum Prec { kAdd = 1, kMul = 2, kPow = 3, kAtom = 4 };
  struct Printed {
    std::string text;
    int prec;
  };
  // muParser refuses expressions longer than 20000 characters; keep statements well below.
  static constexpr size_t kChunk = 3000;
  static constexpr size_t kStageLength = 15000;

  static std::string wrap(const Printed& p, int min_prec) {
    return p.prec < min_prec ? "(" + p.text + ")" : p.text;
  }

  static bool is_negative_power(const GiNaC::ex& e) {
    return GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
           GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_real() &&
           GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_negative();
  }

  static bool is_constant(const GiNaC::ex& e) { return !e.has(sym_x()) && !e.has(sym_y()) && !e.has(sym_z()); }

  /// Function calls, sums and non-trivial powers: evaluated once per point when they occur repeatedly.
  /// Not constants: muParser folds those when it compiles, a temporary would be recomputed each time.
  static bool worth_sharing(const GiNaC::ex& e) {
    if (is_constant(e)) return false;
    if (GiNaC::is_a<GiNaC::function>(e) || GiNaC::is_a<GiNaC::add>(e)) return true;
    if (!GiNaC::is_a<GiNaC::power>(e)) return false;
    return !GiNaC::is_a<GiNaC::symbol>(e.op(0)) || !e.op(1).info(GiNaC::info_flags::posint);
  }

  std::string new_temporary(const std::string& value) {
    const std::string name = "_t" + std::to_string(temporaries_++);
    statements_.push_back(name + "=" + value);
    return name;
  }

  Printed print(const GiNaC::ex& e) {
    if (!program_) return print_node(e);
    if (auto it = temps_.find(e); it != temps_.end()) return {it->second, kAtom};
    Printed p = print_node(e);
    auto use = uses_.find(e);
    if ((use != uses_.end() && use->second > 1) || p.text.size() > kChunk) {
      p = {new_temporary(p.text), kAtom};
      temps_.emplace(e, p.text);
    }
    return p;
  }

  Printed print_node(const GiNaC::ex& e) {
    using namespace GiNaC;
    if (is_a<numeric>(e)) return print_numeric(ex_to<numeric>(e));
    if (is_a<symbol>(e)) {
      const std::string name = ex_to<symbol>(e).get_name();
      if (name != "x" && name != "y" && name != "z") throw Unsupported("unknown symbol '" + name + "'");
      return {name, kAtom};
    }
    if (is_a<constant>(e)) {
      if (e.is_equal(Pi)) return {"Pi", kAtom};
      const ex value = e.evalf();
      if (!is_a<numeric>(value)) throw Unsupported("constant '" + ginac_text(e) + "' has no value");
      return print_numeric(ex_to<numeric>(value));
    }
    if (is_a<add>(e)) return print_sum(e);
    if (is_a<mul>(e)) return print_product(e);
    if (is_a<power>(e)) return is_negative_power(e) ? print_product(e) : print_power(e.op(0), e.op(1));
    if (is_a<fderivative>(e))
      throw Unsupported("derivative of function '" + ex_to<function>(e).get_name() +
                        "' is not known in closed form");
    if (is_a<function>(e)) return print_function(ex_to<function>(e));
    throw Unsupported("'" + ginac_text(e) + "' is not a scalar expression");
  }

  Printed print_numeric(const GiNaC::numeric& n) {
    if (!n.is_real()) throw Unsupported("complex value '" + ginac_text(n) + "'");
    const bool negative = n.is_negative();
    const GiNaC::numeric a = GiNaC::abs(n);
    std::string text;
    int prec = kAtom;
    if (a.is_rational()) {
      text = number(a.numer().to_double());
      if (!a.is_integer()) text += "/" + number(a.denom().to_double()), prec = kMul;
    } else {
      text = number(a.to_double());
    }
    if (negative) return {"-" + text, kAdd};
    return {text, prec};
  }

  static bool is_negative_term(const GiNaC::ex& t) {
    using namespace GiNaC;
    if (is_a<numeric>(t)) return ex_to<numeric>(t).is_real() && ex_to<numeric>(t).is_negative();
    if (is_a<mul>(t))
      for (size_t i = 0; i < t.nops(); ++i)
        if (is_a<numeric>(t.op(i)) && ex_to<numeric>(t.op(i)).is_real() &&
            ex_to<numeric>(t.op(i)).is_negative())
          return true;
    return false;
  }

  /// Positive terms first, so a leading unary minus is only needed when all terms are negative.
  Printed print_sum(const GiNaC::ex& e) {
    std::vector<GiNaC::ex> plus, minus;
    for (size_t i = 0; i < e.nops(); ++i) (is_negative_term(e.op(i)) ? minus : plus).push_back(e.op(i));
    plus = sorted(std::move(plus));
    minus = sorted(std::move(minus));
    std::string acc;
    for (const GiNaC::ex& t : plus) {
      if (!acc.empty()) acc += " + ";
      acc += wrap(print(t), kAdd + 1);
      if (program_ && acc.size() > kChunk) acc = new_temporary(acc);
    }
    for (const GiNaC::ex& t : minus) {
      if (acc.empty())
        acc = negate(-t);
      else
        acc += " - " + wrap(print(-t), kMul);
      if (program_ && acc.size() > kChunk) acc = new_temporary(acc);
    }
    return {acc, kAdd};
  }

  /// "-a" written so that it reads the same whether unary minus binds tighter than "^" or not.
  std::string negate(const GiNaC::ex& positive) {
    bool leading_atom = false;
    Printed p = print_product_parts(positive, &leading_atom);
    // Appended rather than "-" + ...: GCC 12 warns falsely (-Wrestrict) about that form here.
    std::string text = "-";
    text += leading_atom ? p.text : wrap(p, kAtom);
    return text;
  }

  Printed print_product(const GiNaC::ex& e) {
    if (is_negative_term(e)) return {negate(-e), kAdd};
    return print_product_parts(e, nullptr);
  }

  /// num1*num2*.../(den1*den2*...), with rational coefficients split into both parts.
  Printed print_product_parts(const GiNaC::ex& e, bool* leading_atom) {
    using namespace GiNaC;
    std::vector<ex> factors;
    if (is_a<mul>(e))
      for (size_t i = 0; i < e.nops(); ++i) factors.push_back(e.op(i));
    else
      factors.push_back(e);
    // Constant factors (Pi^4) first, next to the coefficient: muParser folds "1024*Pi^4" into one
    // number but not "1024*cos(...)*Pi^4".
    factors = sorted(std::move(factors));
    std::stable_partition(factors.begin(), factors.end(), is_constant);
    numeric coeff = 1;
    std::vector<Printed> num, den;
    for (const ex& f : factors) {
      if (is_a<numeric>(f)) {
        coeff *= ex_to<numeric>(f);
        continue;
      }
      if (is_negative_power(f))
        den.push_back(print(power(f.op(0), -f.op(1))));
      else
        num.push_back(print(f));
    }
    if (!coeff.is_real()) throw Unsupported("complex value '" + ginac_text(coeff) + "'");
    if (coeff.is_negative()) throw std::logic_error("print_product_parts: negative coefficient");
    if (coeff.is_rational()) {
      if (coeff.denom() != 1) den.insert(den.begin(), print_numeric(coeff.denom()));
      if (coeff.numer() != 1) num.insert(num.begin(), print_numeric(coeff.numer()));
    } else if (coeff != 1) {
      num.insert(num.begin(), print_numeric(coeff));
    }
    if (leading_atom) *leading_atom = num.empty() || num.front().prec >= kAtom;
    if (num.size() == 1 && den.empty()) return num.front();
    std::string text = join(num, kMul);
    if (text.empty()) text = "1";
    if (!den.empty()) text += "/" + (den.size() == 1 ? wrap(den.front(), kPow) : "(" + join(den, kMul) + ")");
    return {text, kMul};
  }

  std::string join(const std::vector<Printed>& factors, int min_prec) {
    std::string acc;
    for (const Printed& f : factors) {
      if (!acc.empty()) acc += "*";
      acc += wrap(f, min_prec);
      if (program_ && acc.size() > kChunk) acc = new_temporary(acc);
    }
    return acc;
  }

  Printed print_power(const GiNaC::ex& base, const GiNaC::ex& exponent) {
    const Printed b = print(base);
    if (exponent.is_equal(GiNaC::numeric(1, 2))) return {"sqrt(" + b.text + ")", kAtom};
    // Base and exponent are both atoms or parenthesized: the associativity of "^" never matters.
    return {wrap(b, kAtom) + "^" + wrap(print(exponent), kAtom), kPow};
  }

  Printed print_function(const GiNaC::function& f) {
    // GiNaC name -> muParser name (muParser's own or defined in Evaluator). "log" is natural in
    // muParser 2.3 but was log10 in old versions, so print the unambiguous "ln".
    static const std::map<std::string, std::string> names = {
        {"sin", "sin"},     {"cos", "cos"},   {"tan", "tan"},       {"asin", "asin"},
        {"acos", "acos"},   {"atan", "atan"}, {"atan2", "atan2"},   {"sinh", "sinh"},
        {"cosh", "cosh"},   {"tanh", "tanh"}, {"asinh", "asinh"},   {"acosh", "acosh"},
        {"atanh", "atanh"}, {"exp", "exp"},   {"log", "ln"},        {"abs", "abs"},
        {"csgn", "sign"},   {"step", "step"}, {"tgamma", "tgamma"}, {"lgamma", "lgamma"}};
    auto it = names.find(f.get_name());
    if (it == names.end())
      throw Unsupported("function '" + f.get_name() + "' cannot be evaluated numerically");
    std::string text = it->second + "(";
    for (size_t i = 0; i < f.nops(); ++i) text += (i ? ", " : "") + print(f.op(i)).text;
    return {text + ")", kAtom};
  }

  /// Operands of a sum or product in key() order (ties print the same, so they evaluate the same).
  std::vector<GiNaC::ex> sorted(std::vector<GiNaC::ex> operands) {
    if (operands.size() < 2) return operands;  // also: a lone factor may be `e` itself (x^-1)
    for (const GiNaC::ex& o : operands) key(o);  // fill the cache before sorting by it
    std::stable_sort(operands.begin(), operands.end(),
                     [&](const GiNaC::ex& a, const GiNaC::ex& b) { return keys_.at(a) < keys_.at(b); });
    return operands;
  }

  MuPrinter& flat_printer() {
    if (!flat_) flat_ = std::make_unique<MuPrinter>(false);
    return *flat_;
  }

  bool program_;
  std::unique_ptr<MuPrinter> flat_;  ///< computes key() for a program printer (no temporaries)
  std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> keys_;
  int temporaries_ = 0;
  std::vector<std::string> statements_;
  std::map<GiNaC::ex, int, GiNaC::ex_is_less> uses_;
  std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> temps_;
};

}  // namespace

std::string mu_text(const GiNaC::ex& e) { return MuPrinter(false).flat(e); }

Program mu_program(const GiNaC::ex& e) { return MuPrinter(true).compile(e); }

Program mu_program(const std::vector<GiNaC::ex>& es) { return MuPrinter(true).compile_many(es); }

}  // namespace iga::expression_detail
