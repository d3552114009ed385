#include "ridefit/fitting/hysteresis_fit.h"

#include <ceres/ceres.h>
#include <fmt/core.h>
#include <fmt/format.h>

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <system_error>
#include <thread>
#include <type_traits>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/fit_adequacy.h"
#include "ridefit/fitting/hysteresis_prediction.h"
#include "ridefit/fitting/integration_resolution.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/signal/correlation_time.h"

namespace ridefit::fitting {
namespace {

inline double value_of(double x) { return x; }
template <int N>
double value_of(const ceres::Jet<double, N>& x) {
  return x.a;
}

// One free value (a parameter block of size 1): which parameter, and which record it belongs
// to (-1: shared by all).
struct Block {
  std::size_t parameter = 0;
  int record = -1;
};

// Why the start cannot be evaluated, in the integrator's own words and naming the record (the
// residual blocks only say that they failed).
std::string start_failure(const std::vector<HysteresisRecord>& records,
                          const model::StrutTestParameters<double>& start,
                          const simulate::StrutTestSolverOptions& solver) {
  for (std::size_t r = 0; r < records.size(); ++r) {
    const auto& record = records[r];
    try {
      simulate::strut_test_steps(record.time_s, record.displacement_m, start, solver,
                                 record.command, record.velocity_m_per_s);
    } catch (const RunError& e) {
      return fmt::format(
          "fit: the strut model cannot be run at the start values on record {} ({}): {}; check "
          "the model file's values and the record's time column",
          r + 1, record.source.empty() ? "no name" : record.source, e.what());
    }
  }
  return "fit: the strut model gives no finite force at the start values; check the model "
         "file's values";
}

// The steps of a record's last run in doubles and the values it ran at. Ceres evaluates the
// residuals at a trial point and, when it accepts the point, the Jacobian there: the replay in
// Jets then follows these steps instead of running the record once more to record them. One per
// residual block: Ceres never evaluates a block on two threads at once.
struct KeptSteps {
  std::vector<double> values;
  simulate::EsdirkStepHistory steps;
  bool valid = false;
};

// The force residuals of one record, as a function of the blocks it uses.
struct RecordResidual {
  const HysteresisRecord* record = nullptr;
  model::StrutTestParameters<double> base;
  std::vector<std::size_t> fields;  // the parameter of each of this record's blocks
  std::vector<double> units;        // block value × unit = the parameter
  simulate::StrutTestSolverOptions solver;
  double weight = 1.0;  // the record's residuals are scaled by this (RecordWeighting)
  // Keep each run's steps for a Jacobian at the same point (null: run afresh every time): the
  // Jacobian is then the exact tangent of the run whose residuals Ceres accepted.
  std::shared_ptr<KeptSteps> kept;

  template <typename T>
  std::vector<double> values_of_blocks(T const* const* blocks) const {
    std::vector<double> v(fields.size());
    for (std::size_t b = 0; b < fields.size(); ++b) v[b] = value_of(blocks[b][0]);
    return v;
  }
  // The solver's options for a run in doubles at these values: it records its steps.
  simulate::StrutTestSolverOptions recording_options(const std::vector<double>& values) const {
    simulate::StrutTestSolverOptions options = solver;
    if (kept == nullptr || solver.frozen_steps != nullptr) return options;
    kept->valid = false;
    kept->values = values;
    options.record_steps = &kept->steps;
    return options;
  }
  // ... and for a replay in Jets: on the kept steps when they were recorded at these values.
  simulate::StrutTestSolverOptions replay_options(const std::vector<double>& values) const {
    simulate::StrutTestSolverOptions options = solver;
    if (kept != nullptr && solver.frozen_steps == nullptr && kept->valid &&
        kept->values == values) {
      options.frozen_steps = &kept->steps;
    }
    return options;
  }

