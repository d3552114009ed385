"""ridefit: vehicle vertical dynamics with suspension friction, from Python.

The C++ library (the `ridefit` command's) with NumPy arrays in and out:

    import ridefit
    car = ridefit.load_model("datasets/vehicles/passat_b8_front.yaml")
    road = ridefit.load_excitation("datasets/excitations/smooth_road_seed001.yaml")
    run = ridefit.simulate(car, road)            # run["body_acc"], run.statistics
    psd = ridefit.welch_psd(run["body_acc"], 1000.0, segment_s=4.0)

Bad input raises ridefit.InputError (a ValueError), a failed run ridefit.RunError (a
RuntimeError), each with the message the command line prints. Long calls release the GIL.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from typing import Any, Callable, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

from ._ridefit import (  # noqa: F401  (re-exported)
    InputError,
    Model,
    Road,
    RunError,
    __version__,
    apply_weighting,
    load_excitation,
    measured_road,
    minimum_sample_rate_Hz,
    model_from_dict,
    road_from_dict,
    running_rms,
    vibration_metrics,
    weighting_magnitude,
    welch_psd,
)
from ._ridefit import load_hysteresis_record as _load_hysteresis_record
from ._ridefit import load_model as _load_model
from ._ridefit import modes as _modes
from . import _ridefit

PathLike = Union[str, "os.PathLike[str]"]
ModelLike = Union[Model, PathLike, Mapping[str, Any]]
RoadLike = Union[Road, PathLike, Mapping[str, Any]]

__all__ = [
    "InputError", "RunError", "Model", "Road", "SimulationResult", "load_model",
    "model_from_dict", "modes", "load_excitation", "road_from_dict", "measured_road",
    "profile_road", "simulate",
    "welch_psd", "weighting_magnitude", "apply_weighting", "minimum_sample_rate_Hz",
    "vibration_metrics", "running_rms", "analyse", "load_hysteresis_record", "fit_hysteresis", "fit_psd",
    "diagnose", "optimise",
]


def load_model(path: PathLike, overrides: Optional[Mapping[str, Any]] = None,
               damper_state: str = "") -> Model:
    """Reads a model file (YAML, quarter or half car), with the CLI's --set overrides and
    --damper-state. Raises InputError with the CLI's message for a bad file."""
    return _load_model(os.fspath(path), dict(overrides or {}), damper_state)


def _model(model: ModelLike) -> Model:
    if isinstance(model, Model):
        return model
    if isinstance(model, Mapping):
        return model_from_dict(dict(model))
    return load_model(model)


def _road(road: RoadLike) -> Road:
    if isinstance(road, Road):
        return road
    if isinstance(road, Mapping):
        return road_from_dict(dict(road))
    return load_excitation(os.fspath(road))


def modes(model: ModelLike, state: str = "") -> Dict[str, Any]:
    """Eigenfrequencies and damping ratios of the linear slip and stick quarter car, as
    `ridefit modes MODEL --json` prints them. state: '' (both), 'slip' or 'stick'; a half car's
    strut axles take it, a half car of passive axles has one state, 'passive'."""
    return _modes(_model(model), state)


class SimulationResult(dict):
    """Every channel of a run as a float64 array under its CSV name (`ridefit simulate -o`):
    time, road, body_acc, wheel_acc, travel, tyre_force, damper_force, friction_force,
    top_mount_deflection, stuck (quarter car; the half car's are road_front, seat_acc, ...).

    Attributes: units ({channel: SI unit}), summary (`ridefit simulate --json`'s structure),
    statistics (the solver's: steps, right-hand-side evaluations, ...), notes (what the CLI
    prints as `note:` on stderr)."""

    units: Dict[str, str]
    summary: Dict[str, Any]
    statistics: Dict[str, Any]
    notes: List[str]

    def structured(self):
        """The channels as one NumPy structured array (one field per channel)."""
        import numpy as np

        names = list(self.keys())
        out = np.empty(len(self["time"]), dtype=[(name, np.float64) for name in names])
        for name in names:
            out[name] = self[name]
        return out


