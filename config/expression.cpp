#include "config/expression.hpp"

#include <ginac/ginac.h>
#include <muParser.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <regex>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "config/expression_evaluator.hpp"
#include "config/expression_printer.hpp"
#include "config/expression_vector_program.hpp"

namespace iga {

using expression_detail::Evaluator;
using expression_detail::EvaluatorCache;
using expression_detail::mu_program;
using expression_detail::mu_text;
using expression_detail::number;
using expression_detail::Program;
using expression_detail::sym_x;
using expression_detail::sym_y;
using expression_detail::sym_z;
using expression_detail::Unsupported;

namespace {

// GiNaC counts references without atomics and shares global objects (0, 1, Pi, our x and y) among
// all expressions, so every touch of a GiNaC object goes through this lock; evaluation never does.
// Recursive because an Impl can die while its creator holds the lock. Leaked on purpose, like the
// symbols x and y, so static SymbolicFunctions may be destroyed in any order at exit.
std::recursive_mutex& ginac_mutex() {
  static auto* mutex = new std::recursive_mutex;
  return *mutex;
}

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
    // Copy the name out first: the match points into `reason`, which is about to be replaced.
    const std::string name = m[1].str();
    const std::string near = nearest_word(name, {"x", "y", "pi"});
    return "unknown symbol '" + name + "' (known: x, y, pi" + (near.empty() ? ")" : "; did you mean '" + near + "'?)");
  }
  return reason;
}

/// Skip blanks and '#' comments (to the end of the line) the way GiNaC's lexer does.
size_t skip_blank(const std::string& text, size_t i) {
  while (i < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      ++i;
    } else if (text[i] == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else {
      break;
    }
  }
  return i;
}

/// The first function called with no arguments ("cos()"), or "". GiNaC's prototype table treats an
/// argument count of 0 as "any count", so "cos()" finds cos/1, and GiNaC then evaluates cos on an
/// empty argument list and reads past it: such calls must never reach the parser.
std::string empty_call(const std::string& text) {
  for (size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (std::isdigit(c) || c == '.') {  // a number: digits and points, then an optional exponent
      auto digits = [&] {
        while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.')) ++i;
      };
      digits();
      if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
        digits();
      }
      continue;
    }
    if (!std::isalpha(c)) {
      ++i;
      continue;
    }
    const size_t start = i;
    while (i < text.size() && std::isalnum(static_cast<unsigned char>(text[i]))) ++i;
    const std::string name = text.substr(start, i - start);
    size_t j = skip_blank(text, i);
    if (j < text.size() && text[j] == '(') {
      j = skip_blank(text, j + 1);
      if (j < text.size() && text[j] == ')') return name;
    }
  }
  return {};
}

/// Text longer than this is not an expression anybody writes by hand.
constexpr size_t kMaxExpressionLength = 10000;
/// Parentheses and unary signs deeper than this: GiNaC's parser recurses once per level (100 000
/// levels overflow the stack) and derivatives of deep compositions grow without bound.
constexpr int kMaxNesting = 100;
/// Largest constant exponent: GiNaC evaluates integer powers exactly (2^1000000000 never ends).
constexpr double kMaxLiteralExponent = 1000;

/// The value of a symbol-free exponent such as "(3^2)" in double precision; nullopt when it has
/// symbols or is not understood (GiNaC then reports it).
std::optional<double> constant_value(const std::string& group) {
  for (const char c : group)
    if (std::isalpha(static_cast<unsigned char>(c)) && c != 'e' && c != 'E') return std::nullopt;
  try {
    mu::Parser parser;
    parser.SetExpr(group);
    return parser.Eval();
  } catch (const mu::Parser::exception_type&) {
    return std::nullopt;
  }
}

/// The closing parenthesis matching the one at `open`, or npos.
size_t matching_paren(const std::string& text, size_t open) {
  int depth = 0;
  for (size_t i = open; i < text.size(); ++i) {
    if (text[i] == '(') ++depth;
    if (text[i] == ')' && --depth == 0) return i;
  }
  return std::string::npos;
}

/// The first number literal whose decimal exponent is out of double range (GiNaC reads "1e999999"
/// as an exact rational and computes 10^999999), or "".
std::string huge_number(const std::string& text) {
  for (size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (std::isalpha(c) || c == '_') {  // a name: letters and digits (x1 is no number)
      while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) ++i;
      continue;
    }
    if (!std::isdigit(c) && c != '.') {
      ++i;
      continue;
    }
    const size_t start = i;
    while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.')) ++i;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
      size_t j = i + 1;
      if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
      const size_t digits = j;
      while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
      if (j - digits > 3 || (j > digits && std::stoi(text.substr(digits, j - digits)) > 308))
        return text.substr(start, std::min<size_t>(j - start, 40));
      i = j;
    }
  }
  return {};
}