  template <typename T>
  bool operator()(T const* const* blocks, T* residuals) const {
    model::StrutTestParameters<T> p;
    model::StrutTestParameters<double> v = base;
    for (std::size_t i = 0; i < kStrutParameters.size(); ++i) {
      strut_parameter(p, i) = T(strut_parameter(v, i));
    }
    for (std::size_t b = 0; b < fields.size(); ++b) {
      strut_parameter(p, fields[b]) = blocks[b][0] * T(units[b]);
      strut_parameter(v, fields[b]) = value_of(blocks[b][0]) * units[b];
    }
    const std::vector<double> at = values_of_blocks(blocks);
    const simulate::StrutTestSolverOptions options =
        std::is_same_v<T, double> ? recording_options(at) : replay_options(at);
    auto force = simulate::strut_test_force<T>(record->time_s, record->displacement_m, p, v,
                                               options, record->command, record->velocity_m_per_s);
    if constexpr (std::is_same_v<T, double>) {
      if (options.record_steps != nullptr) kept->valid = force.has_value();
    }
    if (!force) return false;
    for (std::size_t k = 0; k < force->size(); ++k) {
      residuals[k] = ((*force)[k] - T(record->force_N[k])) * weight;
    }
    return true;
  }
};

// A record with many free values (an MR record's command law, lag, knee, free play and mass: 9-12)
// in two halves of Jet lanes on two threads over one recorded run (the trial point's kept steps,
// or a run made here to record them), each half replaying it (esdirk_tangents.h) with Jets as
// wide as its share, concurrently: a record fitted alone (the NEES random test) otherwise ran its
// replay on one core. The derivatives are the same as one pass's, lane by lane
// (JacobianPasses.SplitJacobianIsTheOnePassJacobian).
class SplitLaneRecordCost final : public ceres::CostFunction {
 public:
  static constexpr int kLanes = 6;  // per half: 7-12 free values

  SplitLaneRecordCost(RecordResidual* functor, int blocks, int residuals) : functor_(functor) {
    for (int i = 0; i < blocks; ++i) mutable_parameter_block_sizes()->push_back(1);
    set_num_residuals(residuals);
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const RecordResidual& f = *functor_;
    if (jacobians == nullptr) return f(parameters, residuals);
    model::StrutTestParameters<double> v = f.base;
    for (std::size_t b = 0; b < f.fields.size(); ++b) {
      strut_parameter(v, f.fields[b]) = parameters[b][0] * f.units[b];
    }
    const HysteresisRecord& record = *f.record;
    simulate::StrutTestSolverOptions solver = f.replay_options(f.values_of_blocks(parameters));
    simulate::EsdirkStepHistory history;
    if (solver.frozen_steps == nullptr) {
      try {
        history = simulate::strut_test_steps(record.time_s, record.displacement_m, v, solver,
                                             record.command, record.velocity_m_per_s);
      } catch (const RunError&) {
        return false;
      }
      solver.frozen_steps = &history;
    }
    const std::size_t n = f.fields.size();
    const std::size_t half = (n + 1) / 2;
    bool ok[2] = {false, false};
    auto replay = [&](int part) {
      const std::size_t first = part == 0 ? 0 : half, last = part == 0 ? half : n;
      ok[part] = replay_lanes(v, solver, first, last, parameters, part == 0 ? residuals : nullptr,
                              jacobians);
    };
    std::thread other;
    try {
      other = std::thread([&] { replay(1); });
    } catch (const std::system_error&) {  // no thread to be had: both halves here
      replay(1);
    }
    replay(0);
    if (other.joinable()) other.join();
    return ok[0] && ok[1];
  }

 private:
  using Lanes = ceres::Jet<double, kLanes>;

  // The residuals (when `residuals` is not null) and the Jacobian columns of free values
  // [first, last), seeded on lanes 0…last−first. Never throws (it runs on a thread of its own).
  bool replay_lanes(const model::StrutTestParameters<double>& v,
                    const simulate::StrutTestSolverOptions& solver, std::size_t first,
                    std::size_t last, double const* const* parameters, double* residuals,
                    double** jacobians) const {
    const RecordResidual& f = *functor_;
    const HysteresisRecord& record = *f.record;
    try {
      model::StrutTestParameters<Lanes> p;
      for (std::size_t i = 0; i < kStrutParameters.size(); ++i) {
        strut_parameter(p, i) = Lanes(strut_parameter(v, i));
      }
      for (std::size_t b = first; b < last; ++b) {
        strut_parameter(p, f.fields[b]) =
            Lanes(parameters[b][0] * f.units[b], static_cast<int>(b - first));
      }
      const auto force =
          simulate::strut_test_force<Lanes>(record.time_s, record.displacement_m, p, v, solver,
                                            record.command, record.velocity_m_per_s);
      if (!force) return false;
      for (std::size_t k = 0; k < force->size(); ++k) {
        const Lanes& r = (*force)[k];
        if (residuals != nullptr) residuals[k] = (r.a - record.force_N[k]) * f.weight;
        for (std::size_t b = first; b < last; ++b) {
          if (jacobians[b] != nullptr) {
            jacobians[b][k] = r.v[static_cast<Eigen::Index>(b - first)] * f.units[b] * f.weight;
          }
        }
      }
      return true;
    } catch (const std::exception&) {
      return false;
    }
  }

