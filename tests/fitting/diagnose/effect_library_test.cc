// The diagnosis' effect library: its ids, each effect's change (start inside its bounds, applies
// once), and the exact Jacobians with each effect's parameters free against central differences:
// the PSD fit's for vehicle effects, the hysteresis fit's for the effects that apply to loops.
#include "ridefit/fitting/diagnose/effect.h"

#include <gtest/gtest.h>

#include <ceres/cost_function.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/fitting/psd_fit.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/simulate/quarter_car_sensitivity.h"
#include "support/hidden_effect_record.h"
#include "support/passat.h"
#include "support/rig_record.h"

namespace ridefit::fitting::diagnose {
namespace {

// A baseline every effect of the vehicle library applies to: slip (no friction), no tyre
// damping, a rigid damper path for top_mount_compliance is tested separately.
DiagnosisModel bare_passat() {
  auto p = testing::passat_corner().parameters;
  p.tyre_damping_Ns_per_m = 0.0;
  p.coulomb_force_N = 0.0;
  return {model::QuarterCar(model::DamperState::kSlip, p)};
}

DiagnosisModel rigid_passat() {
  auto m = bare_passat();
  auto p = m.car.parameters();
  p.top_mount_stiffness_N_per_m = 1e9;
  return {model::QuarterCar(model::DamperState::kSlip, p)};
}

// The Passat strut on the rig: with Dahl friction (for friction_velocity_dependence and
// gas_force), without (damper_friction), or with a rigid top mount (top_mount_compliance).
DiagnosisModel rig_passat(double coulomb_force_N = 60.0, double top_mount_N_per_m = 488000.0) {
  DiagnosisModel m;
  m.kind = DataKind::kStrutLoops;
  m.strut = strut_on_rig(testing::passat_corner().parameters);
  m.strut.coulomb_force_N = coulomb_force_N;
  m.strut.top_mount_stiffness_N_per_m = top_mount_N_per_m;
  m.free = {"damping_Ns_per_m", "force_offset_N"};
  return m;
}

bool loops_only(std::string_view id) {
  return id == "gas_force" || id == "friction_velocity_dependence" || id == "command_dependence" ||
         id == "free_play" || id.starts_with("sensor_");
}

DiagnosisModel baseline_for(std::string_view id) {
  if (loops_only(id)) {
    DiagnosisModel m = rig_passat();
    m.has_command = id == "command_dependence";
    return m;
  }
  return id == "top_mount_compliance" ? rigid_passat() : bare_passat();
}

double value_in(const DiagnosisModel& m, const std::string& name) {
  return m.kind == DataKind::kStrutLoops ? parameter_value(m.strut, name)
                                         : parameter_value(m.car, name);
}

TEST(EffectLibrary, HoldsTheIssuesIdsSortedAndNamesThemWhenOneIsUnknown) {
  std::vector<std::string> ids;
  for (const auto& e : effect_library()) ids.emplace_back(e->id());
  EXPECT_EQ(ids.size(), 15u);
  EXPECT_TRUE(std::is_sorted(ids.begin(), ids.end()));
  for (const char* id :
       {"damper_friction", "top_mount_compliance", "top_mount_amplitude_stiffening", "tyre_damping",
        "damper_asymmetry", "damper_digressive", "bump_stop", "tyre_lift_off",
        "friction_velocity_dependence", "gas_force", "command_dependence", "sensor_gain",
        "sensor_delay", "sensor_band_limit", "free_play"}) {
    EXPECT_EQ(find_effect(id).id(), id);
    EXPECT_GT(find_effect(id).description().size(), 40u) << id;
  }
  try {
    find_effect("tyre_dampin");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tyre_dampin"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("tyre_damping"), std::string::npos);
  }
}

TEST(EffectLibrary, EachEffectStartsInsideItsBoundsAndCannotBeAddedTwice) {
  for (const auto& effect : effect_library()) {
    const DiagnosisModel baseline = baseline_for(effect->id());
    ASSERT_EQ(effect->not_applicable(baseline), "") << effect->id();
    const EffectChange change = effect->change(baseline);
    const DiagnosisModel with = apply(baseline, change);
    for (const auto& p : change.free) {
      const double v = value_in(with, p.name);
      EXPECT_LT(p.lower, p.upper) << effect->id() << " " << p.name;
      EXPECT_GT(v, p.lower) << effect->id() << " " << p.name;
      EXPECT_LT(v, p.upper) << effect->id() << " " << p.name;
    }
    for (const auto& [key, value] : change.set) {
      EXPECT_EQ(value_in(with, key), value) << effect->id() << " " << key;
    }
    EXPECT_NE(effect->not_applicable(with), "") << effect->id() << " applies twice";
  }
  // Not applicable where the physics cannot act, with the reason.
  const DiagnosisModel stuck{
      model::QuarterCar(model::DamperState::kStick, bare_passat().car.parameters())};
  EXPECT_NE(find_effect("damper_friction").not_applicable(stuck).find("stick"), std::string::npos);
  EXPECT_NE(find_effect("top_mount_compliance").not_applicable(bare_passat()), "");
  EXPECT_NE(find_effect("top_mount_amplitude_stiffening").not_applicable(rigid_passat()), "");
  EXPECT_EQ(find_effect("damper_friction").change(bare_passat()).damper_state,
            model::DamperState::kStickSlip);
  // Loops: the vehicle-only effects say why, the loop-only ones skip spectra, friction's
  // velocity dependence needs friction, and a fitted load-cell offset carries the gas preload.
  for (const char* id :
       {"tyre_damping", "tyre_lift_off", "bump_stop", "top_mount_amplitude_stiffening"}) {
    EXPECT_NE(find_effect(id).not_applicable(rig_passat()), "") << id;
  }
  // The rig runs the car's damper path: its valving and knee act on loops too.
  for (const char* id : {"damper_asymmetry", "damper_digressive"}) {
    EXPECT_EQ(find_effect(id).not_applicable(rig_passat()), "") << id;
  }
  EXPECT_NE(find_effect("gas_force").not_applicable(bare_passat()), "");
  EXPECT_NE(find_effect("free_play").not_applicable(bare_passat()), "");
  // A controlled damper's law needs a command column; the sensor delay cannot show in spectra.
  EXPECT_NE(find_effect("command_dependence").not_applicable(rig_passat()).find("command column"),
            std::string::npos);
  EXPECT_NE(find_effect("sensor_delay").not_applicable(bare_passat()).find("auto-spectra"),
            std::string::npos);
  EXPECT_TRUE(find_effect("sensor_gain").measurement_chain());
  // The accelerometers' gain and low-pass apply to spectra as well, once, starting in bounds.
  for (const char* id : {"sensor_gain", "sensor_band_limit"}) {
    ASSERT_EQ(find_effect(id).not_applicable(bare_passat()), "") << id;
    const EffectChange change = find_effect(id).change(bare_passat());
    const DiagnosisModel with = apply(bare_passat(), change);
    for (const auto& p : change.free) {
      EXPECT_GT(value_in(with, p.name), p.lower) << id << " " << p.name;
      EXPECT_LT(value_in(with, p.name), p.upper) << id << " " << p.name;
    }
    EXPECT_NE(find_effect(id).not_applicable(with), "") << id << " applies twice";
  }
  EXPECT_EQ(apply(bare_passat(), find_effect("sensor_band_limit").change(bare_passat()))
                .car.parameters()
                .sensors.acc_sensor_order,
            1);
  EXPECT_FALSE(find_effect("damper_friction").measurement_chain());
  EXPECT_NE(find_effect("friction_velocity_dependence").not_applicable(bare_passat()), "");
  EXPECT_NE(find_effect("friction_velocity_dependence").not_applicable(rig_passat(0.0)), "");
  EXPECT_EQ(find_effect("damper_friction").not_applicable(rig_passat(0.0)), "");
  EXPECT_EQ(find_effect("top_mount_compliance").not_applicable(rig_passat(60.0, 1e9)), "");
  EXPECT_EQ(find_effect("gas_force").change(rig_passat()).free.size(), 1u);
  DiagnosisModel fixed_offset = rig_passat();
  fixed_offset.free = {"damping_Ns_per_m"};
  EXPECT_EQ(find_effect("gas_force").change(fixed_offset).free.size(), 2u);
}

// The cost's exact Jacobian at `x` against central differences (steps of `relative_step` times
// |x|, or 1 at 0): every column moves the residuals (by 1e-3 per relative change at least) and
// agrees within `tolerance` of its largest entry; the residuals with and without the Jacobian
// agree.
void expect_exact_jacobian(const ceres::CostFunction& cost, std::vector<double> x,
                           const std::vector<std::string>& names, double relative_step,
                           double tolerance) {
  const std::size_t n = x.size();
  std::vector<const double*> blocks;
  for (const double& v : x) blocks.push_back(&v);
  const auto rows = static_cast<std::size_t>(cost.num_residuals());
  std::vector<double> residuals(rows), plain(rows);
  std::vector<std::vector<double>> exact(n, std::vector<double>(rows));
  std::vector<double*> jacobians;
  for (auto& j : exact) jacobians.push_back(j.data());
  ASSERT_TRUE(cost.Evaluate(blocks.data(), residuals.data(), jacobians.data()));
  ASSERT_TRUE(cost.Evaluate(blocks.data(), plain.data(), nullptr));
  double d = 0;
  for (std::size_t r = 0; r < rows; ++r) d = std::max(d, std::abs(plain[r] - residuals[r]));
  EXPECT_LT(d, 1e-9) << "the residuals with and without the Jacobian differ";
  for (std::size_t p = 0; p < n; ++p) {
    // Relative to the value itself: a step of 1e-6 m/s on a 0.01 m/s knee (1e-4 of it) put a
    // stage's damper rate on the other side of the knee at one sample of the record, and the
    // difference measured the kink, not the derivative (0.2 % off there).
    const double saved = x[p], step = relative_step * (saved != 0.0 ? std::abs(saved) : 1.0);
    std::vector<double> up(rows), down(rows);
    x[p] = saved + step;
    ASSERT_TRUE(cost.Evaluate(blocks.data(), up.data(), nullptr));
    x[p] = saved - step;
    ASSERT_TRUE(cost.Evaluate(blocks.data(), down.data(), nullptr));
    x[p] = saved;
    double scale = 0.0, worst = 0.0;
    for (std::size_t r = 0; r < rows; ++r) {
      scale = std::max(scale, std::abs(exact[p][r]));
      const double e = std::abs((up[r] - down[r]) / (2.0 * step) - exact[p][r]);
      worst = std::max(worst, e);
    }
    // Per relative change of the parameter (their units differ by orders of magnitude).
    EXPECT_GT(scale * std::max(std::abs(saved), 1.0), 1e-3)
        << names[p] << " does not move the residuals";
    EXPECT_LT(worst, tolerance * scale) << names[p];
  }
}

// A 10 s record on a class C road at 50 km/h: rough enough that the bump stop (20 mm) and the
// damper's knee (0.1 m/s) act, so each parameter moves the spectra.
PsdMeasurement rough_record(const model::QuarterCar& truth) {
  return testing::hidden_effect_record(truth, road::Iso8608Class::kC, 3, 10.0, 500.0, 0.0);
}

class EffectGradient : public ::testing::TestWithParam<std::string> {};

// The Jacobian of the PSD fit with `change` applied to `baseline` and its parameters free.
void expect_exact_psd_jacobian(const DiagnosisModel& baseline, const EffectChange& change) {
  const DiagnosisModel with = apply(baseline, change);
  const PsdMeasurement m = rough_record(with.car);
  PsdFitOptions options;
  for (const auto& p : change.free) {
    options.free.push_back(p.name);
    options.bounds[p.name] = {p.lower, p.upper};
  }
  options.free.push_back("damping_Ns_per_m");
  options.segment_s = 2.0;
  // Off the truth, so residuals are not zero.
  auto at = with.car.parameters();
  model::quarter_car_parameter(at, *model::quarter_car_parameter_index(options.free[0])) *= 1.05;
  const model::QuarterCar car(with.car.damper_state(), at);
  // Central differences of the discrete map the Jacobian belongs to: this run's steps, frozen.
  const auto steps = simulate::quarter_car_steps(
      car, *m.road, m.time_s, {.relative_tolerance = options.relative_tolerance});
  options.frozen_steps = &steps;
  std::unique_ptr<ceres::CostFunction> cost(make_psd_cost(m, car, options));
  const std::vector<double> x(options.free.size(), 1.0);
  expect_exact_jacobian(*cost, x, options.free, 1e-6, 1e-4);
}

TEST_P(EffectGradient, PsdJacobianMatchesCentralDifferences) {
  const Effect& effect = find_effect(GetParam());
  // The measurement chain's effects apply to rig loops and vehicle spectra: here the spectra.
  const bool chain = effect.id().starts_with("sensor_");
  const DiagnosisModel baseline = chain ? bare_passat() : baseline_for(effect.id());
  ASSERT_EQ(effect.not_applicable(baseline), "");
  const EffectChange change = effect.change(baseline);
  expect_exact_psd_jacobian(baseline, change);
  if (!chain) return;
  // And from the chain's other starts (the band limit's second order).
  for (const auto& other_start : change.other_starts) {
    EffectChange other = change;
    for (const auto& [key, value] : other_start) other.set[key] = value;
    expect_exact_psd_jacobian(baseline, other);
  }
}

INSTANTIATE_TEST_SUITE_P(Library, EffectGradient,
                         ::testing::Values("damper_friction", "top_mount_compliance",
                                           "top_mount_amplitude_stiffening", "tyre_damping",
                                           "damper_asymmetry", "damper_digressive", "bump_stop",
                                           "tyre_lift_off", "sensor_gain", "sensor_band_limit"));

class LoopEffectGradient : public ::testing::TestWithParam<std::string> {};

TEST_P(LoopEffectGradient, HysteresisJacobianMatchesCentralDifferences) {
  const Effect& effect = find_effect(GetParam());
  const DiagnosisModel baseline = effect.id() == "damper_friction"        ? rig_passat(0.0)
                                  : effect.id() == "top_mount_compliance" ? rig_passat(60.0, 1e9)
                                                                          : rig_passat();
  ASSERT_EQ(effect.not_applicable(baseline), "");
  const DiagnosisModel with = apply(baseline, effect.change(baseline));
  const HysteresisRecord record = testing::multisine_rig_record(with.strut, 4.0, 500.0);
  std::vector<std::string> free;
  for (const auto& p : effect.change(baseline).free) free.push_back(p.name);
  free.push_back("damping_Ns_per_m");
  // Off the truth, so residuals are not zero.
  model::StrutTestParameters<double> at = with.strut;
  // The multisine stays below the knee's start (0.1 m/s): put the knee where it acts.
  if (effect.id() == "damper_digressive") at.damper_knee_velocity_m_per_s = 0.01;
  strut_parameter(at, strut_parameter_index(free[0])) *= 1.05;
  // Central differences of the discrete map the Jacobian belongs to: this run's steps, frozen.
  simulate::StrutTestSolverOptions solver;
  const auto steps = simulate::strut_test_steps(record.time_s, record.displacement_m, at, solver);
  solver.frozen_steps = &steps;
  std::unique_ptr<ceres::CostFunction> cost(make_hysteresis_cost(record, at, free, solver));
  std::vector<double> x;
  for (const auto& name : free) x.push_back(strut_parameter(at, strut_parameter_index(name)));
  expect_exact_jacobian(*cost, x, free, 1e-6, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(LoopLibrary, LoopEffectGradient,
                         ::testing::Values("gas_force", "friction_velocity_dependence",
                                           "damper_friction", "top_mount_compliance", "free_play",
                                           "damper_asymmetry", "damper_digressive"));

}  // namespace
}  // namespace ridefit::fitting::diagnose
