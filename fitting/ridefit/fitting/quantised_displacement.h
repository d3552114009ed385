#pragma once

#include "ridefit/fitting/hysteresis_record.h"

namespace ridefit::fitting {

// A record's quantised displacement: where its values lie on a step q (an ADC's or the
// export's), a spline through the staircase makes the damper feel velocity spikes of q/Δt
// between samples. signal::choose_quantisation_low_pass decides from the record alone whether a
// zero-phase low-pass removes them and at which cut-off (its cost: the content above the
// cut-off, where the record is below its quantisation floor anyway).
//
// examine_quantised_displacement keeps that decision in record.displacement_low_pass for the
// report and changes nothing: the loaders call it. smooth_quantised_displacement also applies
// it (signal::zero_phase_low_pass: no delay, so the force stays aligned) and sets
// record.displacement_low_passed; applied once. It is not the loaders' default: records
// exported to a print digit (the shipped lab tests, triangles whose corners the rig really made)
// carry steps whose removal changes fits that are right as they are.
void examine_quantised_displacement(HysteresisRecord& record);
void smooth_quantised_displacement(HysteresisRecord& record);

}  // namespace ridefit::fitting