  std::unique_ptr<RecordResidual> functor_;
};

// Jets as wide as the record's free values: Ceres evaluates a DynamicAutoDiffCostFunction in
// passes of `Stride` derivatives, so a stride equal to the count takes one pass with no unused
// lanes (8 lanes for 3 parameters cost half as much again).
template <int Stride>
ceres::CostFunction* make_cost(RecordResidual* functor, int blocks, int residuals) {
  auto* cost = new ceres::DynamicAutoDiffCostFunction<RecordResidual, Stride>(functor);
  for (int i = 0; i < blocks; ++i) cost->AddParameterBlock(1);
  cost->SetNumResiduals(residuals);
  return cost;
}

ceres::CostFunction* make_cost(RecordResidual* functor, int blocks, int residuals,
                               JacobianPasses passes = JacobianPasses::kSplitAcrossTwoCores) {
  if (passes == JacobianPasses::kSplitAcrossTwoCores && blocks > SplitLaneRecordCost::kLanes &&
      blocks <= 2 * SplitLaneRecordCost::kLanes) {
    return new SplitLaneRecordCost(functor, blocks, residuals);
  }
  switch (blocks) {
    case 1:
      return make_cost<1>(functor, blocks, residuals);
    case 2:
      return make_cost<2>(functor, blocks, residuals);
    case 3:
      return make_cost<3>(functor, blocks, residuals);
    case 4:
      return make_cost<4>(functor, blocks, residuals);
    case 5:
      return make_cost<5>(functor, blocks, residuals);
    case 6:
      return make_cost<6>(functor, blocks, residuals);
    // 9-12 free values (an MR record's command law, lag, knee and free play): in passes of 8
    // they took two passes, 16 lanes for 9 or 10 values.
    case 9:
    case 10:
      return make_cost<10>(functor, blocks, residuals);
    case 11:
    case 12:
      return make_cost<12>(functor, blocks, residuals);
    default:
      return make_cost<8>(functor, blocks, residuals);
  }
}

std::string describe(const Block& block, const std::vector<HysteresisRecord>& records) {
  const std::string name(kStrutParameters[block.parameter].name());
  return block.record < 0
             ? name
             : name + " (" + records[static_cast<std::size_t>(block.record)].source + ")";
}

// NRMSE over all records, parameters on their bounds, and the verdict (fit_adequacy.h).
void assess_adequacy(const std::vector<HysteresisRecord>& records,
                     const std::array<std::pair<double, double>, kStrutParameters.size()>& bounds,
                     const std::vector<Block>& blocks, double max_nrmse_percent,
                     HysteresisFitResult& result) {
  double residual = 0.0, spread = 0.0;
  for (std::size_t r = 0; r < records.size(); ++r) {
    const auto& measured = records[r].force_N;
    const auto& fitted = result.fitted_force_N[r];
    result.record_nrmse_percent.push_back(nrmse_percent(measured, fitted));
    if (fitted.size() != measured.size()) continue;
    double mean = 0.0;
    for (double f : measured) mean += f / static_cast<double>(measured.size());
    for (std::size_t k = 0; k < measured.size(); ++k) {
      residual += (fitted[k] - measured[k]) * (fitted[k] - measured[k]);
      spread += (measured[k] - mean) * (measured[k] - mean);
    }
  }
  std::vector<std::string> on_bounds;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const auto [lo, hi] = bounds[blocks[b].parameter];
    const std::string text =
        on_bound(describe(blocks[b], records), result.parameters[b].value, lo, hi);
    if (!text.empty()) on_bounds.push_back(text);
  }
  const FitAdequacy a = judge_fit(spread > 0.0 ? 100.0 * std::sqrt(residual / spread) : 0.0,
                                  on_bounds, result.unidentifiable, max_nrmse_percent, "force");
  result.nrmse_percent = a.nrmse_percent;
  result.on_bounds = a.on_bounds;
  result.explains_data = a.explains_data;
  result.adequacy_note = a.note;
}

// The fit's uncertainty at its end: standard errors and correlations from ceres::Covariance
// scaled by s² = 2·cost/(m − n) and by the residuals' correlation time, and the parameters the data
// leave undetermined (into `result`). Returns the physical covariance of the blocks, none when it
// is not computable.
std::optional<Eigen::MatrixXd> assess_uncertainty(
    ceres::Problem& problem, double final_cost, const std::string& solver_message,
    const std::vector<Block>& blocks, std::vector<double>& values, const std::vector<double>& units,
    const std::array<std::pair<double, double>, kStrutParameters.size()>& bounds,
    const std::vector<HysteresisRecord>& records, std::size_t samples,
    HysteresisFitResult& result) {
  const std::size_t n = blocks.size();
  // Identifiability: the Jacobian with each column scaled by its parameter's size.
  ceres::CRSMatrix crs;
  double cost = 0.0;
  std::vector<double> residuals;
  if (!problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, &residuals, nullptr, &crs) ||
      crs.num_rows == 0 || crs.num_cols == 0) {
    throw RunError(fmt::format(
        "fit: the strut model cannot be solved with its derivatives at the fit's end ({}); try "
        "other start values",
        solver_message));
  }
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (int row = 0; row < crs.num_rows; ++row) {
    for (int k = crs.rows[static_cast<std::size_t>(row)];
         k < crs.rows[static_cast<std::size_t>(row) + 1]; ++k) {
      jacobian(row, crs.cols[static_cast<std::size_t>(k)]) =
          crs.values[static_cast<std::size_t>(k)];
    }
  }
  // (its columns are already per unit of each parameter's start size)
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian, Eigen::ComputeThinV);
  const auto& sigma = svd.singularValues();

  std::set<std::size_t> weak;
  for (Eigen::Index i = 0; i < sigma.size(); ++i) {
    if (sigma(i) < 1e-6 * sigma(0)) {
      for (Eigen::Index j = 0; j < svd.matrixV().rows(); ++j) {
        if (std::abs(svd.matrixV()(j, i)) > 0.3) weak.insert(static_cast<std::size_t>(j));
      }
    }
  }
  // Standard errors and correlation from ceres::Covariance, scaled by s².
  const double dof = static_cast<double>(samples) - static_cast<double>(n);
  const double s2 = dof > 0.0 ? 2.0 * final_cost / dof : 0.0;
  ceres::Covariance::Options covariance_options;
  covariance_options.algorithm_type = ceres::DENSE_SVD;
  covariance_options.num_threads = 2;
  ceres::Covariance covariance(covariance_options);
  std::vector<std::pair<const double*, const double*>> pairs;
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a; b < n; ++b) pairs.emplace_back(&values[a], &values[b]);
  }
  Eigen::MatrixXd cov =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  const bool have_covariance = weak.empty() && dof > 0.0 && covariance.Compute(pairs, &problem);
  // (a Jacobian with a near-null direction has no finite covariance: those parameters are
  // reported as undetermined below instead)
  if (have_covariance) {
    for (std::size_t a = 0; a < n; ++a) {
      for (std::size_t b = a; b < n; ++b) {
        double c = 0.0;
        covariance.GetCovarianceBlock(&values[a], &values[b], &c);
        const double physical = s2 * c * units[a] * units[b];
        cov(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = physical;
        cov(static_cast<Eigen::Index>(b), static_cast<Eigen::Index>(a)) = physical;
      }
    }
    result.correlation = cov;
    for (Eigen::Index a = 0; a < cov.rows(); ++a) {
      for (Eigen::Index b = 0; b < cov.cols(); ++b) {
        result.correlation(a, b) = cov(a, b) / std::sqrt(cov(a, a) * cov(b, b));
      }
    }
  }
  // A parameter the data leave undetermined: in a near-null direction of the Jacobian, with a
  // standard error above half its size, or correlated beyond 0.995 with another (the data then
  // fix only a combination of the two, e.g. damping and friction on a quasi-static triangle).
  std::vector<std::string> pairs_note;
  if (!have_covariance && weak.empty() && n > 0) {
    // Ceres found the covariance rank-deficient: the smallest singular direction names the
    // parameters the data do not fix.
    const Eigen::Index last = sigma.size() - 1;
    for (Eigen::Index j = 0; j < svd.matrixV().rows(); ++j) {
      if (std::abs(svd.matrixV()(j, last)) > 0.3) weak.insert(static_cast<std::size_t>(j));
    }
  }
  if (have_covariance) {
    for (std::size_t b = 0; b < n; ++b) {
      const auto [lo, hi] = bounds[blocks[b].parameter];
      const double size = std::max(std::abs(values[b] * units[b]), 1e-3 * (hi - lo));
      const auto i = static_cast<Eigen::Index>(b);
      if (std::sqrt(cov(i, i)) > 0.5 * size) weak.insert(b);
      for (std::size_t c = b + 1; c < n; ++c) {
        const auto j = static_cast<Eigen::Index>(c);
        // |ρ| > 0.995: each variance is inflated more than 100-fold by the other (1/(1 − ρ²)).
        if (std::abs(result.correlation(i, j)) > 0.995) {
          weak.insert(b);
          weak.insert(c);
          pairs_note.push_back(fmt::format("{} and {} (correlation {:.3f})",
                                           describe(blocks[b], records),
                                           describe(blocks[c], records), result.correlation(i, j)));
        }
      }
    }
  }
  for (std::size_t b : weak) result.unidentifiable.push_back(describe(blocks[b], records));
  if (!weak.empty()) {
    std::string list;
    for (const auto& name : result.unidentifiable) list += (list.empty() ? "" : ", ") + name;
    result.identifiability_note = fmt::format(
        "the data cannot determine {}{}{} (condition number of the scaled Jacobian {:.2g}): fix "
        "{} or add a test that excites {}",
        list, pairs_note.empty() ? "" : "; they cannot separate ",
        [&] {
          std::string text;
          for (const auto& p : pairs_note) text += (text.empty() ? "" : ", ") + p;
          return text;
        }(),
        sigma(0) / std::max(sigma(sigma.size() - 1), 1e-300),
        weak.size() > 1 ? "some of them" : "it", weak.size() > 1 ? "them" : "it");
  }
  if (!have_covariance) return std::nullopt;
  // s²·(JᵀJ)⁻¹ holds for independent residuals. A force residual is correlated over many samples
  // (the misfit of a loop, a sampled record's smoothness): with τ samples per independent value
  // the variance of the estimates is about τ times larger, so the errors are widened by √τ (the
  // identifiability above judges the Jacobian, with independent residuals).
  std::vector<std::size_t> lengths;  // the residual blocks, one per record in order
  for (const auto& record : records) lengths.push_back(record.force_N.size());
  result.residual_correlation_samples = signal::pooled_correlation_time_samples(residuals, lengths);
  return cov * result.residual_correlation_samples;
}

}  // namespace