def simulate(model: ModelLike, road: RoadLike, output_rate_Hz: float = 1000.0,
             duration_s: float = 0.0, method: str = "esdirk", rtol: float = 1e-5,
             step_s: float = 1e-4, rear_delay_s: Optional[float] = None) -> SimulationResult:
    """Simulates a quarter or half car over a road from static equilibrium at rest, as
    `ridefit simulate MODEL EXCITATION` does (same defaults: 1000 Hz output, the road's
    duration, the esdirk integrator at rtol 1e-5; method 'cvode' or 'rk4' with step_s).
    rear_delay_s: a half car on a road given over time. model and road may also be paths or
    dicts. The GIL is released while it runs.

    Returns a SimulationResult: {channel: float64 array} under the CSV's names (time, road,
    body_acc, wheel_acc, travel, ...), with .units, .statistics (the solver's), .summary (the
    `--json` structure) and .structured() (one NumPy structured array)."""
    channels, units, summary, notes = _ridefit._simulate(
        _model(model), _road(road), float(output_rate_Hz), float(duration_s), method,
        float(rtol), float(step_s), rear_delay_s)
    result = SimulationResult(channels)
    result.units = units
    result.summary = summary
    result.statistics = summary["solver"]
    result.notes = notes
    return result


def profile_road(distance_m, elevation_m, speed_m_per_s: Optional[float] = None,
                 speed_km_per_h: Optional[float] = None, offset_m: float = 0.0) -> Road:
    """A road profile h(x) (arrays in m, strictly increasing distances, at least 5 points)
    driven at a speed (give exactly one of speed_m_per_s and speed_km_per_h), as an
    excitation of `type: profile` drives its CSV; offset_m: where the tyre is at t = 0
    relative to the first point."""
    if (speed_m_per_s is None) == (speed_km_per_h is None):
        raise InputError("profile_road: give exactly one of speed_m_per_s and speed_km_per_h")
    speed = speed_m_per_s if speed_m_per_s is not None else speed_km_per_h / 3.6
    return _ridefit._profile_road(distance_m, elevation_m, float(speed), float(offset_m))


# The SI unit of each channel a recording may hold (design.md's names), for arrays written to a
# CSV on their way to a library reader.
_CHANNEL_UNITS = {"time": "s", "road": "m", "body_acc": "m/s^2", "wheel_acc": "m/s^2",
                  "seat_acc": "m/s^2", "displacement": "m", "force": "N", "current": "A",
                  "voltage": "V", "travel": "m", "tyre_force": "N", "damper_force": "N",
                  "friction_force": "N"}


def _write_recording(mapping: Mapping[str, Any], path: str) -> None:
    import numpy as np

    units = dict(_CHANNEL_UNITS, **getattr(mapping, "units", {}))
    names = [name for name in mapping if name in units]
    if "time" not in names:
        raise InputError("a recording given as arrays needs a 'time' array [s]")
    columns = np.column_stack([np.asarray(mapping[name], dtype=np.float64) for name in names])
    header = ",".join(f"{name}[{units[name]}]" for name in names)
    # %.17g: the doubles read back bit for bit.
    np.savetxt(path, columns, delimiter=",", header=header, comments="", fmt="%.17g")


@contextlib.contextmanager
def _recording_files(records: Sequence[Any]):
    """CSV paths for records given as paths or as dicts of arrays under channel names (a
    SimulationResult too); the latter are written to temporary CSVs (the readers' checks apply
    to them as to files) that are removed afterwards."""
    with tempfile.TemporaryDirectory(prefix="ridefit-") as directory:
        paths = []
        for i, record in enumerate(records):
            if isinstance(record, Mapping):
                path = os.path.join(directory, f"record{i}.csv")
                _write_recording(record, path)
                paths.append(path)
            else:
                paths.append(os.fspath(record))
        yield paths


def analyse(recordings: Union[PathLike, Mapping[str, Any], Sequence[Any]],
            channels: Iterable[str] = (), weighting: str = "auto",
            band_Hz: Tuple[float, float] = (0.5, 30.0), segment_s: float = 0.0,
            overlap: float = 0.5, detrend: str = "mean", smooth_bins: int = 1,
            confidence: float = 0.9, static_tyre_load_N: Optional[float] = None,
            model: Optional[ModelLike] = None,
            rattle_space_m: Optional[Tuple[float, float]] = None, impact: bool = False,
            levels: Sequence[float] = (), level_name: str = "level") -> Dict[str, Any]:
    """The numbers a ride engineer reports for recordings, as `ridefit analyse --json`:
    per recording every channel's RMS, peak, band RMS and, by channel name or `weighting`
    ('auto', 'none', 'Wk', ...), the ISO 2631-1 weighted RMS, MTVV, VDV, crest factor and
    comfort reactions; tyre load (static_tyre_load_N or a quarter-car model), travel
    (rattle_space_m) and impact figures; the averaged spectra with their confidence band; and
    with levels (one per recording) the correlation of every metric with them.

    recordings: CSVs (time[s] and name[unit] columns) or dicts of arrays under channel names in
    SI units (a SimulationResult too). Returns the CLI's JSON structure plus 'spectra':
    {channel: {'unit', 'frequency_Hz', 'psd', 'lower', 'upper'}}."""
    if isinstance(recordings, (str, os.PathLike, Mapping)):
        recordings = [recordings]
    with _recording_files(recordings) as paths:
        return _ridefit._analyse(
            paths, list(channels), weighting, (float(band_Hz[0]), float(band_Hz[1])),
            float(segment_s), float(overlap), detrend, int(smooth_bins), float(confidence),
            static_tyre_load_N, _model(model) if model is not None else None,
            (float(rattle_space_m[0]), float(rattle_space_m[1])) if rattle_space_m else None,
            bool(impact), [float(v) for v in levels], level_name)


