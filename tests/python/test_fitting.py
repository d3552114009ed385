"""fit_hysteresis (from arrays and from files) and fit_psd against `ridefit fit ... --json`."""

import pathlib

import numpy as np
import pytest

import ridefit
from conftest import assert_same_numbers, dataset, read_csv, run_cli, write_two_tests

TRIANGLE = dataset("lab/triangle_3mm_1mmps.csv")
FREE = "dahl_sigma0_N_per_m,coulomb_force_N,dahl_exponent"


def test_fit_hysteresis_from_arrays_equals_the_cli():
    # From the data sheet's strut values (off the lab truth), not the Passat file (the truth).
    datasheet = dataset("lab/passat_strut_datasheet.yaml")
    cli = run_cli("fit", "hysteresis", TRIANGLE, "--model", datasheet, "--free", FREE,
                  "--interpolation", "linear", "--json").json()
    columns = read_csv(TRIANGLE)  # displacement in mm, as the lab wrote it
    record = {"time_s": columns["time"], "displacement_m": 1e-3 * columns["displacement"],
              "force_N": columns["force"], "source": TRIANGLE}
    fit = ridefit.fit_hysteresis(record, datasheet, free=FREE.split(","), interpolation="linear")
    assert_same_numbers(fit, cli, rtol=1e-6, skip=("written",))
    assert fit["explains_data"]
    assert len(fit["fitted_force_N"]) == 1
    assert fit["fitted_force_N"][0].dtype == np.float64
    assert fit["fitted_force_N"][0].shape == record["time_s"].shape


def test_fit_hysteresis_from_a_file_with_bounds_and_loss_equals_the_cli(passat):
    cli = run_cli("fit", "hysteresis", TRIANGLE, "--model", passat, "--free", FREE,
                  "--interpolation", "linear", "--bounds", "coulomb_force_N=10:200",
                  "--loss", "huber", "--json").json()
    fit = ridefit.fit_hysteresis(TRIANGLE, ridefit.load_model(passat), free=FREE.split(","),
                                 interpolation="linear",
                                 bounds={"coulomb_force_N": (10, 200)}, loss="huber")
    assert_same_numbers(fit, cli, rtol=1e-6, skip=("written",))


def test_fit_hysteresis_of_a_file_of_tests_equals_the_cli(tmp_path, passat):
    # The triangle record as two tests in one file (a segment column): a record per test, each
    # from its own rest state, as the command reads it.
    tests = write_two_tests(TRIANGLE, tmp_path / "two_tests.csv")
    cli = run_cli("fit", "hysteresis", tests, "--model", passat, "--free", FREE,
                  "--interpolation", "linear", "--json").json()
    fit = ridefit.fit_hysteresis(str(tests), passat, free=FREE.split(","),
                                 interpolation="linear")
    assert_same_numbers(fit, cli, rtol=1e-6, skip=("written",))
    assert len(fit["fitted_force_N"]) == 2
    # Per-file values are one model per file: refused for a file of several tests, as by the CLI.
    message = run_cli("fit", "hysteresis", tests, "--model", passat, "--free", FREE,
                      "--per-file", "coulomb_force_N", expect=2).error_message()
    with pytest.raises(ridefit.InputError) as error:
        ridefit.fit_hysteresis(str(tests), passat, free=FREE.split(","),
                               per_file=["coulomb_force_N"])
    assert str(error.value).replace("per_file", "--per-file") == message


def test_fit_hysteresis_refuses_what_the_cli_refuses(passat):
    message = run_cli("fit", "hysteresis", TRIANGLE, "--model", passat, "--free",
                      "coulomb_force_N", "--bounds", "damping_Ns_per_m=1:2",
                      expect=2).error_message()
    assert "is not fitted" in message
    with pytest.raises(ridefit.InputError, match="is not fitted"):
        ridefit.fit_hysteresis(TRIANGLE, passat, free=["coulomb_force_N"],
                               bounds={"damping_Ns_per_m": (1, 2)})
    short = {"time_s": np.arange(10.0), "displacement_m": np.arange(10.0),
             "force_N": np.arange(10.0)}
    with pytest.raises(ridefit.InputError, match="at least 20"):
        ridefit.fit_hysteresis(short, passat, free=["coulomb_force_N"])
    with pytest.raises(ridefit.InputError, match="record weights 'equal'"):
        ridefit.fit_hysteresis(TRIANGLE, passat, free=["coulomb_force_N"],
                               record_weights="equal")
    record = ridefit.load_hysteresis_record(TRIANGLE)
    record["force_N"][100] = np.nan
    with pytest.raises(ridefit.InputError, match=r"force_N\[100\] is nan"):
        ridefit.fit_hysteresis(record, passat, free=["coulomb_force_N"])
    message = run_cli("fit", "hysteresis", TRIANGLE, TRIANGLE, "--model", passat, "--free",
                      "coulomb_force_N", expect=2).error_message()
    with pytest.raises(ridefit.InputError) as error:
        ridefit.fit_hysteresis([TRIANGLE, TRIANGLE], passat, free=["coulomb_force_N"])
    assert str(error.value) == message
    message = run_cli("fit", "hysteresis", TRIANGLE, "--model", passat, "--free", "friction",
                      expect=2).error_message()
    with pytest.raises(ridefit.InputError) as error:
        ridefit.fit_hysteresis(TRIANGLE, passat, free=["friction"])
    assert str(error.value) == message