ceres::CostFunction* make_hysteresis_cost(const HysteresisRecord& record,
                                          const model::StrutTestParameters<double>& base,
                                          const std::vector<std::string>& free,
                                          const simulate::StrutTestSolverOptions& solver,
                                          const HysteresisCostOptions& cost) {
  auto* functor = new RecordResidual{&record, base, {}, {}, solver, 1.0, nullptr};
  if (cost.keep_steps) functor->kept = std::make_shared<KeptSteps>();
  for (const auto& name : free) {
    functor->fields.push_back(strut_parameter_index(name));
    functor->units.push_back(1.0);
  }
  return make_cost(functor, static_cast<int>(free.size()), static_cast<int>(record.force_N.size()),
                   cost.passes);
}

// Each record's weight under `weighting`: 1, or the records' RMS spread over its own spread.
std::vector<double> record_weights(const std::vector<HysteresisRecord>& records,
                                   RecordWeighting weighting) {
  std::vector<double> weights(records.size(), 1.0);
  if (weighting == RecordWeighting::kNewtons) return weights;
  std::vector<double> spread(records.size(), 0.0);
  double mean_square = 0.0;
  for (std::size_t r = 0; r < records.size(); ++r) {
    const auto& f = records[r].force_N;
    if (f.empty()) continue;
    double mean = 0.0;
    for (double v : f) mean += v / static_cast<double>(f.size());
    double square = 0.0;
    for (double v : f) square += (v - mean) * (v - mean) / static_cast<double>(f.size());
    spread[r] = std::sqrt(square);
    mean_square += square / static_cast<double>(records.size());
  }
  for (std::size_t r = 0; r < records.size(); ++r) {
    if (spread[r] > 0.0) weights[r] = std::sqrt(mean_square) / spread[r];
  }
  return weights;
}

