// The `_ridefit` extension: the library's exceptions as Python's, then one concept per file.
#include <glog/logging.h>
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "ridefit/common/errors.h"
#include "ridefit/version.h"

namespace py = pybind11;

PYBIND11_MODULE(_ridefit, m) {
  m.doc() = "ridefit's C++ library (the `ridefit` package wraps it; import ridefit)";
  m.attr("__version__") = RIDEFIT_VERSION;
  // Ceres logs through glog; every condition it reports reaches the caller in ridefit's own words
  // (as on the command line), so its log stays quiet.
  FLAGS_minloglevel = google::GLOG_FATAL;
  // Bad input is a ValueError, a failed run a RuntimeError, each with the CLI's message.
  py::register_exception<ridefit::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<ridefit::RunError>(m, "RunError", PyExc_RuntimeError);
  ridefit::python::bind_model(m);
  ridefit::python::bind_road(m);
  ridefit::python::bind_simulate(m);
  ridefit::python::bind_signal(m);
  ridefit::python::bind_comfort(m);
  ridefit::python::bind_analyse(m);
  ridefit::python::bind_fitting(m);
  ridefit::python::bind_diagnose(m);
  ridefit::python::bind_optimise(m);
}