def test_load_hysteresis_record_converts_to_si():
    record = ridefit.load_hysteresis_record(pathlib.Path(TRIANGLE))
    columns = read_csv(TRIANGLE)
    np.testing.assert_allclose(record["displacement_m"], 1e-3 * columns["displacement"])
    assert record["source"] == TRIANGLE


def test_fit_psd_equals_the_cli(passat):
    measurement = dataset("hidden/damper_friction.csv")
    cli = run_cli("fit", "psd", measurement, "--model", passat, "--free", "coulomb_force_N",
                  "--json", expect=None)
    assert cli.exit_code in (0, 1), cli.stderr  # 1: the model does not explain the data
    fit = ridefit.fit_psd(measurement, passat, free=["coulomb_force_N"])
    assert_same_numbers(fit, cli.json(), rtol=1e-6)
    spectra = fit["spectra"]
    assert spectra["frequency_Hz"].shape == spectra["measured_body_psd"].shape


def test_fit_psd_of_arrays_equals_the_cli_on_their_file(passat):
    measurement = dataset("hidden/damper_friction.csv")  # every column in SI units
    cli = run_cli("fit", "psd", measurement, "--model", passat, "--free", "coulomb_force_N",
                  "--json", expect=None)
    arrays = read_csv(measurement)
    fit = ridefit.fit_psd(arrays, passat, free=["coulomb_force_N"])
    assert_same_numbers(fit, cli.json(), rtol=1e-6)
    with pytest.raises(ridefit.InputError, match="time"):
        ridefit.fit_psd({"body_acc": arrays["body_acc"]}, passat, free=["coulomb_force_N"])


def test_fit_hysteresis_per_file_with_compression_equals_the_cli(passat):
    shims = [dataset(f"lab/shim_{mm}mm.csv") for mm in (0, 2, 4)]
    free = "dahl_sigma0_N_per_m,coulomb_force_N,force_offset_N"
    cli = run_cli("fit", "hysteresis", *shims, "--model", passat, "--free", free, "--per-file",
                  "coulomb_force_N", "--compression", "0,2,4", "--interpolation", "linear",
                  "--json").json()
    fit = ridefit.fit_hysteresis(shims, passat, free=free.split(","), per_file=["coulomb_force_N"],
                                 compression_mm=[0, 2, 4], interpolation="linear")
    assert_same_numbers(fit, cli, rtol=1e-6, skip=("written",))
    assert len(fit["fitted_force_N"]) == 3
    with pytest.raises(ridefit.InputError, match="compression_mm"):
        ridefit.fit_hysteresis(shims, passat, free=free.split(","), compression_mm=[0, 2, 4])


def test_the_fitted_model_files_equal_the_cli_outputs(tmp_path, passat):
    free = FREE + ",force_offset_N"
    cli_file = tmp_path / "cli.yaml"
    run_cli("fit", "hysteresis", TRIANGLE, "--model", passat, "--free", free,
            "--interpolation", "linear", "-o", cli_file)
    python_file = tmp_path / "python.yaml"
    fit = ridefit.fit_hysteresis(TRIANGLE, passat, free=free.split(","), interpolation="linear",
                                 output=python_file)
    assert fit["written"] == [str(python_file)]
    assert ridefit.load_model(python_file).parameters == ridefit.load_model(cli_file).parameters
    with pytest.raises(ridefit.InputError, match="output"):  # an input is never replaced
        ridefit.fit_hysteresis(TRIANGLE, passat, free=["coulomb_force_N"], output=passat)

    measurement = dataset("hidden/damper_friction.csv")
    cli_file = tmp_path / "cli_psd.yaml"
    run_cli("fit", "psd", measurement, "--model", passat, "--free", "coulomb_force_N", "-o",
            cli_file, expect=None)
    python_file = tmp_path / "python_psd.yaml"
    fit = ridefit.fit_psd(measurement, passat, free=["coulomb_force_N"], output=python_file)
    assert fit["written"] == ([str(python_file)] if fit["explains_data"] else [])
    if fit["explains_data"]:
        assert (ridefit.load_model(python_file).parameters
                == ridefit.load_model(cli_file).parameters)
