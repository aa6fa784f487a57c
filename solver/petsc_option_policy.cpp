#include "solver/petsc_option_policy.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string_view>

#include "config/config_node.hpp"
#include "config/errors.hpp"

namespace iga {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// What an option's value may be. None of them can name a file: a viewer prints to standard
/// output only, the other kinds are numbers, booleans or words of a fixed set.
enum class Kind {
  boolean,   ///< no value, or true/false/yes/no/on/off/1/0
  viewer,    ///< no value, or ":stdout" / "ascii:stdout" (standard output)
  integer,   ///< an integer in [lo, hi]
  real,      ///< a finite number in [lo, hi]
  reals,     ///< finite numbers separated by commas ("0.02,0.01")
  integers,  ///< integers separated by commas, each in [lo, hi]
  choice,    ///< one of `choices` (case-insensitive, as PETSc compares them)
};

struct Rule {
  std::string_view name;  ///< lower case, without the leading '-'
  Kind kind;
  double lo = -kInf, hi = kInf;  ///< for reals and integers: each number's range
  std::vector<std::string_view> choices = {};
  bool prefixable = false;  ///< a KSP or PC option: also with sub_, mg_levels_, mg_coarse_
  /// The upper bound with a prefix: an inner solve runs once per outer iteration (or per block,
  /// per smoothing step), so its iteration count multiplies the work of the whole solve.
  double inner_hi = kInf;
};

const std::vector<std::string_view> kPrefixes = {"sub_", "mg_levels_", "mg_coarse_"};

/// The memory estimate that guards a run (solver/resource_checks.cpp) knows the config's `pc:` key
/// only, and nothing else limits what a solve may allocate (no address-space limit on the program).
/// So the options must not turn an iterative preconditioner into a factorization or into one
/// whose memory grows with a value: no factorization types (a factorization is chosen with `pc:`),
/// no multigrid level counts (one level makes the coarse solve a factorization of the whole
/// matrix; hypre's is dense), and small bounds on the sizes PETSc allocates from (Krylov bases,
/// fill, block counts, coarse grid sizes, MUMPS workspace) and on the counts that multiply the
/// work of every iteration (sweeps, inner iterations, cycles).
const std::vector<Rule>& rules() {
  static const std::vector<Rule> list = [] {
    const std::vector<std::string_view> hypre_relax = {
        "Jacobi", "sequential-Gauss-Seidel", "seqboundary-Gauss-Seidel", "SOR/Jacobi", "backward-SOR/Jacobi",
        "symmetric-SOR/Jacobi", "l1scaled-SOR/Jacobi", "Gaussian-elimination", "l1-Gauss-Seidel",
        "backward-l1-Gauss-Seidel", "CG", "Chebyshev", "FCF-Jacobi", "l1scaled-Jacobi"};
    std::vector<Rule> r = {
        // Krylov method
        {"ksp_type", Kind::choice, 0, 0,
         {"cg", "gmres", "fgmres", "lgmres", "dgmres", "bcgs", "bcgsl", "ibcgs", "fbcgs", "minres", "symmlq", "cr",
          "gcr", "preonly", "richardson", "chebyshev", "tfqmr", "cgs", "bicg", "fcg", "pipecg", "pipecr", "groppcg"},
         true},
        {"ksp_rtol", Kind::real, 0, 1, {}, true},
        {"ksp_atol", Kind::real, 0, kInf, {}, true},
        {"ksp_divtol", Kind::real, 0, kInf, {}, true},
        {"ksp_max_it", Kind::integer, 0, kMaxIterations, {}, true, 100},
        {"ksp_min_it", Kind::integer, 0, kMaxIterations, {}, true, 100},
        {"ksp_norm_type", Kind::choice, 0, 0, {"none", "preconditioned", "unpreconditioned", "natural"}, true},
        // No symmetric side: few pairs support it, and PETSc crashes on some (gmres + eisenstat).
        {"ksp_pc_side", Kind::choice, 0, 0, {"left", "right"}, true},
        {"ksp_initial_guess_nonzero", Kind::boolean, 0, 0, {}, true},
        {"ksp_gmres_restart", Kind::integer, 1, 200, {}, true},
        {"ksp_gmres_modifiedgramschmidt", Kind::boolean, 0, 0, {}, true},
        {"ksp_gmres_classicalgramschmidt", Kind::boolean, 0, 0, {}, true},
        {"ksp_gmres_cgs_refinement_type", Kind::choice, 0, 0, {"refine_never", "refine_ifneeded", "refine_always"}, true},
        {"ksp_lgmres_augment", Kind::integer, 0, 30, {}, true},
        {"ksp_bcgsl_ell", Kind::integer, 1, 20, {}, true},
        {"ksp_richardson_scale", Kind::real, -kInf, kInf, {}, true},
        {"ksp_richardson_self_scale", Kind::boolean, 0, 0, {}, true},
        {"ksp_chebyshev_eigenvalues", Kind::reals, -kInf, kInf, {}, true},
        {"ksp_chebyshev_esteig", Kind::reals, -kInf, kInf, {}, true},
        {"ksp_chebyshev_esteig_steps", Kind::integer, 1, 100, {}, true},
        {"ksp_diagonal_scale", Kind::boolean, 0, 0, {}, true},
        {"ksp_diagonal_scale_fix", Kind::boolean, 0, 0, {}, true},
        // monitors and views: standard output only
        {"ksp_monitor", Kind::viewer, 0, 0, {}, true},
        {"ksp_monitor_short", Kind::viewer, 0, 0, {}, true},
        {"ksp_monitor_true_residual", Kind::viewer, 0, 0, {}, true},
        {"ksp_monitor_singular_value", Kind::viewer, 0, 0, {}, true},
        {"ksp_monitor_max", Kind::viewer, 0, 0, {}, true},
        {"ksp_monitor_range", Kind::viewer, 0, 0, {}, true},
        {"ksp_monitor_cancel", Kind::boolean, 0, 0, {}, true},
        {"ksp_converged_reason", Kind::viewer, 0, 0, {}, true},
        {"ksp_converged_rate", Kind::viewer, 0, 0, {}, true},
        {"ksp_view", Kind::viewer, 0, 0, {}, true},
        {"ksp_view_pre", Kind::viewer, 0, 0, {}, true},
        // preconditioner: no lu, cholesky or icc, also not for blocks or the coarse solve (above)
        {"pc_type", Kind::choice, 0, 0,
         {"none", "jacobi", "pbjacobi", "bjacobi", "asm", "sor", "eisenstat", "ilu", "gamg", "hypre"}, true},
        {"pc_factor_mat_solver_type", Kind::choice, 0, 0, {"petsc", "mumps"}, true},
        // ILU(k) keeps about as much memory as the matrix for small k only.
        {"pc_factor_levels", Kind::integer, 0, 3, {}, true},
        {"pc_factor_fill", Kind::real, 1, 10, {}, true},
        // The fill-reducing orderings only: a banded one (natural, rcm, ...) gives the factor of
        // `pc: cholesky` far more fill than the memory estimate assumes.
        {"pc_factor_mat_ordering_type", Kind::choice, 0, 0, {"nd", "qmd"}, true},
        {"pc_factor_shift_type", Kind::choice, 0, 0, {"none", "nonzero", "positive_definite", "inblocks"}, true},
        {"pc_factor_shift_amount", Kind::real, 0, kInf, {}, true},
        {"pc_factor_zeropivot", Kind::real, 0, kInf, {}, true},
        {"pc_factor_diagonal_fill", Kind::boolean, 0, 0, {}, true},
        {"pc_factor_reuse_ordering", Kind::boolean, 0, 0, {}, true},
        {"pc_factor_reuse_fill", Kind::boolean, 0, 0, {}, true},
        {"pc_factor_pivot_in_blocks", Kind::boolean, 0, 0, {}, true},
        {"pc_jacobi_type", Kind::choice, 0, 0, {"diagonal", "rowmax", "rowsum"}, true},
        {"pc_jacobi_abs", Kind::boolean, 0, 0, {}, true},
        {"pc_jacobi_fixdiagonal", Kind::boolean, 0, 0, {}, true},
        // Every block is a matrix, a KSP and a PC of its own (100000 blocks of 25 unknowns took 3 GB).
        // ASM keeps one block per rank: its blocks are row ranges widened by the overlap, so many
        // small blocks each carry a halo of several grid rows (1024 blocks with overlap 2 and ILU(3)
        // took 1.4 GB and over 120 s where one block per rank took 0.23 GB and 8 s).
        {"pc_bjacobi_blocks", Kind::integer, 1, 1024, {}, true},
        {"pc_bjacobi_local_blocks", Kind::integer, 1, 1024, {}, true},
        {"pc_asm_overlap", Kind::integer, 0, 2, {}, true},
        {"pc_asm_type", Kind::choice, 0, 0, {"basic", "restrict", "interpolate", "none"}, true},
        {"pc_asm_local_type", Kind::choice, 0, 0, {"additive", "multiplicative"}, true},
        {"pc_sor_omega", Kind::real, 0, 2, {}, true},
        {"pc_sor_its", Kind::integer, 1, 20, {}, true},
        {"pc_sor_lits", Kind::integer, 1, 20, {}, true},
        {"pc_sor_symmetric", Kind::boolean, 0, 0, {}, true},
        {"pc_sor_forward", Kind::boolean, 0, 0, {}, true},
        {"pc_sor_backward", Kind::boolean, 0, 0, {}, true},
        {"pc_sor_local_symmetric", Kind::boolean, 0, 0, {}, true},
        {"pc_sor_local_forward", Kind::boolean, 0, 0, {}, true},
        {"pc_sor_local_backward", Kind::boolean, 0, 0, {}, true},
        {"pc_sor_diagonal_shift", Kind::real, -kInf, kInf, {}, true},
        // multigrid (GAMG is PETSc's multigrid with algebraic coarse spaces); the coarse solve is a
        // factorization, so the levels are GAMG's choice and the coarse size is small
        // (no -pc_mg_levels: one level would factor the whole matrix).
        {"pc_mg_cycle_type", Kind::choice, 0, 0, {"v", "w"}},
        {"pc_mg_type", Kind::choice, 0, 0, {"multiplicative", "additive", "full", "kaskade"}},
        {"pc_mg_galerkin", Kind::choice, 0, 0, {"both", "pmat", "mat", "none", "external"}},
        {"pc_mg_multiplicative_cycles", Kind::integer, 1, 10},
        {"pc_mg_distinct_smoothup", Kind::boolean},
        {"pc_gamg_type", Kind::choice, 0, 0, {"agg", "geo", "classical"}},
        {"pc_gamg_agg_nsmooths", Kind::integer, 0, 2},  // each smoothing widens the interpolation
        // A high threshold drops the couplings aggregation needs: coarsening stalls and the coarse
        // factorization gets the size of the matrix.
        {"pc_gamg_threshold", Kind::reals, -1, 0.1},
        {"pc_gamg_threshold_scale", Kind::real, 0, 1},
        {"pc_gamg_square_graph", Kind::integer, 0, 2},  // a squared graph has far more entries
        {"pc_gamg_aggressive_coarsening", Kind::integer, 0, 2},
        {"pc_gamg_coarse_eq_limit", Kind::integer, 1, 10000},
        {"pc_gamg_process_eq_limit", Kind::integer, 1, 1e9},
        {"pc_gamg_repartition", Kind::boolean},
        {"pc_gamg_reuse_interpolation", Kind::boolean},
        {"pc_gamg_asm_use_agg", Kind::boolean},
        {"pc_gamg_use_parallel_coarse_grid_solver", Kind::boolean},
        {"pc_gamg_cpu_pin_coarse_grids", Kind::boolean},
        {"pc_gamg_coarse_grid_layout_type", Kind::choice, 0, 0, {"compact", "spread"}},
        {"pc_gamg_use_sa_esteig", Kind::boolean},
        {"pc_gamg_eigenvalues", Kind::reals},
        {"pc_gamg_rank_reduction_factors", Kind::integers, 1, 1e6},
        // hypre: BoomerAMG only. Euclid (also as a BoomerAMG smoother) reads a file ./database.
        // Its coarsest level is solved by dense Gaussian elimination: no -max_levels, a small
        // coarse size. The options for systems of PDEs (nodal coarsening, number of functions,
        // vector interpolation) are left out: our problems are scalar, and hypre crashes on a
        // matrix whose size is no multiple of the number of functions.
        {"pc_hypre_type", Kind::choice, 0, 0, {"boomeramg"}},
        {"pc_hypre_boomeramg_strong_threshold", Kind::real, 0, 1},
        {"pc_hypre_boomeramg_max_iter", Kind::integer, 1, 10},
        {"pc_hypre_boomeramg_tol", Kind::real, 0, kInf},
        {"pc_hypre_boomeramg_truncfactor", Kind::real, 0, 1},
        {"pc_hypre_boomeramg_p_max", Kind::integer, 0, 1000},
        {"pc_hypre_boomeramg_agg_nl", Kind::integer, 0, 100},
        {"pc_hypre_boomeramg_agg_num_paths", Kind::integer, 1, 100},
        {"pc_hypre_boomeramg_max_row_sum", Kind::real, 0, 1},
        {"pc_hypre_boomeramg_coarsen_type", Kind::choice, 0, 0,
         {"CLJP", "Ruge-Stueben", "modifiedRuge-Stueben", "Falgout", "PMIS", "HMIS"}},
        {"pc_hypre_boomeramg_interp_type", Kind::choice, 0, 0,
         {"classical", "direct", "multipass", "multipass-wts", "ext+i", "ext+i-cc", "standard", "standard-wts", "block",
          "block-wtd", "FF", "FF1", "ext", "ad-wts", "ext-mm", "ext+i-mm", "ext+e-mm"}},
        {"pc_hypre_boomeramg_relax_type_all", Kind::choice, 0, 0, hypre_relax},
        {"pc_hypre_boomeramg_relax_type_down", Kind::choice, 0, 0, hypre_relax},
        {"pc_hypre_boomeramg_relax_type_up", Kind::choice, 0, 0, hypre_relax},
        {"pc_hypre_boomeramg_relax_type_coarse", Kind::choice, 0, 0, hypre_relax},
        {"pc_hypre_boomeramg_grid_sweeps_all", Kind::integer, 1, 20},
        {"pc_hypre_boomeramg_grid_sweeps_down", Kind::integer, 1, 20},
        {"pc_hypre_boomeramg_grid_sweeps_up", Kind::integer, 1, 20},
        {"pc_hypre_boomeramg_grid_sweeps_coarse", Kind::integer, 1, 20},
        {"pc_hypre_boomeramg_relax_weight_all", Kind::real},
        {"pc_hypre_boomeramg_outer_relax_weight_all", Kind::real},
        {"pc_hypre_boomeramg_measure_type", Kind::choice, 0, 0, {"local", "global"}},
        {"pc_hypre_boomeramg_smooth_type", Kind::choice, 0, 0, {"Schwarz-smoothers", "Pilut", "ParaSails"}},
        {"pc_hypre_boomeramg_smooth_num_levels", Kind::integer, 0, 25},
        {"pc_hypre_boomeramg_cycle_type", Kind::choice, 0, 0, {"V", "W"}},
        {"pc_hypre_boomeramg_max_coarse_size", Kind::integer, 1, 1000},
        {"pc_hypre_boomeramg_min_coarse_size", Kind::integer, 1, 1000},
        {"pc_hypre_boomeramg_no_cf", Kind::boolean},
        {"pc_hypre_boomeramg_keeptranspose", Kind::boolean},
        {"pc_hypre_boomeramg_restriction_type", Kind::integer, 0, 2},
    };
    return r;
  }();
  return list;
}

/// MUMPS control parameters a config may set, with their ranges. Left out: ICNTL(1-3), Fortran
/// output units (a unit other than 6 writes a file fort.N); ICNTL(22), out-of-core factorization
/// into files; ICNTL(23), the working memory MUMPS allocates; ICNTL(28-29), parallel analysis
/// (it needs ParMETIS or PT-Scotch, which the installed MUMPS may lack); and those PETSc sets
/// itself (distribution, Schur complement, right-hand sides). ICNTL(14), the percentage of extra
/// workspace, is allocated from; each of the ICNTL(10) steps of iterative refinement is a solve.
const std::map<int, std::pair<double, double>> kMumpsIcntl = {
    {4, {0, 4}},   {6, {0, 7}},  {7, {0, 7}},  {8, {-2, 77}}, {10, {-10, 10}}, {11, {0, 2}},    {12, {0, 3}},
    {13, {-1, 1}}, {14, {0, 100}}, {24, {0, 1}}, {27, {-512, 512}}, {35, {0, 3}}, {36, {0, 1}}, {37, {0, 1}},
    {38, {0, 1000}}};
const std::map<int, std::pair<double, double>> kMumpsCntl = {{1, {0, 1}}, {2, {0, 1}}, {3, {-1e6, 1e6}},
                                                             {4, {-1, 1e6}}, {5, {0, 1e6}}, {7, {0, 1}}};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

bool is_name(const std::string& word) {
  return word.size() > 1 && word[0] == '-' && std::isalpha(static_cast<unsigned char>(word[1]));
}

/// The rule for `name` (lower case, without '-'), if the config may set it.
std::optional<Rule> find_rule(const std::string& name) {
  for (const Rule& r : rules())
    if (r.name == name) return r;
  for (std::string_view prefix : kPrefixes)
    if (name.compare(0, prefix.size(), prefix) == 0) {
      const std::string rest = name.substr(prefix.size());
      for (Rule r : rules())
        if (r.prefixable && r.name == rest) {
          r.hi = std::min(r.hi, r.inner_hi);
          return r;
        }
    }
  for (const auto& [family, allowed, kind] :
       {std::tuple{std::string_view("mat_mumps_icntl_"), &kMumpsIcntl, Kind::integer},
        std::tuple{std::string_view("mat_mumps_cntl_"), &kMumpsCntl, Kind::real}}) {
    if (name.compare(0, family.size(), family) != 0) continue;
    const std::string digits = name.substr(family.size());
    if (digits.empty() || digits.size() > 2 || digits[0] == '0' ||
        !std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      return std::nullopt;
    const auto range = allowed->find(std::stoi(digits));
    if (range == allowed->end()) return std::nullopt;
    return Rule{"", kind, range->second.first, range->second.second};
  }
  return std::nullopt;
}

bool integral(const Rule& r) { return r.kind == Kind::integer || r.kind == Kind::integers; }

/// The whole of `s` (a leading '+' allowed) as an integer (`integral`) or a finite number.
std::optional<double> to_number(std::string_view s, bool integral) {
  double x = 0;
  long long n = 0;
  const char* end = s.data() + s.size();
  const char* begin = s.data() + (!s.empty() && s[0] == '+' ? 1 : 0);
  const auto [ptr, ec] =
      integral ? std::from_chars(begin, end, n) : std::from_chars(begin, end, x, std::chars_format::general);
  if (ec != std::errc() || ptr != end || begin == end || !std::isfinite(x)) return std::nullopt;
  return integral ? static_cast<double>(n) : x;
}

std::vector<std::string_view> split_commas(std::string_view s) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t comma = s.find(',', start);
    out.push_back(s.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

std::string range_text(const Rule& r) {
  const auto number = [&](double x) { return integral(r) ? std::to_string(static_cast<long long>(x)) : format_number(x); };
  if (r.lo == -kInf && r.hi == kInf) return "";
  if (r.hi == kInf) return " >= " + number(r.lo);
  if (r.lo == -kInf) return " <= " + number(r.hi);
  return " in [" + number(r.lo) + ", " + number(r.hi) + "]";
}

/// "an integer in [1, 1000]", "one of cg, gmres, ...": what the option takes, for messages.
std::string expected(const Rule& r) {
  switch (r.kind) {
    case Kind::boolean: return "no value or a boolean (true, false, yes, no, on, off, 1, 0)";
    case Kind::viewer: return "no value (it prints to standard output), or :stdout";
    case Kind::integer: return "an integer" + range_text(r);
    case Kind::real: return "a finite number" + range_text(r);
    case Kind::reals: return "finite numbers" + range_text(r) + " separated by commas";
    case Kind::integers: return "integers" + range_text(r) + " separated by commas";
    case Kind::choice: {
      std::string text = "one of";
      for (std::size_t i = 0; i < r.choices.size(); ++i) text += (i ? ", " : " ") + std::string(r.choices[i]);
      return text;
    }
  }
  return "";
}

bool value_fits(const Rule& r, const std::optional<std::string>& value) {
  const auto in_range = [&](std::string_view s) {
    const std::optional<double> x = to_number(s, integral(r));
    return x && *x >= r.lo && *x <= r.hi;
  };
  switch (r.kind) {
    case Kind::boolean: {
      if (!value) return true;
      const std::string v = lower(*value);
      for (const char* b : {"true", "false", "yes", "no", "on", "off", "1", "0"})
        if (v == b) return true;
      return false;
    }
    case Kind::viewer: return !value || *value == ":stdout" || *value == "ascii:stdout";
    case Kind::integer:
    case Kind::real: return value && in_range(*value);
    case Kind::reals:
    case Kind::integers: {
      if (!value) return false;
      const auto parts = split_commas(*value);
      return std::all_of(parts.begin(), parts.end(), in_range);
    }
    case Kind::choice: {
      if (!value) return false;
      const std::string v = lower(*value);
      return std::any_of(r.choices.begin(), r.choices.end(), [&](std::string_view c) { return lower(c) == v; });
    }
  }
  return false;
}

/// A word for a message: control characters and overlong words shown shortened.
std::string shown(const std::string& word) {
  std::string out;
  for (char c : word.substr(0, 60)) out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return word.size() > 60 ? out + "..." : out;
}

[[noreturn]] void refuse_name(const std::string& name) {
  std::vector<std::string> candidates;
  for (const Rule& r : rules()) candidates.push_back(std::string("-").append(r.name));
  // No suggestion for a long word: it is no near miss, and the distances would cost time.
  const std::string near = name.size() <= 64 ? nearest_word(lower(name), candidates) : std::string();
  throw InputError(shown(name) +
                   " is not an option a config may set: a config sets solver-tuning options only (Krylov "
                   "method, preconditioner, tolerances, GAMG, hypre and MUMPS parameters, monitors to standard "
                   "output; the list is in docs/parallel.md); options that write or read files, views to files, "
                   "logging, debuggers and signal handling belong on the command line or in PETSC_OPTIONS" +
                   (near.empty() ? std::string() : " (did you mean " + near + "?)"));
}

}  // namespace

std::vector<PetscOption> parse_config_petsc_options(const std::string& text) {
  std::vector<PetscOption> options;
  std::vector<Rule> option_rules;
  std::set<std::string> seen;
  const auto finish = [&] {  // the value check of the last option, once its value is known
    if (options.empty()) return;
    const PetscOption& o = options.back();
    const Rule& r = option_rules.back();
    if (value_fits(r, o.value)) return;
    if (!o.value) throw InputError(shown(o.name) + " needs a value: " + expected(r));
    if (r.kind == Kind::viewer)
      throw InputError(shown(o.name) + " prints to standard output only: give it no value ('" + shown(*o.value) +
                       "' would be a file or viewer target; those belong on the command line)");
    throw InputError(shown(o.name) + " takes " + expected(r) + ", not '" + shown(*o.value) + "'");
  };
  bool value_allowed = false;  // the word after a name may be its value
  for (std::size_t pos = 0; pos < text.size();) {
    while (pos < text.size() && is_space(text[pos])) ++pos;
    if (pos == text.size()) break;
    std::size_t end = pos;
    while (end < text.size() && !is_space(text[end])) ++end;
    const std::string word = text.substr(pos, end - pos);
    pos = end;
    if (!is_name(word)) {
      // PETSc would silently take "ksp_monitor" as a value or ignore it.
      if (!value_allowed)
        throw InputError("'" + shown(word) +
                         "' is not a PETSc option name (options are written -name [value], e.g. \"-ksp_monitor\")");
      options.back().value = word;
      value_allowed = false;
      continue;
    }
    finish();
    const std::string key = lower(word.substr(1));
    if (!std::all_of(key.begin(), key.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }))
      refuse_name(word);
    const std::optional<Rule> rule = find_rule(key);
    if (!rule) refuse_name(word);
    // PETSc keeps the last of two values; the config's options yield to earlier ones (the command
    // line): a repeated option would be ambiguous.
    if (!seen.insert(key).second) throw InputError(shown(word) + " is given twice");
    options.push_back({word, std::nullopt});
    option_rules.push_back(*rule);
    value_allowed = true;
  }
  finish();
  return options;
}

std::vector<std::string> config_petsc_option_names() {
  std::vector<std::string> names;
  for (const Rule& r : rules()) names.push_back(std::string("-").append(r.name));
  names.push_back("-mat_mumps_icntl_N");
  names.push_back("-mat_mumps_cntl_N");
  return names;
}

std::vector<std::string> config_petsc_option_prefixes() { return {kPrefixes.begin(), kPrefixes.end()}; }

}  // namespace iga
