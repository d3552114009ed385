"""Shared helpers of the Python module's tests: the `ridefit` CLI to compare with, the datasets.

ctest sets RIDEFIT_CLI (the command), RIDEFIT_SOURCE_DIR and PYTHONPATH (build/python)."""

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

SOURCE_DIR = Path(os.environ.get("RIDEFIT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
CLI = os.environ.get("RIDEFIT_CLI", str(SOURCE_DIR / "build" / "tools" / "ridefit"))


def dataset(relative: str) -> str:
    return str(SOURCE_DIR / "datasets" / relative)


class CliRun:
    def __init__(self, completed: subprocess.CompletedProcess):
        self.exit_code = completed.returncode
        self.stdout = completed.stdout
        self.stderr = completed.stderr

    def json(self):
        return json.loads(self.stdout[self.stdout.index("{"):])

    def error_message(self) -> str:
        """The message of `ridefit: error: MESSAGE` (or `run failed:`) on stderr."""
        for prefix in ("ridefit: error: ", "ridefit: run failed: "):
            if prefix in self.stderr:
                return self.stderr.split(prefix, 1)[1].rstrip("\n")
        raise AssertionError(f"no error message on stderr: {self.stderr!r}")


def run_cli(*args, expect=0) -> CliRun:
    completed = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True,
                               check=False)
    run = CliRun(completed)
    if expect is not None:
        assert run.exit_code == expect, f"{args}: exit {run.exit_code}\n{run.stderr}"
    return run


def read_csv(path):
    """A ridefit CSV (`name[unit]` headers) as {name: float64 array}."""
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {h.split("[")[0]: data[:, i] for i, h in enumerate(header)}


def write_two_tests(source, path):
    """The CSV `source` (time, displacement in mm, force) as two tests in one file, its halves
    numbered by a segment column, written to `path`."""
    columns = read_csv(source)
    n = len(columns["time"])
    with open(path, "w") as f:
        f.write("time[s],displacement[mm],force[N],segment[1]\n")
        for k in range(n):
            f.write(f"{float(columns['time'][k])!r},{float(columns['displacement'][k])!r},"
                    f"{float(columns['force'][k])!r},{1 if k < n // 2 else 2}\n")
    return path


def assert_same_numbers(python_value, cli_value, path="", rtol=1e-9, skip=()):
    """Every number of the CLI's JSON equals Python's (dicts recursively, lists element-wise);
    keys in `skip` (e.g. wall times, file names) are left out."""
    if isinstance(cli_value, dict):
        assert isinstance(python_value, dict), path
        for key, value in cli_value.items():
            if key in skip:
                continue
            assert key in python_value, f"{path}.{key} missing in Python's result"
            assert_same_numbers(python_value[key], value, f"{path}.{key}", rtol, skip)
    elif isinstance(cli_value, list):
        assert len(python_value) == len(cli_value), path
        for i, (p, c) in enumerate(zip(python_value, cli_value)):
            assert_same_numbers(p, c, f"{path}[{i}]", rtol, skip)
    elif isinstance(cli_value, bool) or isinstance(cli_value, str) or cli_value is None:
        if cli_value is None and isinstance(python_value, float):
            assert np.isnan(python_value), path  # JSON writes NaN as null
        else:
            assert python_value == cli_value, path
    else:
        assert python_value == pytest.approx(cli_value, rel=rtol, abs=1e-300), path


@pytest.fixture
def passat():
    return dataset("vehicles/passat_b8_front.yaml")


def _scalar(text: str):
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def read_flat_yaml(path) -> dict:
    """A flat `key: value` YAML file (the shipped quarter-car and excitation files) as a dict,
    without PyYAML (not a dependency of the suite)."""
    mapping = {}
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                key, value = line.split(":", 1)
                mapping[key.strip()] = _scalar(value.strip())
    return mapping


def write_flat_yaml(path, mapping: dict):
    path.write_text("".join(f"{k}: {v!r}\n" if not isinstance(v, str) else f"{k}: {v}\n"
                            for k, v in mapping.items()))
