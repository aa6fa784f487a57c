#include "config/expression_evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace iga::expression_detail {

namespace {

double step_function(double v) { return v > 0 ? 1.0 : (v < 0 ? 0.0 : 0.5); }  // GiNaC: step(0) = 1/2
double tgamma_function(double v) { return std::tgamma(v); }
double lgamma_function(double v) { return std::lgamma(v); }

}  // namespace

Evaluator::Evaluator(const Program& program) : temps_(program.temporaries) {
  for (const std::string& stage : program.stages) {
    auto parser = std::make_unique<mu::Parser>();
    parser->DefineConst("Pi", std::numbers::pi);
    parser->DefineVar("x", &x_);
    parser->DefineVar("y", &y_);
    parser->DefineVar("z", &z_);
    for (size_t i = 0; i < temps_.size(); ++i) parser->DefineVar("_t" + std::to_string(i), &temps_[i]);
    parser->DefineFun("step", step_function);
    parser->DefineFun("tgamma", tgamma_function);
    parser->DefineFun("lgamma", lgamma_function);
    parser->SetExpr(stage);
    parser->Eval();  // muParser compiles lazily: do it now, so a bad string fails here
    stages_.push_back(std::move(parser));
  }
}

Evaluator& EvaluatorCache::add(std::uint64_t id, std::weak_ptr<const void> owner, const Program& program) {
  if (entries_.size() >= purge_at_) {
    std::erase_if(entries_, [](const auto& kv) { return kv.second.owner.expired(); });
    purge_at_ = std::max<size_t>(64, 2 * entries_.size());
  }
  auto it = entries_.emplace(id, Entry{std::move(owner), std::make_unique<Evaluator>(program)}).first;
  return *remember(id, it->second.evaluator.get());
}

}  // namespace iga::expression_detail
