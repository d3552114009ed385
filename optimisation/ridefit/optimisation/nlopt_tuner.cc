#include "ridefit/optimisation/nlopt_tuner.h"

#include <fmt/core.h>

#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <nlopt.hpp>
#include <random>

#include "ridefit/common/errors.h"

namespace ridefit::optimisation {
namespace {

// Physical value of variable v at unit coordinate u, and back.
double to_physical(const DesignVariable& v, double u) {
  u = std::clamp(u, 0.0, 1.0);
  if (v.log_scale) return v.lower * std::pow(v.upper / v.lower, u);
  return v.lower + u * (v.upper - v.lower);
}

double to_unit(const DesignVariable& v, double x) {
  if (v.log_scale) return std::log(x / v.lower) / std::log(v.upper / v.lower);
  return (x - v.lower) / (v.upper - v.lower);
}

const char* result_name(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS:
      return "success";
    case nlopt::STOPVAL_REACHED:
      return "stopval_reached";
    case nlopt::FTOL_REACHED:
      return "ftol_reached";
    case nlopt::XTOL_REACHED:
      return "xtol_reached";
    case nlopt::MAXEVAL_REACHED:
      return "maxeval_reached";
    case nlopt::MAXTIME_REACHED:
      return "maxtime_reached";
    case nlopt::ROUNDOFF_LIMITED:
      return "roundoff_limited";
    case nlopt::FORCED_STOP:
      return "forced_stop";
    default:
      return "failure";
  }
}

void set_stopping(nlopt::opt& opt, const OptimiserSettings& s) {
  opt.set_xtol_abs(s.x_tolerance);
  opt.set_ftol_rel(s.f_tolerance);
  opt.set_maxeval(s.max_evaluations);
  if (s.max_time_s > 0.0) opt.set_maxtime(s.max_time_s);
}

// The optimiser for the study's algorithm; `constrained` wraps the ones without native
// inequality constraints in AUGLAG.
nlopt::opt make_optimiser(const OptimiserSettings& s, unsigned n, bool constrained) {
  auto local = [&](nlopt::algorithm a) {
    nlopt::opt o(a, n);
    set_stopping(o, s);
    o.set_initial_step(s.initial_step);
    return o;
  };
  auto wrap = [&](const nlopt::opt& inner) {
    if (!constrained) return inner;
    nlopt::opt outer(nlopt::AUGLAG, n);
    set_stopping(outer, s);
    outer.set_local_optimizer(inner);
    return outer;
  };
  switch (s.algorithm) {
    case Algorithm::kCobyla:
      return local(nlopt::LN_COBYLA);
    case Algorithm::kBobyqa:
      return wrap(local(nlopt::LN_BOBYQA));
    case Algorithm::kIsres: {
      nlopt::opt o(nlopt::GN_ISRES, n);
      set_stopping(o, s);
      return o;
    }
    case Algorithm::kDirectL: {
      nlopt::opt o(nlopt::GN_DIRECT_L, n);
      set_stopping(o, s);
      return wrap(o);
    }
    case Algorithm::kMlsl: {
      nlopt::opt o(nlopt::G_MLSL_LDS, n);
      set_stopping(o, s);
      o.set_local_optimizer(local(nlopt::LN_BOBYQA));
      return wrap(o);
    }
  }
  throw std::logic_error("unknown algorithm");
}

// The best point so far: feasible before infeasible, then the lower objective (feasible) or
// violation (infeasible); the first of equals stays.
struct BestPoint {
  bool found = false;
  bool feasible = false;
  double objective = 0.0;
  double violation = std::numeric_limits<double>::infinity();

