#pragma once
/// @file
/// Internal to SymbolicFunction: evaluation of printed expressions with muParser. A Program (made
/// by expression_printer) is compiled once per thread into an Evaluator; each thread keeps its own
/// because a muParser instance binds its variables by address and is not thread-safe.

#include <muParser.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace iga::expression_detail {

/// Statements for muParser: "_t0=..., _t1=..., result", split in stages below muParser's length limit.
/// Reads the variables x, y (and z for functions on surfaces), the constant Pi, the temporaries _t<i> and muParser's functions plus
/// step, tgamma and lgamma.
struct Program {
  std::vector<std::string> stages;  ///< run in order; the value of the last one is the result
  int temporaries = 0;
  std::vector<int> results;  ///< several functions at once: the temporary holding each one's value
};

/// One thread's compiled muParser instances for one function. Variables are bound by address, so
/// this object never moves (held by unique_ptr) and `temps_` is never resized.
class Evaluator {
 public:
  /// Compiles every stage now. Throws mu::Parser::exception_type if muParser rejects one.
  explicit Evaluator(const Program& program);

  double operator()(double x, double y) {
    x_ = x;
    y_ = y;
    for (size_t i = 0; i + 1 < stages_.size(); ++i) stages_[i]->Eval();
    return stages_.back()->Eval();
  }
  /// The same at a point in 3D (functions of x, y, z).
  double operator()(double x, double y, double z) {
    z_ = z;
    return (*this)(x, y);
  }
  /// Temporary i after the last evaluation (the results of a program of several functions).
  double temporary(int i) const { return temps_[i]; }

 private:
  double x_ = 0, y_ = 0, z_ = 0;
  std::vector<double> temps_;
  std::vector<std::unique_ptr<mu::Parser>> stages_;
};

/// One thread's compiled evaluators, keyed by function id. Entries of dead functions are purged when
/// the map has doubled since the last purge.
class EvaluatorCache {
 public:
  /// The calling thread's cache.
  static EvaluatorCache& this_thread() {
    thread_local EvaluatorCache cache;
    return cache;
  }

  /// The evaluator of function `id`, or null if this thread has not compiled it yet. Inline: this is
  /// on the path of every evaluation, and hits the last-used entry almost always.
  Evaluator* find(std::uint64_t id) {
    if (id == last_id_) return last_;
    auto it = entries_.find(id);
    if (it == entries_.end()) return nullptr;
    return remember(id, it->second.evaluator.get());
  }

  /// Compile `program` as function `id` (not yet in the cache), kept while `owner` is alive.
  /// Throws like Evaluator's constructor; the cache is then left without the entry.
  Evaluator& add(std::uint64_t id, std::weak_ptr<const void> owner, const Program& program);

 private:
  struct Entry {
    std::weak_ptr<const void> owner;
    std::unique_ptr<Evaluator> evaluator;
  };

  Evaluator* remember(std::uint64_t id, Evaluator* evaluator) {
    last_id_ = id;
    last_ = evaluator;
    return evaluator;
  }

  std::unordered_map<std::uint64_t, Entry> entries_;
  std::uint64_t last_id_ = 0;  ///< ids start at 1
  Evaluator* last_ = nullptr;
  size_t purge_at_ = 64;
};

}  // namespace iga::expression_detail
