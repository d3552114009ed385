// The fits' option structs check themselves (validate()), and the robust loss is a choice, not a
// string.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "ridefit/fitting/hysteresis_fit_options.h"
#include "ridefit/fitting/psd_fit_options.h"
#include "ridefit/fitting/robust_loss.h"
#include "support/throws_input_error.h"

namespace ridefit::fitting {
namespace {

using testing::throws_input_error;

TEST(RobustLoss, ParsesItsThreeNamesAndRefusesOthersListingThem) {
  for (auto loss : {RobustLoss::kNone, RobustLoss::kHuber, RobustLoss::kCauchy}) {
    EXPECT_EQ(parse_robust_loss(to_string(loss)), loss);
  }
  EXPECT_TRUE(throws_input_error([] { parse_robust_loss("l1"); }, "none, huber, cauchy"));
  EXPECT_EQ(make_loss_function(RobustLoss::kNone, 1.0), nullptr);
  // Huber at scale 2: ρ(s) = s for s <= 4, 2·2·√s − 4 beyond (Ceres' definition, s = r²).
  std::unique_ptr<ceres::LossFunction> huber(make_loss_function(RobustLoss::kHuber, 2.0));
  double rho[3];
  huber->Evaluate(9.0, rho);
  EXPECT_DOUBLE_EQ(rho[0], 2.0 * 2.0 * 3.0 - 4.0);
  std::unique_ptr<ceres::LossFunction> cauchy(make_loss_function(RobustLoss::kCauchy, 2.0));
  cauchy->Evaluate(4.0, rho);
  EXPECT_DOUBLE_EQ(rho[0], 4.0 * std::log1p(1.0));  // b·log(1 + s/b), b = scale²
}

TEST(HysteresisFitOptions, ValidateNamesWhatIsWrong) {
  HysteresisFitOptions o;
  EXPECT_TRUE(throws_input_error([&] { o.validate(); }, "at least one parameter"));
  o.free = {"coulomb_force_N", "dahl_sigma0_N_per_m"};
  EXPECT_NO_THROW(o.validate());
  o.free.push_back("coulomb_force_N");
  EXPECT_TRUE(throws_input_error([&] { o.validate(); }, "'coulomb_force_N' is given twice"));
  o.free.pop_back();
  o.per_file = {"damping_Ns_per_m"};
  EXPECT_TRUE(throws_input_error([&] { o.validate(); }, "not among the free parameters"));
  o.per_file.clear();
  o.bounds["coulomb_force_N"] = {50.0, 10.0};
  EXPECT_TRUE(throws_input_error([&] { o.validate(); }, "must be below upper"));
  o.bounds["coulomb_force_N"] = {10.0, 50.0};
  EXPECT_EQ(o.resolved_bounds()[strut_parameter_index("coulomb_force_N")].second, 50.0);
  EXPECT_EQ(o.resolved_bounds()[strut_parameter_index("dahl_exponent")].second,
            kStrutParameters[strut_parameter_index("dahl_exponent")].upper);
  o.loss_scale_N = 0.0;
  EXPECT_TRUE(throws_input_error([&] { o.validate(); }, "loss scale"));
  o.loss_scale_N = 5.0;
  o.max_iterations = -1;
  EXPECT_TRUE(throws_input_error([&] { o.validate(); }, "iteration limit"));
}

TEST(PsdFitOptions, ValidateNamesWhatIsWrong) {
  PsdFitOptions o;
  EXPECT_NO_THROW(o.validate(false));  // a comparison frees nothing
  EXPECT_TRUE(
      throws_input_error([&] { o.validate(); }, "name 1 to 12 parameters to fit (0 named)"));
  o.free = {"top_mount_stiffness_N_per_m"};
  EXPECT_NO_THROW(o.validate());
  o.free.push_back("top_mount_stiffnes_N_per_m");
  EXPECT_TRUE(throws_input_error([&] { o.validate(); }, "not a quarter-car parameter"));
  o.free.pop_back();
  o.band_low_Hz = 40.0;
  EXPECT_TRUE(throws_input_error([&] { o.validate(); }, "0 < low < high"));
  o.band_low_Hz = 0.5;
  o.relative_tolerance = 0.5;
  EXPECT_TRUE(throws_input_error([&] { o.validate(); }, "relative tolerance"));
  o.relative_tolerance = 1e-4;
  o.starts = 0;
  EXPECT_TRUE(throws_input_error([&] { o.validate(); }, "starts 0"));
}

}  // namespace
}  // namespace ridefit::fitting
