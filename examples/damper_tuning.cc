// Example: the optimisation library (ridefit::optimisation, NLopt) on a damper-tuning study.
//
// Loads a tuning study (model, design variables with bounds, load cases, objective, limits),
// lets NLopt search for the damping that minimises the ISO 2631-1 comfort objective while the
// limits on tyre load and travel hold, and prints the optimum, re-evaluated at verification
// accuracy, with each limit's margin. Seed 001's linear half car is evaluated exactly in the
// frequency domain, so the whole search takes a fraction of a second.
//
//   damper_tuning STUDY.yaml
//   e.g. damper_tuning datasets/studies/seed001_damper_tuning_linear.yaml
//
// `ridefit optimise STUDY.yaml` does the same and adds what the study asks for on top (the cost
// of ignoring friction, the trade-off curve), a journal to resume from and the result files.
// Exit code 1 when no design holds every limit, or the optimum is not finite or outside a
// broad physical range (the example runs as a test), 2 for bad arguments.
#include <fmt/core.h>

#include <cmath>
#include <exception>
#include <string>

#include "ridefit/optimisation/nlopt_tuner.h"
#include "ridefit/optimisation/tuning_problem.h"
#include "ridefit/optimisation/tuning_study.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    fmt::print(stderr, "usage: {} STUDY.yaml\n", argv[0]);
    return 2;
  }
  namespace opt = ridefit::optimisation;
  try {
    // The study file is checked as a whole (keys, bounds, roads, metric names) here; paths in it
    // are relative to the study file.
    const opt::TuningStudy study = opt::load_tuning_study(argv[1]);
    // The problem generates each load case's road once and caches evaluations (no journal).
    opt::TuningProblem problem(study);
    const opt::OptimisationRun run =
        opt::optimise(problem, opt::FrictionVariant::kStudy, problem.study_limits(),
                      opt::study_start(study), [](const std::string& line) {
                        fmt::print(stderr, "  {}\n", line);  // one line per evaluation
                      });

    fmt::print("{}: {}, NLopt {}, {} evaluations\n", study.study_file.string(),
               opt::to_string(study.optimiser.algorithm), run.nlopt_result, run.evaluations);
    bool ok = run.feasible;
    if (!ok) fmt::print(stderr, "FAILED: no design within the bounds holds every limit\n");
    for (std::size_t v = 0; v < study.design.size(); ++v) {
      const opt::DesignVariable& d = study.design[v];
      fmt::print("  {:<28} {:>10.5g}   (bounds {:g} … {:g})\n", d.name, run.best.x[v], d.lower,
                 d.upper);
      if (!(std::isfinite(run.best.x[v]) && run.best.x[v] >= d.lower && run.best.x[v] <= d.upper)) {
        fmt::print(stderr, "FAILED: {} = {} outside its bounds\n", d.name, run.best.x[v]);
        ok = false;
      }
    }
    const double objective = run.verified.objective;
    fmt::print("  objective {} ({}): {:.5g}\n", study.objective.metric,
               opt::to_string(study.objective.aggregate), objective);
    for (const opt::ConstraintMargin& m : run.margins) {
      fmt::print("  {:<46} value {:>9.5g}, margin {:+.2f} % {}\n", m.description, m.value,
                 100.0 * m.relative_margin, m.holds ? "holds" : "VIOLATED");
    }
    // Wk-weighted accelerations of a car's occupant on a road: a few hundredths to a few m/s^2.
    if (!(std::isfinite(objective) && objective > 0.01 && objective < 5.0)) {
      fmt::print(stderr, "FAILED: objective {} outside (0.01, 5)\n", objective);
      ok = false;
    }
    return ok ? 0 : 1;
  } catch (const std::exception& e) {  // InputError (bad study), RunError (evaluation failed)
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
}
