#include "solver/expression.hpp"

#include <ginac/ginac.h>
#include <muParser.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <mutex>
#include <numbers>
#include <optional>
#include <regex>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "solver/config_node.hpp"
#include "solver/errors.hpp"

namespace iga {

namespace {

// GiNaC counts references without atomics and shares global objects (0, 1, Pi, our x and y) among
// all expressions, so every touch of a GiNaC object goes through this lock; evaluation never does.
// Recursive because an Impl can die while its creator holds the lock. Leaked on purpose, like the
// symbols below, so static SymbolicFunctions may be destroyed in any order at exit.
std::recursive_mutex& ginac_mutex() {
  static auto* mutex = new std::recursive_mutex;
  return *mutex;
}

// Real symbols: with complex ones GiNaC keeps conjugate(x) in derivatives of abs().
const GiNaC::realsymbol& sym_x() {
  static const auto* s = new GiNaC::realsymbol("x");
  return *s;
}
const GiNaC::realsymbol& sym_y() {
  static const auto* s = new GiNaC::realsymbol("y");
  return *s;
}

/// Why an expression cannot be turned into muParser text (turned into an InputError by the caller).
struct Unsupported : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string number(double value) {
  char buf[40];
  auto end = std::to_chars(buf, buf + sizeof buf, value).ptr;  // shortest round-trip form, no locale
  return std::string(buf, end);
}

std::string ginac_text(const GiNaC::ex& e) {
  std::ostringstream out;
  out << e;
  return out.str();
}

/// Statements for muParser: "_t0=..., _t1=..., result", split in stages below muParser's length limit.
struct Program {
  std::vector<std::string> stages;  ///< run in order; the value of the last one is the result
  int temporaries = 0;
};

/// Prints GiNaC expressions for muParser. We print ourselves instead of using GiNaC's output: GiNaC
/// writes floats as "(2.5)", rationals as "1/2*x" and leaves precedence of unary minus and "^" to the
/// reader. Here every sign and power is printed so that any reasonable precedence rules agree.
class MuPrinter {
 public:
  /// program = false: one flat string (for str()); true: also hoist repeated function calls and powers
  /// into temporaries and keep every statement short.
  explicit MuPrinter(bool program) : program_(program) {}

  std::string flat(const GiNaC::ex& e) { return print(e).text; }

  Program compile(const GiNaC::ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
      // A negative power is printed as a denominator, i.e. through its positive counterpart.
      const GiNaC::ex key = is_negative_power(*it) ? GiNaC::power(it->op(0), -it->op(1)) : *it;
      if (worth_sharing(key)) ++uses_[key];
    }
    statements_.clear();
    const std::string result = print(e).text;
    Program program;
    program.temporaries = temporaries_;
    std::string stage;
    auto append = [&](const std::string& s) {
      if (!stage.empty() && stage.size() + s.size() + 2 > kStageLength)
        program.stages.push_back(std::move(stage)), stage.clear();
      stage += (stage.empty() ? "" : ", ") + s;
    };
    for (const std::string& s : statements_) append(s);
    append(result);
    program.stages.push_back(stage);
    return program;
  }

 private:
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

  static bool is_constant(const GiNaC::ex& e) { return !e.has(sym_x()) && !e.has(sym_y()); }

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
      if (name != "x" && name != "y") throw Unsupported("unknown symbol '" + name + "'");
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
    return "-" + (leading_atom ? p.text : wrap(p, kAtom));
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

  bool program_;
  int temporaries_ = 0;
  std::vector<std::string> statements_;
  std::map<GiNaC::ex, int, GiNaC::ex_is_less> uses_;
  std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> temps_;
};

double step_function(double v) { return v > 0 ? 1.0 : (v < 0 ? 0.0 : 0.5); }  // GiNaC: step(0) = 1/2
double tgamma_function(double v) { return std::tgamma(v); }
double lgamma_function(double v) { return std::lgamma(v); }

/// One thread's compiled muParser instances for one function. Variables are bound by address, so
/// this object never moves (held by unique_ptr) and `temps_` is never resized.
class Evaluator {
 public:
  explicit Evaluator(const Program& program) : temps_(program.temporaries) {
    for (const std::string& stage : program.stages) {
      auto parser = std::make_unique<mu::Parser>();
      parser->DefineConst("Pi", std::numbers::pi);
      parser->DefineVar("x", &x_);
      parser->DefineVar("y", &y_);
      for (size_t i = 0; i < temps_.size(); ++i) parser->DefineVar("_t" + std::to_string(i), &temps_[i]);
      parser->DefineFun("step", step_function);
      parser->DefineFun("tgamma", tgamma_function);
      parser->DefineFun("lgamma", lgamma_function);
      parser->SetExpr(stage);
      parser->Eval();  // muParser compiles lazily: do it now, so a bad string fails here
      stages_.push_back(std::move(parser));
    }
  }