  // True (and taken) when the point beats the best so far.
  bool offer(bool is_feasible, double point_objective, double point_violation) {
    const bool better = !found || (is_feasible && !feasible) ||
                        (is_feasible == feasible &&
                         (is_feasible ? point_objective < objective : point_violation < violation));
    if (better) *this = {true, is_feasible, point_objective, point_violation};
    return better;
  }
};

struct Search {
  TuningProblem* problem = nullptr;
  FrictionVariant variant = FrictionVariant::kStudy;
  const std::vector<double>* limits = nullptr;
  const ProgressSink* progress = nullptr;
  OptimisationRun* run = nullptr;
  Accuracy accuracy = Accuracy::kSearch;
  int start = 0;
  std::exception_ptr error;
  // The last evaluation: NLopt asks for the objective and then the constraints at one x.
  std::vector<double> last_u;
  Evaluation last;
  BestPoint best;

  const Evaluation& at(unsigned n, const double* u) {
    std::vector<double> unit(u, u + n);
    if (unit == last_u) return last;
    const auto& design = problem->study().design;
    std::vector<double> x(n);
    for (unsigned i = 0; i < n; ++i) x[i] = to_physical(design[i], unit[i]);
    last = problem->evaluate(variant, accuracy, x);
    last_u = unit;
    record(last);
    return last;
  }

