#pragma once

// The pieces of the `_ridefit` extension: each bind_*.cc adds one concept's functions to the
// module (module.cc calls them in order: the classes before the functions that take them).

#include <pybind11/pybind11.h>

namespace ridefit::python {

void bind_model(pybind11::module_& m);     // Model, load_model, model_from_dict, modes
void bind_road(pybind11::module_& m);      // Road, load_excitation, road_from_dict, measured_road
void bind_simulate(pybind11::module_& m);  // simulate
void bind_signal(pybind11::module_& m);    // welch_psd
void bind_comfort(pybind11::module_& m);   // ISO 2631-1 weightings and metrics
void bind_analyse(pybind11::module_& m);   // analyse (recordings: metrics, comfort, spectra)
void bind_fitting(pybind11::module_& m);   // fit_hysteresis, fit_psd, load_hysteresis_record
void bind_diagnose(pybind11::module_& m);  // diagnose
void bind_optimise(pybind11::module_& m);  // optimise

}  // namespace ridefit::python