  double operator()(double x, double y) {
    x_ = x;
    y_ = y;
    for (size_t i = 0; i + 1 < stages_.size(); ++i) stages_[i]->Eval();
    return stages_.back()->Eval();
  }

 private:
  double x_ = 0, y_ = 0;
  std::vector<double> temps_;
  std::vector<std::unique_ptr<mu::Parser>> stages_;
};

std::atomic<std::uint64_t> next_id{1};

std::string prefix(const std::string& where) { return where.empty() ? std::string() : where + ": "; }

/// Size of the expression tree, to pick the smaller of two equivalent forms.
size_t tree_size(const GiNaC::ex& e) {
  size_t n = 0;
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) ++n;
  return n;
}

/// Expanding collects like terms (products of cosines stay a short sum) but multiplies out powers of
/// sums; keep whichever form is smaller.
GiNaC::ex tidy(const GiNaC::ex& e) {
  GiNaC::ex expanded = e.expand();
  return tree_size(expanded) <= tree_size(e) ? expanded : e;
}

/// GiNaC's messages span lines and carry source locations (always "line 0, column 0"): keep the gist.
std::string parse_reason(const std::string& what) {
  std::string reason = what.substr(0, what.find('\n'));
  reason = std::regex_replace(reason, std::regex("^GiNaC: "), "");
  reason = std::regex_replace(reason, std::regex("^parse error at line [0-9]+, column [0-9]+: "), "");
  if (reason.find("power should have exactly 2 operands") != std::string::npos)
    return "GiNaC cannot chain '^'; add parentheses, e.g. a^(b^c)";
  std::smatch m;
  if (std::regex_search(reason, m, std::regex("symbol \"([^\"]*)\" not found"))) {
    reason = "unknown symbol '" + m[1].str() + "' (known: x, y, pi";
    const std::string near = nearest_word(m[1].str(), {"x", "y", "pi"});
    reason += near.empty() ? ")" : "; did you mean '" + near + "'?)";
  }
  return reason;
}

}  // namespace

struct SymbolicFunction::Impl {
  std::optional<GiNaC::ex> expr;  ///< touched only under ginac_mutex()
  std::string where;              ///< config place, for errors in derived functions
  std::string source;             ///< the text as written
  std::string text;               ///< str()
  Program program;
  bool zero = false;
  std::uint64_t id = next_id++;  ///< never reused, unlike addresses: keys the per-thread cache

  ~Impl() {
    std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
    expr.reset();
  }
};

namespace {

/// Per-thread compiled evaluators, keyed by Impl id. Entries of dead functions are purged when the
/// map has doubled since the last purge.
struct EvaluatorCache {
  struct Entry {
    std::weak_ptr<const SymbolicFunction::Impl> owner;
    std::unique_ptr<Evaluator> evaluator;
  };
  std::unordered_map<std::uint64_t, Entry> entries;
  std::uint64_t last_id = 0;
  Evaluator* last = nullptr;
  size_t purge_at = 64;