/// Why `text` must not reach GiNaC (empty when it may): calls without arguments, huge texts, deep
/// nesting, power towers and huge literal exponents, all of which crash or hang the parser or the
/// exact arithmetic behind it.
std::string hostile_text(const std::string& text) {
  if (const std::string name = empty_call(text); !name.empty()) return "function '" + name + "' called with no arguments";
  if (text.size() > kMaxExpressionLength)
    return "longer than " + std::to_string(kMaxExpressionLength) + " characters";
  if (const std::string number = huge_number(text); !number.empty())
    return "the number '" + number + "' is out of range (decimal exponents up to 308)";
  int depth = 0, signs = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(' && ++depth > kMaxNesting) return "nested more than " + std::to_string(kMaxNesting) + " levels deep";
    if (c == ')') --depth;
    if (c == '+' || c == '-') {
      if (++signs > kMaxNesting) return "more than " + std::to_string(kMaxNesting) + " signs in a row";
    } else if (!std::isspace(static_cast<unsigned char>(c))) {
      signs = 0;
    }
    if (c != '^') continue;
    size_t j = skip_blank(text, i + 1);
    while (j < text.size() && (text[j] == '+' || text[j] == '-')) j = skip_blank(text, j + 1);
    // GiNaC raises exact integers to exact integer powers: 2^(2^40) never ends. A literal exponent
    // or one without symbols (evaluated here in double precision) must stay below the bound.
    // (GiNaC itself refuses a^b^c without parentheses.)
    std::optional<double> exponent;
    if (j < text.size() && text[j] == '(') {
      const size_t end = matching_paren(text, j);
      if (end != std::string::npos) exponent = constant_value(text.substr(j, end + 1 - j));
    } else if (j < text.size() && (std::isdigit(static_cast<unsigned char>(text[j])) || text[j] == '.')) {
      exponent = std::strtod(text.c_str() + j, nullptr);
    }
    if (exponent && !(std::fabs(*exponent) <= kMaxLiteralExponent))
      return "an exponent larger than " + std::to_string(static_cast<int>(kMaxLiteralExponent)) +
             " in magnitude (exact powers of that size do not end)";
  }
  return {};
}

/// `text` shortened for messages.
std::string quoted(const std::string& text) {
  return "'" + (text.size() > 80 ? text.substr(0, 77) + "..." : text) + "'";
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

/// This thread's evaluator of `impl`, compiled on first use.
Evaluator& evaluator(const std::shared_ptr<const SymbolicFunction::Impl>& impl) {
  EvaluatorCache& cache = EvaluatorCache::this_thread();
  if (Evaluator* e = cache.find(impl->id)) return *e;
  return cache.add(impl->id, impl, impl->program);
}

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
    impl->text = mu_text(e);
    impl->program = mu_program(e);
    evaluator(impl);
  } catch (const Unsupported& u) {
    throw InputError(prefix(where) + "cannot " + what + " '" + source + "': " + u.what());
  } catch (const mu::Parser::exception_type& err) {
    throw InputError(prefix(where) + "cannot " + what + " '" + source + "': muParser rejects '" +
                     err.GetExpr() + "': " + err.GetMsg());
  }
  return impl;
}

}  // namespace

namespace {

/// The GiNaC expression of `text` in x, y (and z when `with_z`), after the checks of hostile_text.
GiNaC::ex parse_ginac(const std::string& text, const std::string& where, bool with_z) {
  if (const std::string why = hostile_text(text); !why.empty())
    throw InputError(prefix(where) + "cannot parse " + quoted(text) + ": " + why);
  try {
    GiNaC::symtab table;
    table["x"] = sym_x();
    table["y"] = sym_y();
    if (with_z) table["z"] = sym_z();
    table["pi"] = GiNaC::Pi;
    GiNaC::parser reader(table, /*strict=*/true);
    return reader(text);
  } catch (const std::exception& err) {
    std::string reason = parse_reason(err.what());
    const std::string planar = "(known: x, y, pi";
    if (const auto at = reason.find(planar); with_z && at != std::string::npos)
      reason.replace(at, planar.size(), "(known: x, y, z, pi");
    throw InputError(prefix(where) + "cannot parse '" + text + "': " + reason);
  }
}

}  // namespace

