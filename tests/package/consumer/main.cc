// Uses one piece of each installed library: the quarter car's modes (core), a strut parameter's
// row (fitting) and the tuning settings' rules (optimisation). Exits 1 if a result is off.
#include <cstdio>
#include <exception>

#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/optimisation/tuning_settings.h"
#include "ridefit/simulate/quarter_car_modes.h"
#include "ridefit/version.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer MODEL.yaml\n");
    return 2;
  }
  try {
    ridefit::io::ModelOverrides linear;
    linear.damper_state = "slip";
    const auto car = ridefit::io::load_quarter_car(argv[1], linear).make_model();
    const auto modes = ridefit::simulate::quarter_car_modes(car);
    const std::size_t coulomb = ridefit::fitting::strut_parameter_index("coulomb_force_N");
    ridefit::optimisation::OptimiserSettings settings;
    settings.starts = 0;
    const bool refused = settings.error().has_value();
    std::printf("ridefit %s: %zu oscillatory modes, first %.3f Hz; Fc is strut parameter %zu\n",
                RIDEFIT_VERSION, modes.oscillatory.size(),
                modes.oscillatory.front().natural_frequency_Hz, coulomb);
    const double f = modes.oscillatory.front().natural_frequency_Hz;
    return modes.oscillatory.size() >= 2 && f > 0.5 && f < 50.0 && refused ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
