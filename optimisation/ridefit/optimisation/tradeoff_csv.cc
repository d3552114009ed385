#include "ridefit/optimisation/tradeoff_csv.h"

#include <fmt/core.h>

#include <string>
#include <utility>

#include "ridefit/io/atomic_file.h"
#include "ridefit/study/half_car_sweep.h"

namespace ridefit::optimisation {

void write_tradeoff_csv(const TuningStudy& study, const std::vector<TradeoffPoint>& tradeoff,
                        const std::filesystem::path& path) {
  const std::string metric = study.constraints[study.tradeoff->constraint].metric;
  // Named copies, not structured bindings: Clang 14 cannot capture those in a lambda.
  const std::pair<std::string, std::string> limit = study::split_unit_suffix(metric);
  const std::pair<std::string, std::string> goal = study::split_unit_suffix(study.objective.metric);
  const std::string& name = limit.first;
  const std::string& unit = limit.second;
  const std::string& objective = goal.first;
  const std::string& objective_unit = goal.second;
  io::write_atomically(path, [&](std::ostream& out) {
    out << fmt::format("limit_{}[{}],feasible[1],{}[{}],{}[{}]", name, unit, objective,
                       objective_unit, name, unit);
    for (const auto& v : study.design) {
      const auto [vname, vunit] = study::split_unit_suffix(v.name);
      out << fmt::format(",{}[{}]", vname, vunit);
    }
    out << "\n";
    for (const auto& p : tradeoff) {
      out << fmt::format("{:.10g},{},{:.10g},{:.10g}", p.limit, p.run.feasible ? 1 : 0,
                         p.run.verified.objective, p.achieved);
      for (double x : p.run.best.x) out << fmt::format(",{:.10g}", x);
      out << "\n";
    }
  });
}

}  // namespace ridefit::optimisation