SymbolicFunction SymbolicFunction::parse(const std::string& text, const std::string& where) {
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  SymbolicFunction f;
  f.impl_ = make_impl(parse_ginac(text, where, false), where, text, "parse");
  return f;
}

SymbolicFunction SymbolicFunction::parse_xyz(const std::string& text, const std::string& where) {
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  SymbolicFunction f;
  f.impl_ = make_impl(parse_ginac(text, where, true), where, text, "parse");
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

/// d/ds of `impl` (the zero function for none).
std::shared_ptr<const SymbolicFunction::Impl> derivative(const std::shared_ptr<const SymbolicFunction::Impl>& impl,
                                                         const GiNaC::symbol& s) {
  auto self = impl_or_zero(impl);
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  return make_impl(tidy(self->expr->diff(s)), self->where, self->source, "differentiate");
}

}  // namespace

SymbolicFunction SymbolicFunction::diff_x() const {
  SymbolicFunction f;
  f.impl_ = derivative(impl_, sym_x());
  return f;
}

SymbolicFunction SymbolicFunction::diff_y() const {
  SymbolicFunction f;
  f.impl_ = derivative(impl_, sym_y());
  return f;
}

SymbolicFunction SymbolicFunction::diff_z() const {
  SymbolicFunction f;
  f.impl_ = derivative(impl_, sym_z());
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

double SymbolicFunction::operator()(const Eigen::Vector2d& p) const {
  if (!impl_) return 0.0;
  return evaluator(impl_)(p.x(), p.y());
}

double SymbolicFunction::at(const Eigen::Vector3d& p) const {
  if (!impl_) return 0.0;
  return evaluator(impl_)(p.x(), p.y(), p.z());
}

struct FunctionBatch::Impl {
  std::optional<expression_detail::VectorProgram> vector;  ///< preferred; else the muParser program
  Program program;
  int size = 0;
  std::uint64_t id = next_id++;  ///< keys the per-thread cache, like SymbolicFunction's
};

FunctionBatch::FunctionBatch(const std::vector<SymbolicFunction>& functions) {
  auto impl = std::make_shared<Impl>();
  impl->size = static_cast<int>(functions.size());
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  std::vector<GiNaC::ex> es;
  std::string where;
  for (const SymbolicFunction& f : functions) {
    const auto self = impl_or_zero(f.impl_);
    es.push_back(*self->expr);
    if (where.empty()) where = self->where;
  }
  impl->vector = expression_detail::vector_program(es);
  if (impl->vector) {
    impl_ = std::move(impl);
    return;
  }
  try {
    impl->program = mu_program(es);
    EvaluatorCache::this_thread().add(impl->id, impl, impl->program);  // compile now: errors here
  } catch (const Unsupported& u) {
    throw InputError(prefix(where) + "cannot evaluate: " + u.what());
  } catch (const mu::Parser::exception_type& err) {
    throw InputError(prefix(where) + "cannot evaluate: muParser rejects '" + err.GetExpr() + "': " + err.GetMsg());
  }
  impl_ = std::move(impl);
}

int FunctionBatch::size() const { return impl_->size; }

void FunctionBatch::evaluate(const Eigen::Matrix2Xd& points, Eigen::MatrixXd& values) const {
  const int m = impl_->size;
  const Eigen::Index q = points.cols();
  values.resize(m, q);
  if (impl_->vector) {
    using expression_detail::VectorProgram;
    thread_local std::vector<double> work;
    double x[VectorProgram::kBlock], y[VectorProgram::kBlock];
    for (Eigen::Index first = 0; first < q; first += VectorProgram::kBlock) {
      const int count = static_cast<int>(std::min<Eigen::Index>(VectorProgram::kBlock, q - first));
      for (int k = 0; k < count; ++k) x[k] = points(0, first + k), y[k] = points(1, first + k);
      impl_->vector->run(x, y, count, work, values.data() + first * m, m);
    }
    return;
  }
  EvaluatorCache& cache = EvaluatorCache::this_thread();
  Evaluator* e = cache.find(impl_->id);
  if (!e) e = &cache.add(impl_->id, impl_, impl_->program);
  const std::vector<int>& results = impl_->program.results;
  for (Eigen::Index k = 0; k < points.cols(); ++k) {
    (*e)(points(0, k), points(1, k));
    for (int i = 0; i < m; ++i) values(i, k) = e->temporary(results[i]);
  }
}

}  // namespace iga
