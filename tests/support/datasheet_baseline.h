#pragma once

#include <cstdint>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car.h"
#include "ridefit/synthetic/datasheet_values.h"

namespace ridefit::testing {

// `car` as an engineer's data sheet gives it (synthetic::datasheet_values: masses ±3 %, tyre
// and spring ±8 %, damping ±12 %, top mount ±15 %, Fc ±25 %, σ0 a factor 2; uniform, seeded).
inline model::QuarterCar datasheet_baseline(const model::QuarterCar& car, std::uint64_t seed) {
  fitting::diagnose::DiagnosisModel m{car};
  fitting::diagnose::EffectChange change;
  for (const auto& [name, value] : synthetic::datasheet_values(car, seed)) change.set[name] = value;
  return fitting::diagnose::apply(m, change).car;
}

}  // namespace ridefit::testing