def load_hysteresis_record(path: PathLike) -> Dict[str, Any]:
    """A strut rig record (CSV: time, displacement, force[, current|voltage]) in SI units:
    {'source', 'time_s', 'displacement_m', 'force_N'[, 'command', 'command_unit']}, checked as
    `ridefit fit hysteresis` checks it."""
    return _load_hysteresis_record(os.fspath(path))


def _record(record: Union[PathLike, Mapping[str, Any]]):
    if isinstance(record, Mapping):
        return dict(record)
    return os.fspath(record)


def fit_hysteresis(records: Union[PathLike, Mapping[str, Any], Sequence[Any]], model: ModelLike,
                   free: Iterable[str], per_file: Iterable[str] = (),
                   bounds: Optional[Mapping[str, Tuple[float, float]]] = None,
                   starts: Optional[Mapping[str, float]] = None, loss: str = "none",
                   loss_scale_N: float = 5.0, rtol: float = 1e-6, interpolation: str = "spline",
                   max_iterations: int = 100, compression_mm: Iterable[float] = (),
                   max_nrmse_percent: float = 10.0, output: Optional[PathLike] = None,
                   keep: bool = False, record_weights: str = "newtons") -> Dict[str, Any]:
    """Fits the strut's parameters to rig records, as `ridefit fit hysteresis --json` does.

    records: one or a list of records, each a CSV path or a dict of arrays {'time_s',
    'displacement_m', 'force_N'[, 'command', 'command_unit', 'source']} (extension and
    tension positive). model: the start values (a Model, path or dict). free: parameter names
    (e.g. ['dahl_sigma0_N_per_m', 'coulomb_force_N']); per_file, bounds {name: (lo, hi)},
    starts {name: value}, loss ('none', 'huber', 'cauchy'), record_weights ('newtons', or
    'relative': each record over its own force's spread), ... as the CLI's flags.

    Returns the CLI's JSON structure (parameters with standard errors, correlation, cost,
    nrmse_percent, explains_data, ...) plus 'fitted_force_N' (an array per record) and
    'records' (the measured arrays) and 'written'. output: the fitted model file (YAML, the
    model file's schema; one per record with per-file parameters, as the CLI's -o), written
    when the fit explains the data or with keep. Raises RunError when the fit does not
    converge; a fit that does not explain the data is returned with explains_data False."""
    if isinstance(records, (str, os.PathLike, Mapping)):
        records = [records]
    return _ridefit._fit_hysteresis(
        [_record(r) for r in records], _model(model), list(free), list(per_file),
        {k: (float(v[0]), float(v[1])) for k, v in (bounds or {}).items()},
        {k: float(v) for k, v in (starts or {}).items()}, loss, float(loss_scale_N),
        float(rtol), interpolation, int(max_iterations), [float(c) for c in compression_mm],
        float(max_nrmse_percent), os.fspath(output) if output else "", bool(keep),
        record_weights)