  Evaluator& get(const std::shared_ptr<const SymbolicFunction::Impl>& impl) {
    if (impl->id == last_id) return *last;
    auto it = entries.find(impl->id);
    if (it == entries.end()) {
      if (entries.size() >= purge_at) {
        std::erase_if(entries, [](const auto& kv) { return kv.second.owner.expired(); });
        purge_at = std::max<size_t>(64, 2 * entries.size());
      }
      it = entries.emplace(impl->id, Entry{impl, std::make_unique<Evaluator>(impl->program)}).first;
    }
    last_id = impl->id;
    last = it->second.evaluator.get();
    return *last;
  }
};

thread_local EvaluatorCache evaluator_cache;

/// Wrap a GiNaC expression (caller holds ginac_mutex()). Printing and compiling happen here, so an
/// expression that muParser cannot evaluate is an error at parse time, not a NaN later.
std::shared_ptr<const SymbolicFunction::Impl> make_impl(const GiNaC::ex& e, const std::string& where,
                                                        const std::string& source, const std::string& what) {
  auto impl = std::make_shared<SymbolicFunction::Impl>();
  impl->expr = e;
  impl->where = where;
  impl->source = source;
  impl->zero = e.is_zero();
  try {
    impl->text = MuPrinter(false).flat(e);
    impl->program = MuPrinter(true).compile(e);
    evaluator_cache.get(impl);
  } catch (const Unsupported& u) {
    throw InputError(prefix(where) + "cannot " + what + " '" + source + "': " + u.what());
  } catch (const mu::Parser::exception_type& err) {
    throw InputError(prefix(where) + "cannot " + what + " '" + source + "': muParser rejects '" +
                     err.GetExpr() + "': " + err.GetMsg());
  }
  return impl;
}

}  // namespace

SymbolicFunction SymbolicFunction::parse(const std::string& text, const std::string& where) {
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  GiNaC::ex e;
  try {
    GiNaC::symtab table;
    table["x"] = sym_x();
    table["y"] = sym_y();
    table["pi"] = GiNaC::Pi;
    GiNaC::parser reader(table, /*strict=*/true);
    e = reader(text);
  } catch (const std::exception& err) {
    throw InputError(prefix(where) + "cannot parse '" + text + "': " + parse_reason(err.what()));
  }
  SymbolicFunction f;
  f.impl_ = make_impl(e, where, text, "parse");
  return f;
}

SymbolicFunction SymbolicFunction::constant(double value) {
  if (!std::isfinite(value)) throw InputError("constant function: value " + number(value) + " is not finite");
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  SymbolicFunction f;
  f.impl_ = make_impl(GiNaC::numeric(value), "", number(value), "evaluate");
  return f;
}

namespace {

/// The Impl of `f`, or of the zero function for a default-constructed one.
std::shared_ptr<const SymbolicFunction::Impl> impl_or_zero(
    const std::shared_ptr<const SymbolicFunction::Impl>& impl) {
  if (impl) return impl;
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  static const auto* zero =
      new std::shared_ptr<const SymbolicFunction::Impl>(make_impl(0, "", "0", "evaluate"));
  return *zero;
}

}  // namespace

SymbolicFunction SymbolicFunction::diff_x() const {
  auto self = impl_or_zero(impl_);
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  SymbolicFunction f;
  f.impl_ = make_impl(tidy(self->expr->diff(sym_x())), self->where, self->source, "differentiate");
  return f;
}

SymbolicFunction SymbolicFunction::diff_y() const {
  auto self = impl_or_zero(impl_);
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  SymbolicFunction f;
  f.impl_ = make_impl(tidy(self->expr->diff(sym_y())), self->where, self->source, "differentiate");
  return f;
}

namespace {
GiNaC::ex laplace(const GiNaC::ex& u) { return tidy(u.diff(sym_x(), 2) + u.diff(sym_y(), 2)); }
}  // namespace

SymbolicFunction SymbolicFunction::laplacian() const {
  auto self = impl_or_zero(impl_);
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  SymbolicFunction f;
  f.impl_ = make_impl(laplace(*self->expr), self->where, self->source, "take the Laplacian of");
  return f;
}

SymbolicFunction SymbolicFunction::bilaplacian() const {
  auto self = impl_or_zero(impl_);
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  SymbolicFunction f;
  f.impl_ = make_impl(laplace(laplace(*self->expr)), self->where, self->source, "take the bilaplacian of");
  return f;
}

SymbolicFunction SymbolicFunction::operator-() const {
  auto self = impl_or_zero(impl_);
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  SymbolicFunction f;
  f.impl_ = make_impl(-*self->expr, self->where, self->source, "negate");
  return f;
}

bool SymbolicFunction::is_zero() const { return !impl_ || impl_->zero; }

std::string SymbolicFunction::str() const { return impl_ ? impl_->text : "0"; }

double SymbolicFunction::operator()(const Point2& p) const {
  if (!impl_) return 0.0;
  return evaluator_cache.get(impl_)(p.x(), p.y());
}

}  // namespace iga
