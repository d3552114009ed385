"""diagnose and optimise against `ridefit diagnose|optimise --json`."""

import pytest

import ridefit
from conftest import assert_same_numbers, dataset, read_csv, run_cli, write_two_tests

# Wall times, file names and paths of what the CLI wrote.
RUN_KEYS = ("wall_time_s", "report", "model", "files", "journal", "result", "written")


# A shipped record of the slip baseline made by CVODE through the sensor model (0.5 % noise, the
# accelerometers' band; datasets/hidden/README.md), not by `ridefit simulate`'s ESDIRK, which the
# diagnosis runs itself: a false alarm can show.
@pytest.fixture(scope="module")
def record():
    return dataset("hidden/baseline_only.csv")


@pytest.fixture(scope="module")
def slip_baseline():
    return dataset("hidden/baselines/passat_slip.yaml")


def test_diagnose_equals_the_cli(tmp_path, record, slip_baseline):
    cli = run_cli("diagnose", slip_baseline, record, "--effects", "tyre_lift_off,bump_stop",
                  "--segment", 2, "--threads", 1, "--json", "-q", "-o",
                  tmp_path / "diagnosis").json()
    lines = []
    result = ridefit.diagnose(slip_baseline, record, effects=["tyre_lift_off", "bump_stop"],
                              segment_s=2, threads=2, progress=lines.append)
    assert_same_numbers(result, cli, rtol=1e-6, skip=RUN_KEYS)
    assert lines and all(isinstance(line, str) for line in lines)
    assert result["verdict"].startswith("no missing effect found (p = ")
    assert result["explanations"][0]["effects"] == []


def test_diagnose_of_rig_loops_equals_the_cli(tmp_path, passat):
    rig = dataset("hidden/rig_baseline_only.csv")
    cli = run_cli("diagnose", passat, rig, "--effects", "gas_force", "--threads", 1, "--json",
                  "-q", "-o", tmp_path / "loops").json()
    result = ridefit.diagnose(passat, rig, effects="gas_force", threads=1)
    assert_same_numbers(result, cli, rtol=1e-6, skip=RUN_KEYS)
    # The same record as arrays (displacement converted from the file's mm).
    columns = read_csv(rig)
    arrays = {"time": columns["time"], "displacement": 1e-3 * columns["displacement"],
              "force": columns["force"]}
    from_arrays = ridefit.diagnose(passat, arrays, effects="gas_force", threads=1)
    assert from_arrays["verdict"] == result["verdict"]
    assert from_arrays["gap_after_nrmse_percent"] == pytest.approx(
        result["gap_after_nrmse_percent"], rel=1e-6)


def test_diagnose_splits_a_file_of_tests_as_the_cli(tmp_path, passat):
    # The shipped rig record as two tests in one file (a segment column): each test is a record
    # of its own, fitted and judged apart, as the command does it.
    tests = write_two_tests(dataset("hidden/rig_baseline_only.csv"), tmp_path / "two_tests.csv")
    cli = run_cli("diagnose", passat, tests, "--effects", "gas_force", "--threads", 1, "--json",
                  "-q", "-o", tmp_path / "loops").json()
    result = ridefit.diagnose(passat, tests, effects="gas_force", threads=1)
    assert_same_numbers(result, cli, rtol=1e-6, skip=RUN_KEYS)


def test_diagnose_refuses_what_the_cli_refuses(tmp_path, record, passat):
    message = run_cli("diagnose", passat, record, "--effects", "gas_spring", "-o",
                      tmp_path / "d", expect=2).error_message()
    with pytest.raises(ridefit.InputError) as error:
        ridefit.diagnose(passat, record, effects="gas_spring")
    assert str(error.value).replace("effects:", "--effects:") == message


def test_diagnose_tolerances_as_the_cli(tmp_path, record, slip_baseline):
    # A tolerance set of the caller's own gives the CLI's numbers for the same KEY=SHARE items;
    # bad ones are refused before any fit.
    cli = run_cli("diagnose", slip_baseline, record, "--effects", "tyre_lift_off",
                  "--tolerances", "sprung_mass_kg=0.05", "--segment", 2, "--threads", 1,
                  "--json", "-q", "-o", tmp_path / "diagnosis").json()
    result = ridefit.diagnose(slip_baseline, record, effects=["tyre_lift_off"], segment_s=2,
                              threads=1, tolerances={"sprung_mass_kg": 0.05})
    assert_same_numbers(result, cli, rtol=1e-6, skip=RUN_KEYS)
    assert [v["name"] for v in result["sheet_values"]] == ["sprung_mass_kg"]
    with pytest.raises(ridefit.InputError, match="tolerances: 'sometimes'"):
        ridefit.diagnose(slip_baseline, record, tolerances="sometimes")
    with pytest.raises(ridefit.InputError, match="'spring_rate' is not a quarter-car parameter"):
        ridefit.diagnose(slip_baseline, record, tolerances={"spring_rate": 0.1})


def test_optimise_equals_the_cli(tmp_path):
    study = dataset("studies/seed001_damper_tuning_linear.yaml")
    cli = run_cli("optimise", study, "--json", "-q", "--journal", tmp_path / "j.journal").json()
    lines = []
    result = ridefit.optimise(study, progress=lines.append)
    assert_same_numbers(result, cli, rtol=1e-9, skip=RUN_KEYS)
    assert lines
    written = tmp_path / "result.yaml"
    ridefit.optimise(study, output=written, journal=tmp_path / "p.journal")
    assert written.exists()
    with pytest.raises(ridefit.InputError):
        ridefit.optimise(dataset("vehicles/passat_b8_front.yaml"))


@pytest.mark.filterwarnings("ignore::pytest.PytestUnraisableExceptionWarning")
def test_a_failing_progress_callback_does_not_end_the_run():
    def fail(line):
        raise KeyError(line)

    study = dataset("studies/seed001_damper_tuning_linear.yaml")
    assert ridefit.optimise(study, progress=fail)["status"] == ridefit.optimise(study)["status"]