def fit_psd(measurement: Union[PathLike, Mapping[str, Any]], model: ModelLike,
            free: Iterable[str], excitation: Optional[PathLike] = None,
            band_Hz: Tuple[float, float] = (0.5, 30.0), segment_s: float = 10.0,
            starts: int = 1, max_iterations: int = 50, loss: str = "none", rtol: float = 1e-4,
            body_noise_psd: Optional[float] = None, wheel_noise_psd: Optional[float] = None,
            max_nrmse_percent: float = 10.0, output: Optional[PathLike] = None,
            keep: bool = False) -> Dict[str, Any]:
    """Fits quarter-car parameters to a measurement's acceleration spectra, as
    `ridefit fit psd --json` does. measurement: a CSV (time, road unless `excitation`,
    body_acc and/or wheel_acc, optionally current or voltage) or the same as a dict of arrays
    in SI units (a SimulationResult too). Returns the CLI's JSON structure plus 'spectra'
    (frequency_Hz, measured and fitted PSDs) and 'written'. output: the fitted model file
    (YAML, the model file's schema; the CLI's -o), written when the fit explains the data or
    with keep."""
    with _recording_files([measurement]) as (path,):
        return _ridefit._fit_psd(
            path, _model(model), list(free),
            os.fspath(excitation) if excitation is not None else "",
            (float(band_Hz[0]), float(band_Hz[1])), float(segment_s), int(starts),
            int(max_iterations), loss, float(rtol), body_noise_psd, wheel_noise_psd,
            float(max_nrmse_percent), os.fspath(output) if output else "", bool(keep))


def diagnose(model: ModelLike, records: Union[PathLike, Mapping[str, Any], Sequence[Any]],
             excitations: Sequence[PathLike] = (), effects: Union[str, Iterable[str]] = "all",
             free: Iterable[str] = (),
             tolerances: Union[str, Mapping[str, float]] = "default",
             band_Hz: Tuple[float, float] = (0.5, 30.0),
             segment_s: float = 4.0, screening_rtol: float = 1e-3, rtol: float = 1e-4,
             body_noise_psd: Optional[float] = None, wheel_noise_psd: Optional[float] = None,
             threads: int = 0, progress: Optional[Callable[[str], None]] = None
             ) -> Dict[str, Any]:
    """Finds the physical effect the model misses, as `ridefit diagnose --json` does: vehicle
    measurements (one or two CSVs: time, road or excitations, body_acc/wheel_acc) or strut rig
    records (time, displacement, force); a record may also be a dict of arrays under those
    channel names in SI units (a SimulationResult too). effects: 'all' or a list of the library's ids.
    Returns the CLI's JSON structure (ranked effects, scores, parameters, the gap before and
    after) as a dict; no report folder is written. progress: called with each line the CLI
    prints on stderr (from the diagnosis's threads, with the GIL taken). tolerances: the
    baseline values a data sheet is unsure of, freed in every fit, as `--tolerances`:
    "default" (vehicle spectra: held; rig loops: "datasheet"), "none" (held), "datasheet" (the
    usual set: on spectra with a Gaussian prior at the model's value, on rig loops within three
    tolerances of it), or a dict {key: share of the value as one standard deviation}."""
    if isinstance(records, (str, os.PathLike, Mapping)):
        records = [records]
    if isinstance(tolerances, str):
        if tolerances not in ("default", "datasheet", "none"):
            raise InputError(f"tolerances: '{tolerances}'; expected 'default', 'datasheet', "
                             "'none' or a dict {key: share}")
        sheet = {} if tolerances == "none" else None
    else:
        sheet = {str(k): float(v) for k, v in tolerances.items()}
    if isinstance(effects, str):
        effects = [] if effects == "all" else effects.split(",")
    with _recording_files(records) as paths:
        return _ridefit._diagnose(
            _model(model), paths, [os.fspath(e) for e in excitations], list(effects),
            list(free), sheet, tolerances == "datasheet", (float(band_Hz[0]), float(band_Hz[1])),
            float(segment_s), float(screening_rtol), float(rtol), body_noise_psd, wheel_noise_psd,
            int(threads), progress)


def optimise(study: PathLike, output: Optional[PathLike] = None,
             journal: Optional[PathLike] = None, threads: Optional[int] = None,
             progress: Optional[Callable[[str], None]] = None) -> Dict[str, Any]:
    """Damper tuning with NLopt under friction from a study file (YAML), as
    `ridefit optimise STUDY --json` runs it. Returns the result tree (status, variables,
    objective, constraint margins, load cases, friction, the cost of ignoring it, the
    trade-off) as a dict; an infeasible optimum is reported in it, not raised.

    output: a result YAML to write (NAME_model.yaml and NAME_tradeoff.csv go beside it);
    journal: a journal file of the evaluations (started afresh); threads: for the load cases
    (0 = every core; default: the study's); progress: called with each line the CLI prints on
    stderr. Without output and journal nothing is written."""
    return _ridefit._optimise(os.fspath(study), os.fspath(output) if output else "",
                              os.fspath(journal) if journal else "", threads, progress)