  void record(const Evaluation& e) {
    const double violation = problem->max_violation(e, *limits);
    const bool feasible = problem->feasible(e, *limits);
    ++run->evaluations;
    if (!e.reused) ++run->computed;
    run->history.push_back({start, e.objective, violation, e.reused});
    if (best.offer(feasible, e.objective, violation)) run->best = e;
    if (*progress) {
      std::string where;
      for (std::size_t i = 0; i < e.x.size(); ++i) {
        where += fmt::format("{}{}={:.5g}", i ? " " : "", problem->study().design[i].name, e.x[i]);
      }
      (*progress)(fmt::format(
          "eval {} (start {}{}): {} objective {:.6g}, {}", run->evaluations, start + 1,
          e.reused ? ", from journal" : "", where, e.objective,
          feasible ? "limits hold" : fmt::format("limit exceeded by {:.3g} %", 100 * violation)));
    }
  }
};

double objective(unsigned n, const double* u, double* grad, void* data) {
  auto* s = static_cast<Search*>(data);
  if (grad) throw std::logic_error("derivative-free algorithms only");
  try {
    return s->at(n, u).objective;
  } catch (...) {
    s->error = std::current_exception();
    throw nlopt::forced_stop();
  }
}

void constraints(unsigned m, double* result, unsigned n, const double* u, double* grad,
                 void* data) {
  auto* s = static_cast<Search*>(data);
  if (grad) throw std::logic_error("derivative-free algorithms only");
  try {
    const Evaluation& e = s->at(n, u);
    for (unsigned i = 0; i < m; ++i) {
      result[i] = s->problem->normalised_constraint(e, i, *s->limits);
    }
  } catch (...) {
    s->error = std::current_exception();
    throw nlopt::forced_stop();
  }
}

// One NLopt run from unit coordinates `u`; returns NLopt's result as a word.
std::string run_nlopt(Search& search, const OptimiserSettings& settings, std::vector<double> u) {
  const TuningStudy& study = search.problem->study();
  const auto n = static_cast<unsigned>(u.size());
  nlopt::opt opt = make_optimiser(settings, n, !study.constraints.empty());
  opt.set_lower_bounds(std::vector<double>(n, 0.0));
  opt.set_upper_bounds(std::vector<double>(n, 1.0));
  opt.set_min_objective(objective, &search);
  if (!study.constraints.empty()) {
    opt.add_inequality_mconstraint(constraints, &search,
                                   std::vector<double>(study.constraints.size(), 0.0));
  }
  search.last_u.clear();
  nlopt::srand(settings.seed + static_cast<unsigned long>(search.start));
  double value = 0.0;
  try {
    return result_name(opt.optimize(u, value));
  } catch (const nlopt::roundoff_limited&) {
    return "roundoff_limited";
  } catch (const nlopt::forced_stop&) {
    if (search.error) std::rethrow_exception(search.error);
    return "forced_stop";
  } catch (const std::invalid_argument& e) {
    throw std::logic_error(fmt::format("NLopt rejected the problem: {}", e.what()));
  } catch (const std::runtime_error& e) {
    if (search.error) std::rethrow_exception(search.error);
    return fmt::format("failure ({})", e.what());
  }
}

// The constraint limits the search aims at: inside each limit by the constraint tolerance,
// so that the optimum it converges to (from either side) holds the limit itself, not only
// within the tolerance.
std::vector<double> aim_of(const TuningStudy& study, const std::vector<double>& limits) {
  std::vector<double> aim = limits;
  for (std::size_t i = 0; i < aim.size(); ++i) {
    const double inset = study.optimiser.constraint_tolerance * aim[i];
    aim[i] += study.constraints[i].is_upper ? -inset : inset;
  }
  return aim;
}

// Every start in unit coordinates: the given one, then seeded uniform points.
std::vector<std::vector<double>> start_points(const TuningStudy& study,
                                              const std::vector<double>& start) {
  const std::size_t n = study.design.size();
  std::mt19937_64 random(study.optimiser.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::vector<double>> points;
  for (int s = 0; s < study.optimiser.starts; ++s) {
    std::vector<double> u(n);
    for (std::size_t i = 0; i < n; ++i) {
      u[i] = s == 0 ? std::clamp(to_unit(study.design[i], start[i]), 0.0, 1.0) : unit(random);
    }
    points.push_back(std::move(u));
  }
  return points;
}

// One start's search: its evaluations, its best point and NLopt's result.
OptimisationRun search_from(TuningProblem& problem, FrictionVariant variant,
                            const std::vector<double>& aim, std::vector<double> u, int start,
                            const ProgressSink& progress) {
  OptimisationRun run;
  run.variant = variant;
  Search search;
  search.problem = &problem;
  search.variant = variant;
  search.limits = &aim;
  search.progress = &progress;
  search.run = &run;
  search.start = start;
  run.nlopt_result = run_nlopt(search, problem.study().optimiser, std::move(u));
  return run;
}

// The starts' searches as one run: every evaluation in start order, and the best point of all
// (feasible before infeasible, then the lower objective or violation; the earliest of equals).
OptimisationRun combine_starts(const TuningProblem& problem, FrictionVariant variant,
                               const std::vector<double>& limits, const std::vector<double>& aim,
                               const std::vector<OptimisationRun>& starts) {
  OptimisationRun run;
  run.variant = variant;
  run.limits = limits;
  BestPoint best;
  std::size_t best_start = 0;
  for (std::size_t s = 0; s < starts.size(); ++s) {
    const OptimisationRun& r = starts[s];
    run.evaluations += r.evaluations;
    run.computed += r.computed;
    run.history.insert(run.history.end(), r.history.begin(), r.history.end());
    if (r.evaluations == 0) continue;
    if (best.offer(problem.feasible(r.best, aim), r.best.objective,
                   problem.max_violation(r.best, aim))) {
      run.best = r.best;
      best_start = s;
    }
  }
  run.nlopt_result = starts.at(best_start).nlopt_result;
  return run;
}

// The reported optimum, evaluated again at the verification accuracy; where the search's
// optimum sits on a limit that the search accuracy placed slightly differently, polished with
// COBYLA at the verification accuracy, in small steps from where the search ended.
OptimisationRun verify(TuningProblem& problem, OptimisationRun run, const std::vector<double>& aim,
                       const ProgressSink& progress) {
  const TuningStudy& study = problem.study();
  const auto n = static_cast<unsigned>(study.design.size());
  run.verified = problem.evaluate(run.variant, Accuracy::kVerify, run.best.x);
  run.feasible = problem.feasible(run.verified, run.limits);
  const bool best_feasible = problem.feasible(run.best, aim);
  if (!run.feasible && (best_feasible || problem.max_violation(run.best, aim) < 0.01)) {
    OptimiserSettings polish = study.optimiser;
    polish.algorithm = Algorithm::kCobyla;
    polish.initial_step = std::max(10.0 * polish.x_tolerance, 1e-3);
    polish.max_evaluations = 60;
    Search refine;
    refine.problem = &problem;
    refine.variant = run.variant;
    refine.limits = &aim;
    refine.progress = &progress;
    refine.run = &run;
    refine.accuracy = Accuracy::kVerify;
    refine.start = study.optimiser.starts - 1;
    const Evaluation searched = run.best;
    std::vector<double> u(n);
    for (unsigned i = 0; i < n; ++i)
      u[i] = std::clamp(to_unit(study.design[i], searched.x[i]), 0.0, 1.0);
    const std::string result = run_nlopt(refine, polish, u);
    if (refine.best.feasible) {
      run.verified = run.best;  // evaluated at the verification accuracy already
      run.nlopt_result += ", polished: " + result;
    } else {
      run.best = searched;
    }
    run.feasible = problem.feasible(run.verified, run.limits);
  }
  run.margins = problem.margins(run.verified, run.limits);
  return run;
}

}  // namespace

std::vector<double> study_start(const TuningStudy& study) {
  std::vector<double> start;
  for (const auto& v : study.design) start.push_back(v.start);
  return start;
}

std::vector<OptimisationRun> optimise_all(TuningProblem& problem,
                                          const std::vector<OptimisationRequest>& requests,
                                          SearchRunner& runner) {
  const TuningStudy& study = problem.study();
  // Searches on several threads report one line at a time.
  auto lock = std::make_shared<std::mutex>();
  std::vector<ProgressSink> sinks;
  std::vector<std::vector<double>> aims;
  std::vector<SearchTask> searches;
  for (std::size_t r = 0; r < requests.size(); ++r) {
    const ProgressSink& progress = requests[r].progress;
    sinks.push_back(progress ? ProgressSink([lock, progress](const std::string& line) {
      const std::lock_guard<std::mutex> guard(*lock);
      progress(line);
    })
                             : ProgressSink());
    aims.push_back(aim_of(study, requests[r].limits));
    const auto points = start_points(study, requests[r].start);
    for (std::size_t s = 0; s < points.size(); ++s) {
      searches.push_back([&, r, s, u = points[s]](TuningProblem& branch) {
        return search_from(branch, requests[r].variant, aims[r], u, static_cast<int>(s), sinks[r]);
      });
    }
  }
  const std::vector<OptimisationRun> searched = runner.run(problem, searches);
  std::vector<OptimisationRun> combined;
  const auto starts = static_cast<std::size_t>(study.optimiser.starts);
  for (std::size_t r = 0; r < requests.size(); ++r) {
    const std::vector<OptimisationRun> own(
        searched.begin() + static_cast<std::ptrdiff_t>(r * starts),
        searched.begin() + static_cast<std::ptrdiff_t>((r + 1) * starts));
    combined.push_back(
        combine_starts(problem, requests[r].variant, requests[r].limits, aims[r], own));
  }
  std::vector<SearchTask> verifications;
  for (std::size_t r = 0; r < requests.size(); ++r) {
    verifications.push_back([&, r](TuningProblem& branch) {
      OptimisationRun run = verify(branch, combined[r], aims[r], sinks[r]);
      if (requests[r].follow_up) requests[r].follow_up(branch, run);
      return run;
    });
  }
  return runner.run(problem, verifications);
}

OptimisationRun optimise(TuningProblem& problem, FrictionVariant variant,
                         const std::vector<double>& limits, const std::vector<double>& start,
                         const ProgressSink& progress) {
  LocalSearchRunner runner(problem.study().evaluation.threads);
  return optimise_all(problem, {{variant, limits, start, progress, {}}}, runner).front();
}

}  // namespace ridefit::optimisation
