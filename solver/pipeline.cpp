#include "solver/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "config/errors.hpp"
#include "config/progress.hpp"

namespace iga {

namespace {
bool finite(const ErrorNorms& e) {
  return std::isfinite(e.l2) && std::isfinite(e.h1.value_or(0)) && std::isfinite(e.h2.value_or(0));
}
}  // namespace

Constraints assemble_level(const Formulation& f, LinearBackend& backend, LevelResult& r, const ProgressSink& progress) {
  const Space& space = f.space();
  r.h = space.mesh_size();
  r.dofs = f.unknowns();
  r.elements = space.num_elements();
  Stopwatch clock;
  const WorkShare share = backend.share();
  // Ticks: one per element of the matrix loop and of the load loop (whole assemblies only).
  const std::int64_t ticks = share.elements ? 0 : 2 * static_cast<std::int64_t>(f.space().num_elements());
  std::optional<ProgressPhase> phase;
  Eigen::VectorXd b;
  Constraints c;
  backend.locally([&] {
    f.check();
    if (progress) progress("assembling");
    phase.emplace("assembling", ticks);
    // NaN or inf data (sqrt of a negative number, a pole inside the domain) is bad input, not a
    // numerical failure: say which datum it was before the solver reports a singular system.
    b = f.load(share);
    if (!b.allFinite()) throw InputError(f.messages().load);
    c = f.constraints();
    if (!c.values.allFinite()) throw InputError(f.messages().boundary_data);
    if (progress)
      for (const std::string& note : f.notes()) progress(note);
  });
  backend.assemble(f, c, b, progress);
  phase.reset();  // the phase (its progress line) ends with the assembly, inside t_assemble
  r.t_assemble = clock.seconds();
  r.notes = f.notes();
  r.free_dofs = static_cast<int>(c.free.size());
  backend.count_whole(f, r);
  return c;
}

DiscreteSolution solve_pipeline(const Formulation& f, LinearBackend& backend, const ProgressSink& progress) {
  const Space& space = f.space();
  DiscreteSolution out;
  LevelResult& r = out.result;
  const Constraints c = assemble_level(f, backend, r, progress);

  Stopwatch clock;
  const WorkShare share = backend.share();
  out.coefficients = backend.solve(out.solve, progress);
  f.finish(out.coefficients, share);
  if (f.reports_energy()) r.energy = backend.energy(out.coefficients);  // for studies without an exact solution
  r.t_solve = clock.seconds();

  // Each component's gradient jump (a vector field: the largest of its components').
  const int n = space.dimension();
  for (int c = 0; c < f.components(); ++c)
    if (const auto jump = space.max_gradient_jump(out.coefficients.segment(c * n, n)))
      r.g1_jump = std::max(r.g1_jump.value_or(0.0), share.max(*jump));
  if (f.has_exact()) {
    if (progress) progress("computing errors");
    clock.restart();
    std::optional<ProgressPhase> phase(std::in_place, "error norms", share.elements ? 0 : space.num_elements());
    ErrorNorms e = f.errors(out.coefficients, share);
    if (share.elements) {  // squared integrals add up over the shares
      const auto whole = [&](double part) { return std::sqrt(share.sum(part * part)); };
      e.l2 = whole(e.l2);
      if (e.h1) e.h1 = whole(*e.h1);
      if (e.h2) e.h2 = whole(*e.h2);
    }
    if (!finite(e)) throw InputError(f.messages().exact);
    r.l2 = e.l2;
    r.h1 = e.h1;
    r.h2 = e.h2;
    r.t_errors = clock.seconds();
  }
  return out;
}

}  // namespace iga
