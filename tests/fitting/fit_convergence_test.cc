// A fit that explains the data but did not converge is a failed run; otherwise nothing happens.
#include "ridefit/fitting/fit_convergence.h"

#include <gtest/gtest.h>

#include "ridefit/common/errors.h"

namespace ridefit::fitting {
namespace {

TEST(FitConvergence, OnlyAnUnconvergedFitThatExplainsTheDataIsARunError) {
  EXPECT_NO_THROW(require_convergence(true, true, "the fit", 5, "converged", "x"));
  EXPECT_NO_THROW(require_convergence(false, false, "the fit", 50, "no step", "x"));
  try {
    require_convergence(false, true, "the PSD fit", 50, "maximum iterations", "--starts 5");
    FAIL() << "no exception";
  } catch (const RunError& e) {
    EXPECT_STREQ(e.what(),
                 "the PSD fit did not converge after 50 iterations (maximum iterations); no "
                 "fitted model was written. Try --starts 5");
  }
}

}  // namespace
}  // namespace ridefit::fitting
