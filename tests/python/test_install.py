"""`cmake --install build --component python` gives a package that imports on its own."""

import os
import subprocess
import sys

import pytest


@pytest.mark.skipif("RIDEFIT_BINARY_DIR" not in os.environ, reason="needs the build tree (ctest)")
def test_the_installed_package_imports_and_runs(tmp_path):
    cmake = os.environ.get("CMAKE_COMMAND", "cmake")
    subprocess.run([cmake, "--install", os.environ["RIDEFIT_BINARY_DIR"], "--component",
                    "python", "--prefix", str(tmp_path)], check=True, capture_output=True)
    site = tmp_path / "lib" / "python3" / "dist-packages"
    for name in ("__init__.py", "_ridefit.pyi", "py.typed"):
        assert (site / "ridefit" / name).exists(), name
    environment = dict(os.environ, PYTHONPATH=str(site))
    code = ("import ridefit, numpy; "
            "p = ridefit.welch_psd(numpy.sin(numpy.arange(4096) * 0.3), 100.0); "
            "print(ridefit.__file__, float(p['frequency_Hz'][numpy.argmax(p['psd'])]))")
    out = subprocess.run([sys.executable, "-c", code], env=environment, check=True,
                         capture_output=True, text=True, cwd=tmp_path).stdout
    location, peak_Hz = out.split()
    assert location.startswith(str(site))
    assert abs(float(peak_Hz) - 100.0 * 0.3 / (2 * 3.141592653589793)) < 0.2
