#pragma once

#include "ridefit/model/quarter_car.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/synthetic/hidden_dataset_spec.h"

namespace ridefit::synthetic {

// The truth a hidden dataset simulates: the model file with the spec's `set:` (and damper_state);
// for a strut rig dataset its strut on the rig (fitting::strut_on_rig) with `set:` applied to the
// strut-test keys.
struct HiddenTruthModel {
  model::QuarterCar car;
  model::StrutTestParameters<double> strut{};  // strut rig datasets only
};

// Loads and checks everything a dataset reads (model, excitation, sensor) before anything is
// simulated. InputError from the model, the excitation or the sensor model; an error caused by a
// `set:` entry says so, naming its place in the spec.
HiddenTruthModel load_truth_model(const HiddenDataset& d);

}  // namespace ridefit::synthetic
