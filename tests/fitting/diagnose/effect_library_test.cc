// The diagnosis' effect library: its ids, each effect's change (start inside its bounds, applies
// once), and the PSD fit's exact Jacobian with each effect's parameters free against central
// differences.
#include "ridefit/fitting/diagnose/effect.h"

#include <gtest/gtest.h>

#include <ceres/cost_function.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ridefit/fitting/psd_fit.h"
#include "ridefit/io/input_error.h"
#include "ridefit/road/iso8608.h"
#include "support/hidden_effect_record.h"
#include "support/passat.h"

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

TEST(EffectLibrary, HoldsTheIssuesIdsSortedAndNamesThemWhenOneIsUnknown) {
  std::vector<std::string> ids;
  for (const auto& e : effect_library()) ids.emplace_back(e->id());
  EXPECT_TRUE(std::is_sorted(ids.begin(), ids.end()));
  for (const char* id :
       {"damper_friction", "top_mount_compliance", "top_mount_amplitude_stiffening", "tyre_damping",
        "damper_asymmetry", "damper_digressive", "bump_stop", "tyre_lift_off"}) {
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
    const DiagnosisModel baseline =
        effect->id() == "top_mount_compliance" ? rigid_passat() : bare_passat();
    ASSERT_EQ(effect->not_applicable(baseline), "") << effect->id();
    const EffectChange change = effect->change(baseline);
    const DiagnosisModel with = apply(baseline, change);
    for (const auto& p : change.free) {
      const double v = parameter_value(with.car, p.name);
      EXPECT_LT(p.lower, p.upper) << effect->id() << " " << p.name;
      EXPECT_GT(v, p.lower) << effect->id() << " " << p.name;
      EXPECT_LT(v, p.upper) << effect->id() << " " << p.name;
    }
    for (const auto& [key, value] : change.set) {
      EXPECT_EQ(parameter_value(with.car, key), value) << effect->id() << " " << key;
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
}

// A 10 s record on a class C road at 50 km/h: rough enough that the bump stop (20 mm) and the
// damper's knee (0.1 m/s) act, so each parameter moves the spectra.
PsdMeasurement rough_record(const model::QuarterCar& truth) {
  return testing::hidden_effect_record(truth, road::Iso8608Class::kC, 3, 10.0, 500.0, 0.0);
}

class EffectGradient : public ::testing::TestWithParam<std::string> {};

TEST_P(EffectGradient, PsdJacobianMatchesCentralDifferences) {
  const Effect& effect = find_effect(GetParam());
  const DiagnosisModel baseline =
      effect.id() == "top_mount_compliance" ? rigid_passat() : bare_passat();
  const EffectChange change = effect.change(baseline);
  const DiagnosisModel with = apply(baseline, change);
  const PsdMeasurement m = rough_record(with.car);
  PsdFitOptions options;
  for (const auto& p : change.free) {
    options.free.push_back(p.name);
    options.bounds[p.name] = {p.lower, p.upper};
  }
  options.free.push_back("damping_Ns_per_m");
  options.segment_s = 2.0;
  options.steps_per_sample = 2;
  std::unique_ptr<ceres::CostFunction> cost(make_psd_cost(m, with.car, options));
  const std::size_t n = options.free.size();
  std::vector<double> x(n, 1.0);
  x[0] = 1.05;  // off the truth, so residuals are not zero
  std::vector<const double*> blocks;
  for (const double& v : x) blocks.push_back(&v);
  const auto rows = static_cast<std::size_t>(cost->num_residuals());
  std::vector<double> residuals(rows);
  std::vector<std::vector<double>> exact(n, std::vector<double>(rows));
  std::vector<double*> jacobians;
  for (auto& j : exact) jacobians.push_back(j.data());
  ASSERT_TRUE(cost->Evaluate(blocks.data(), residuals.data(), jacobians.data()));
  {
    std::vector<double> plain(rows);
    ASSERT_TRUE(cost->Evaluate(blocks.data(), plain.data(), nullptr));
    double d = 0;
    for (std::size_t r = 0; r < rows; ++r) d = std::max(d, std::abs(plain[r] - residuals[r]));
    EXPECT_LT(d, 1e-9) << "the residuals with and without the Jacobian differ";
  }
  for (std::size_t p = 0; p < n; ++p) {
    const double saved = x[p], step = 1e-6;
    std::vector<double> up(rows), down(rows);
    x[p] = saved + step;
    ASSERT_TRUE(cost->Evaluate(blocks.data(), up.data(), nullptr));
    x[p] = saved - step;
    ASSERT_TRUE(cost->Evaluate(blocks.data(), down.data(), nullptr));
    x[p] = saved;
    double scale = 0.0, worst = 0.0;
    for (std::size_t r = 0; r < rows; ++r) {
      scale = std::max(scale, std::abs(exact[p][r]));
      worst = std::max(worst, std::abs((up[r] - down[r]) / (2.0 * step) - exact[p][r]));
    }
    EXPECT_GT(scale, 1e-3) << options.free[p] << " does not move the spectra";
    EXPECT_LT(worst, 1e-3 * scale) << options.free[p];
  }
}

INSTANTIATE_TEST_SUITE_P(Library, EffectGradient,
                         ::testing::Values("damper_friction", "top_mount_compliance",
                                           "top_mount_amplitude_stiffening", "tyre_damping",
                                           "damper_asymmetry", "damper_digressive", "bump_stop",
                                           "tyre_lift_off"));

}  // namespace
}  // namespace ridefit::fitting::diagnose
