// Data-sheet priors in the PSD fit (PsdFitOptions::priors): a tight one holds its parameter at
// the sheet's value, a loose one yields to the spectra, one in between lands between them; up to
// twelve parameters are fitted, more are refused before anything runs. Records by CVODE with
// the sensor chain (support/hidden_effect_record.h).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/psd_fit.h"
#include "support/hidden_effect_record.h"
#include "support/passat.h"

namespace ridefit::fitting {
namespace {

model::QuarterCarParameters<double> slip_passat() {
  auto p = testing::passat_corner().parameters;
  p.coulomb_force_N = 0.0;
  return p;
}

const PsdMeasurement& record() {
  static const PsdMeasurement m = testing::hidden_effect_record(
      model::QuarterCar(model::DamperState::kSlip, slip_passat()), road::Iso8608Class::kC, 3);
  return m;
}

// The sheet says 420 kg for the body (385.4 kg true, +9 %), damping as the truth.
PsdFitResult fit_body_mass(std::optional<double> prior_share) {
  auto sheet = slip_passat();
  sheet.sprung_mass_kg = 420.0;
  PsdFitOptions options;
  options.segment_s = 2.0;
  options.free = {"sprung_mass_kg", "damping_Ns_per_m"};
  if (prior_share) options.priors["sprung_mass_kg"] = {420.0, *prior_share * 420.0};
  return fit_psd(record(), model::QuarterCar(model::DamperState::kSlip, sheet), options);
}

TEST(PsdPrior, ATightPriorHoldsTheSheetsValueALooseOneYieldsToTheSpectra) {
  const double free = fit_body_mass(std::nullopt).values[0];
  EXPECT_NEAR(free, 385.4, 0.03 * 385.4);
  const PsdFitResult tight = fit_body_mass(1e-4);
  EXPECT_NEAR(tight.values[0], 420.0, 0.1);
  const PsdFitResult loose = fit_body_mass(10.0);
  EXPECT_NEAR(loose.values[0], free, 0.005 * free);
  // A 1 % prior against hundreds of bins that each see the body mode: in between, strictly.
  const double between = fit_body_mass(0.01).values[0];
  EXPECT_GT(between, free + 0.5);
  EXPECT_LT(between, 420.0 - 0.5);
}

TEST(PsdPrior, TwelveParametersAreFittedThirteenAreRefusedBeforeAnyRun) {
  PsdFitOptions options;
  options.segment_s = 2.0;
  options.max_iterations = 2;  // the width of the Jets is what is checked, not convergence
  const auto sheet = slip_passat();
  for (const char* name :
       {"sprung_mass_kg", "unsprung_mass_kg", "tyre_stiffness_N_per_m", "tyre_damping_Ns_per_m",
        "spring_stiffness_N_per_m", "top_mount_spring_path_stiffness_N_per_m",
        "top_mount_stiffness_N_per_m", "damping_Ns_per_m"}) {
    options.free.push_back(name);
  }
  const PsdFitResult eight =
      fit_psd(record(), model::QuarterCar(model::DamperState::kSlip, sheet), options);
  EXPECT_EQ(eight.values.size(), 8u);
  EXPECT_LT(eight.final_cost, 1e300);
  std::vector<std::string> thirteen = options.free;
  for (const char* name : {"dahl_sigma0_N_per_m", "coulomb_force_N", "dahl_exponent",
                           "compression_to_rebound_ratio", "damper_knee_velocity_m_per_s"}) {
    thirteen.push_back(name);
  }
  options.free = thirteen;
  try {
    fit_psd(record(), model::QuarterCar(model::DamperState::kSlip, sheet), options);
    ADD_FAILURE() << "thirteen free parameters were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("name 1 to 12 parameters to fit (13 named)"),
              std::string::npos)
        << e.what();
  }
}

TEST(PsdPrior, APriorOnAHeldParameterOrWithoutSpreadIsRefused) {
  PsdFitOptions options;
  options.free = {"damping_Ns_per_m"};
  options.priors["sprung_mass_kg"] = {385.4, 10.0};
  EXPECT_THROW(
      {
        try {
          options.validate();
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("prior on sprung_mass_kg: it is not fitted"),
                    std::string::npos)
              << e.what();
          throw;
        }
      },
      InputError);
  options.priors = {{"damping_Ns_per_m", {886.9, 0.0}}};
  EXPECT_THROW(options.validate(), InputError);
  options.priors = {{"damping_Ns_per_m", {std::nan(""), 10.0}}};
  EXPECT_THROW(options.validate(), InputError);
}

}  // namespace
}  // namespace ridefit::fitting
