#pragma once

#include <vector>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/fitting/psd_fit.h"
#include "ridefit/model/quarter_car.h"

namespace ridefit::fitting::diagnose {

// The RMS stroke speed of rig records [m/s]: their velocity column where they have one, else
// central differences of the displacement (uneven steps allowed). 0 for records too short.
double damper_speed_rms_m_per_s(const std::vector<HysteresisRecord>& records);

// The RMS rate of the suspension travel [m/s] of `car` run over the record's road for the
// record's duration: the speeds a vehicle record's damper sees, by the engineer's model (its
// values off by data-sheet margins change this by a few per cent). 0 when the record has no
// road or the run fails.
double damper_speed_rms_m_per_s(const model::QuarterCar& car, const PsdMeasurement& record);

}  // namespace ridefit::fitting::diagnose