double largest_force_N(const std::vector<HysteresisRecord>& records) {
  double largest = 0.0;
  for (const auto& r : records) {
    for (double f : r.force_N) largest = std::max(largest, std::abs(f));
  }
  return largest;
}

HysteresisFitResult fit_hysteresis(const std::vector<HysteresisRecord>& records,
                                   const model::StrutTestParameters<double>& start,
                                   const HysteresisFitOptions& given_options) {
  if (records.empty()) throw InputError("fit: no data file given");
  given_options.validate();
  HysteresisFitOptions options = given_options;
  if (options.force_scale_N == 0.0) options.force_scale_N = largest_force_N(records);
  const bool any_command = std::any_of(
      records.begin(), records.end(), [](const HysteresisRecord& r) { return !r.command.empty(); });
  for (const auto& name : options.free) {
    namespace rows = model::quarter_car_rows;
    if (!any_command &&
        (name == rows::damping_per_command_Ns_per_m.key ||
         name == rows::coulomb_force_per_command_N.key || name == rows::command_lag_s.key)) {
      throw InputError(fmt::format(
          "free parameter {}: no record has a command column (current[A] or voltage[V]); a "
          "controlled damper's law needs the command the damper was given",
          name));
    }
  }
  std::set<std::size_t> free, per_file;
  for (const auto& name : options.free) free.insert(strut_parameter_index(name));
  for (const auto& name : options.per_file) per_file.insert(strut_parameter_index(name));
  const auto bounds = options.resolved_bounds();
  model::StrutTestParameters<double> base = start;
  for (std::size_t index : free) {
    const double v = strut_parameter(base, index);
    if (!(v >= bounds[index].first && v <= bounds[index].second)) {
      throw InputError(fmt::format(
          "the start value of {} is {}, outside its bounds [{}, {}]; set it in the model file or "
          "widen the bounds",
          kStrutParameters[index].name(), v, bounds[index].first, bounds[index].second));
    }
  }

  // Blocks: shared parameters first, then each file's own.
  std::vector<Block> blocks;
  // In the order the caller named them: shared ones, then each file's own.
  std::vector<std::size_t> order;
  for (const auto& name : options.free) order.push_back(strut_parameter_index(name));
  for (std::size_t index : order) {
    if (!per_file.count(index)) blocks.push_back({index, -1});
  }
  for (std::size_t r = 0; r < records.size(); ++r) {
    for (std::size_t index : order) {
      if (per_file.count(index)) blocks.push_back({index, static_cast<int>(r)});
    }
  }
  // The solver works on each parameter in units of its start size (σ0 ~ 1e6 N/m and d ~ 1
  // side by side would leave Levenberg-Marquardt and the covariance badly scaled).
  std::vector<double> values(blocks.size()), units(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const auto [lo, hi] = bounds[blocks[b].parameter];
    const double start_value = strut_parameter(base, blocks[b].parameter);
    units[b] = std::max(std::abs(start_value), 1e-3 * (hi - lo));
    values[b] = start_value / units[b];
  }

  // Every record's residual block, integrated at `solver`'s settings.
  const std::vector<double> weights = record_weights(records, options.record_weighting);
  auto add_records = [&](ceres::Problem& problem, const simulate::StrutTestSolverOptions& solver,
                         bool keep_steps) {
    for (std::size_t r = 0; r < records.size(); ++r) {
      auto* functor = new RecordResidual{&records[r], base, {}, {}, solver, weights[r], nullptr};
      if (keep_steps) functor->kept = std::make_shared<KeptSteps>();
      std::vector<double*> used;
      for (std::size_t b = 0; b < blocks.size(); ++b) {
        if (blocks[b].record < 0 || blocks[b].record == static_cast<int>(r)) {
          functor->fields.push_back(blocks[b].parameter);
          functor->units.push_back(units[b]);
          used.push_back(&values[b]);
        }
      }
      ceres::CostFunction* cost = make_cost(functor, static_cast<int>(used.size()),
                                            static_cast<int>(records[r].force_N.size()));
      problem.AddResidualBlock(cost, make_loss_function(options.loss, options.loss_scale_N), used);
    }
  };
  ceres::Problem problem;
  add_records(problem, options.solver, true);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    problem.SetParameterLowerBound(&values[b], 0, bounds[blocks[b].parameter].first / units[b]);
    problem.SetParameterUpperBound(&values[b], 0, bounds[blocks[b].parameter].second / units[b]);
  }

  double initial_cost = 0.0;
  std::vector<double> initial_residuals;
  if (!problem.Evaluate(ceres::Problem::EvaluateOptions(), &initial_cost, &initial_residuals,
                        nullptr, nullptr)) {
    throw RunError(start_failure(records, base, options.solver));
  }

  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = options.max_iterations;
  // With bounds, Ceres' trust region otherwise runs a projected line search on every step whose
  // trial points it evaluates with the Jacobian: a whole tangent replay per candidate
  // (psd_fit_bench went from 3.7 to 2.5 s without it). The step is projected onto the bounds all
  // the same.
  solver.max_num_line_search_step_size_iterations = 0;
  solver.function_tolerance = 1e-12;
  solver.gradient_tolerance = 1e-14;
  solver.parameter_tolerance = 1e-10;
  // What the integration resolves (integration_resolution.h): the residuals at the iterate at
  // the fit's tolerance and at four times it, each from a problem of its own on the same
  // parameter blocks (Ceres forbids evaluating the problem being solved from a callback).
  // Frozen steps are one discrete map: nothing to resolve.
  ceres::Problem at_tolerance, at_coarser;
  simulate::StrutTestSolverOptions coarser = options.solver;
  coarser.relative_tolerance = coarser_tolerance(coarser.relative_tolerance);
  add_records(at_tolerance, options.solver, true);
  add_records(at_coarser, coarser, false);
  // The scatter under the same robust loss as the cost it is compared with, of the raw residuals.
  const std::unique_ptr<ceres::LossFunction> floor_loss(
      make_loss_function(options.loss, options.loss_scale_N));
  auto measure_floor = [&]() -> double {
    if (options.solver.frozen_steps != nullptr) return 0.0;
    std::vector<double> residuals, coarse_residuals;
    ceres::Problem::EvaluateOptions all;
    all.apply_loss_function = false;
    if (!at_tolerance.Evaluate(all, nullptr, &residuals, nullptr, nullptr) ||
        !at_coarser.Evaluate(all, nullptr, &coarse_residuals, nullptr, nullptr)) {
      return 0.0;
    }
    return integration_cost_floor(residuals, coarse_residuals, floor_loss.get());
  };
  // The whole Gauss-Newton step's promise at the iterate, from the exact Jacobian at the fit's
  // tolerance: the gradient condition of the rejected-step stop.
  auto gauss_newton_decrease = [&]() -> double {
    double cost = 0.0;
    std::vector<double> residuals;
    ceres::CRSMatrix jacobian;
    if (!at_tolerance.Evaluate(ceres::Problem::EvaluateOptions(), &cost, &residuals, nullptr,
                               &jacobian)) {
      return std::numeric_limits<double>::infinity();
    }
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(jacobian.num_rows, jacobian.num_cols);
    for (int row = 0; row < jacobian.num_rows; ++row) {
      for (int k = jacobian.rows[row]; k < jacobian.rows[row + 1]; ++k) {
        j(row, jacobian.cols[k]) = jacobian.values[k];
      }
    }
    const Eigen::VectorXd r = Eigen::Map<const Eigen::VectorXd>(
        residuals.data(), static_cast<Eigen::Index>(residuals.size()));
    const Eigen::VectorXd g = j.transpose() * r;
    const Eigen::VectorXd step = j.colPivHouseholderQr().solve(-r);
    const double decrease = -0.5 * g.dot(step);
    return std::isfinite(decrease) ? decrease : std::numeric_limits<double>::infinity();
  };
  StopAtIntegrationResolution stop(measure_floor, initial_residuals.size(), gauss_newton_decrease,
                                   blocks.size());
  solver.update_state_every_iteration = true;
  if (options.stop_at_integration_resolution) solver.callbacks.push_back(&stop);
  solver.logging_type = ceres::SILENT;
  solver.num_threads = 2;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);

  HysteresisFitResult result;
  result.initial_cost = initial_cost;
  result.final_cost = summary.final_cost;
  result.iterations = static_cast<int>(summary.iterations.size()) - 1;
  result.converged = summary.termination_type == ceres::CONVERGENCE || stop.reached();
  result.termination =
      stop.reached() ? integration_resolution_message(stop.floor()) : summary.message;
  std::size_t samples = 0;
  for (const auto& r : records) samples += r.force_N.size();
  result.residual_rms_N = std::sqrt(2.0 * summary.final_cost / static_cast<double>(samples));

  const std::size_t n = blocks.size();
  const std::optional<Eigen::MatrixXd> cov =
      assess_uncertainty(problem, summary.final_cost, summary.message, blocks, values, units,
                         bounds, records, samples, result);
  for (std::size_t b = 0; b < n; ++b) {
    FittedParameter p;
    p.name = std::string(kStrutParameters[blocks[b].parameter].name());
    if (blocks[b].record >= 0) p.file = records[static_cast<std::size_t>(blocks[b].record)].source;
    p.value = values[b] * units[b];
    if (cov) {
      p.standard_error =
          std::sqrt((*cov)(static_cast<Eigen::Index>(b), static_cast<Eigen::Index>(b)));
    }
    result.parameters.push_back(p);
  }
  if (summary.termination_type == ceres::FAILURE && !stop.reached()) {
    // Ceres stops when the derivatives cannot be evaluated at an accepted point: say where, in
    // the parameters' names, since Ceres' own words ("Residual and Jacobian evaluation failed")
    // name nothing a user can change.
    std::vector<std::string> at;
    for (std::size_t b = 0; b < n; ++b) {
      const auto [lo, hi] = bounds[blocks[b].parameter];
      const double v = result.parameters[b].value;
      at.push_back(fmt::format("{} = {:.4g}{}", describe(blocks[b], records), v,
                               v <= lo   ? " (its lower bound)"
                               : v >= hi ? " (its upper bound)"
                                         : ""));
    }
    result.termination = fmt::format(
        "the strut model could not be run with derivatives near {}: the fit went where the model "
        "stops being solvable. Values that run far from their start often stand in for a held "
        "value that is off: check the values the fit holds, or free them",
        fmt::join(at, ", "));
  }
  for (std::size_t r = 0; r < records.size(); ++r) {
    model::StrutTestParameters<double> fitted = base;
    for (std::size_t b = 0; b < n; ++b) {
      if (blocks[b].record < 0 || blocks[b].record == static_cast<int>(r)) {
        strut_parameter(fitted, blocks[b].parameter) = values[b] * units[b];
      }
    }
    result.fitted.push_back(fitted);
    const auto force = run_fitted_strut(records[r], fitted, options.solver);
    result.fitted_force_N.push_back(force ? *force : std::vector<double>());
  }
  if (options.record_weighting == RecordWeighting::kRelative) {  // in newtons, not weighted
    double square = 0.0;
    for (std::size_t r = 0; r < records.size(); ++r) {
      const auto& fitted = result.fitted_force_N[r];
      for (std::size_t k = 0; k < fitted.size(); ++k) {
        square += (fitted[k] - records[r].force_N[k]) * (fitted[k] - records[r].force_N[k]);
      }
    }
    result.residual_rms_N = std::sqrt(square / static_cast<double>(samples));
  }
  assess_adequacy(records, bounds, blocks, options.max_nrmse_percent, result);
  return result;
}

}  // namespace ridefit::fitting
