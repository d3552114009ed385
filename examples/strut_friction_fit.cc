// Example: the fitting library (ridefit::fitting, Ceres) on a strut rig test.
//
// Fits the Dahl friction of a MacPherson strut (σ0, Fc, d) and the load cell's offset to a
// measured hysteresis loop (imposed displacement, measured force) and prints each value with its
// standard error. The strut's other values (damping, top-mount stiffness) come from a quarter-car
// model file. Derivatives are exact (Jets through the strut's implicit integrator); the
// standard errors come from ceres::Covariance.
//
//   strut_friction_fit MODEL.yaml RECORD.csv
//   e.g., from the repository's root:
//   strut_friction_fit datasets/vehicles/passat_b8_front.yaml datasets/lab/triangle_3mm_1mmps.csv
//
// The command line does the same with `ridefit fit hysteresis RECORD.csv --model MODEL.yaml
// --free dahl_sigma0_N_per_m,coulomb_force_N,dahl_exponent,force_offset_N`. Exit code 1 when
// the fit fails or a value is not finite or outside a broad physical range (the example runs
// as a test), 2 for bad arguments.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <string>
#include <utility>

#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/fitting/strut_start.h"
#include "ridefit/io/quarter_car_file.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    fmt::print(stderr, "usage: {} MODEL.yaml RECORD.csv\n", argv[0]);
    return 2;
  }
  using namespace ridefit;
  try {
    // The record: time, displacement and force columns with units in their headers.
    const fitting::HysteresisRecord record = fitting::load_hysteresis_record(argv[2]);

    // What to fit, by the model files' key names (rig-only ones such as force_offset_N too).
    fitting::HysteresisFitOptions options;
    options.free = {"dahl_sigma0_N_per_m", "coulomb_force_N", "dahl_exponent", "force_offset_N"};
    // A slow triangle is sampled finely: linear interpolation between samples is enough.
    options.solver.interpolation = simulate::RigInterpolation::kLinear;

    // Start: the model file's strut as the rig sees it, with the friction level read off the
    // record's sliding phases instead of the file's (so the fit does not start at the answer),
    // and a deliberately poor guess for σ0 and d.
    const io::QuarterCarFile model = io::load_quarter_car(argv[1]);
    model::StrutTestParameters<double> start =
        fitting::with_estimates(fitting::strut_on_rig(model.parameters),
                                fitting::estimate_strut_start({record}), options.free);
    start.dahl_sigma0_N_per_m = 1e6;
    start.dahl_exponent = 2.0;

    const fitting::HysteresisFitResult fit = fitting::fit_hysteresis({record}, start, options);
    fmt::print("{}: {} iterations, residual RMS {:.3f} N, NRMSE {:.2f} %\n  {}\n", record.source,
               fit.iterations, fit.residual_rms_N, fit.nrmse_percent, fit.termination);

    // Broad physical ranges of a passenger-car strut: (lower, upper) per parameter.
    const std::map<std::string, std::pair<double, double>> plausible = {
        {"dahl_sigma0_N_per_m", {1e4, 1e9}},
        {"coulomb_force_N", {1.0, 1000.0}},
        {"dahl_exponent", {0.2, 5.0}},
        {"force_offset_N", {-100.0, 100.0}}};
    bool ok = fit.converged && fit.explains_data;
    if (!ok) fmt::print(stderr, "FAILED: no converged fit that explains the data\n");
    for (const fitting::FittedParameter& p : fit.parameters) {
      const auto [lo, hi] = plausible.at(p.name);
      const double se = p.standard_error.value_or(NAN);  // empty: the data do not determine it
      fmt::print("  {:<22} {:>12.6g} ± {:.3g}\n", p.name, p.value, se);
      // A value inside its range, determined by the data to better than 10 % of its size.
      if (!(std::isfinite(p.value) && p.value >= lo && p.value <= hi && std::isfinite(se) &&
            se <= 0.1 * std::max(std::abs(p.value), 1.0))) {
        fmt::print(stderr, "FAILED: {} = {} ± {} (expected within [{}, {}])\n", p.name, p.value, se,
                   lo, hi);
        ok = false;
      }
    }
    return ok ? 0 : 1;
  } catch (const std::exception& e) {  // InputError (bad file), RunError (model unsolvable)
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
}
