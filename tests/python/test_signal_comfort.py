"""welch_psd and the ISO 2631-1 functions against `ridefit analyse --psd --json` on a recording
made by `ridefit simulate`."""

import numpy as np
import pytest

import ridefit
from conftest import assert_same_numbers, dataset, read_csv, run_cli

RATE_HZ = 1000.0


@pytest.fixture(scope="module")
def recording(tmp_path_factory):
    out = tmp_path_factory.mktemp("analyse") / "record.csv"
    run_cli("simulate", dataset("vehicles/passat_b8_front.yaml"),
            dataset("excitations/iso8608_class_a_50kmh.yaml"), "--duration", 12, "-o", out)
    return out


def analyse(recording, tmp_path, *flags):
    psd_file = tmp_path / "psd.csv"
    result = run_cli("analyse", recording, "--channel", "body_acc", "--psd", psd_file, "--json",
                     *flags).json()
    return result, read_csv(psd_file)


@pytest.mark.parametrize("flags,kwargs", [
    (("--segment", "4"), dict(segment_s=4.0)),
    (("--segment", "2", "--overlap", "0.75", "--detrend", "linear", "--smooth", "3",
      "--confidence", "0.95"),
     dict(segment_s=2.0, overlap=0.75, detrend="linear", smooth_bins=3, confidence=0.95)),
])
def test_welch_psd_equals_the_cli(recording, tmp_path, flags, kwargs):
    _, cli = analyse(recording, tmp_path, *flags)
    body_acc = read_csv(recording)["body_acc"]
    psd = ridefit.welch_psd(body_acc, RATE_HZ, **kwargs)
    for key, column in (("frequency_Hz", "frequency"), ("psd", "body_acc_psd"),
                        ("lower", "body_acc_psd_lower"), ("upper", "body_acc_psd_upper")):
        assert psd[key].dtype == np.float64
        np.testing.assert_allclose(psd[key], cli[column], rtol=1e-6,
                                   atol=1e-9 * np.max(cli[column]), err_msg=key)
    assert psd["confidence"] == kwargs.get("confidence", 0.9)
    assert np.all(psd["lower"] <= psd["psd"]) and np.all(psd["psd"] <= psd["upper"])


def test_welch_psd_refuses_a_segment_longer_than_the_signal():
    with pytest.raises(ridefit.InputError, match="segment"):
        ridefit.welch_psd(np.zeros(100), 100.0, segment_s=10.0)
    with pytest.raises(ridefit.InputError, match="one-dimensional"):
        ridefit.welch_psd(np.zeros((10, 10)), 100.0)


def test_weighted_metrics_equal_the_cli(recording, tmp_path):
    result, _ = analyse(recording, tmp_path, "--segment", "4")
    channel = next(c for c in result["recordings"][0]["channels"] if c["channel"] == "body_acc")
    assert channel["weighting"] == "Wk"
    body_acc = read_csv(recording)["body_acc"]
    centred = body_acc - sum(v / len(body_acc) for v in body_acc)  # as the library centres it
    weighted = ridefit.apply_weighting("Wk", centred, RATE_HZ)
    metrics = ridefit.vibration_metrics(weighted, RATE_HZ)
    # The CSV holds the simulation to its printed digits: the metrics agree to about that.
    for key, cli_key in (("weighted_rms_m_per_s2", "weighted_rms"), ("mtvv_m_per_s2", "mtvv"),
                         ("vdv_m_per_s1_75", "vdv"), ("crest_factor", "crest_factor")):
        assert metrics[key] == pytest.approx(channel[cli_key], rel=1e-7), key
    running = ridefit.running_rms(weighted, RATE_HZ)
    assert np.max(running) == pytest.approx(metrics["mtvv_m_per_s2"], rel=1e-12)


def test_weighting_magnitudes_match_iso_2631_table_3():
    # Table 3, Wk ×1000: 482 at 1 Hz, 531 at 2 Hz, 631 at 2.5 Hz.
    magnitude = ridefit.weighting_magnitude("Wk", np.array([1.0, 2.0, 2.5]))
    np.testing.assert_allclose(np.round(1000 * magnitude), [482, 531, 631])
    assert ridefit.minimum_sample_rate_Hz("Wk") == pytest.approx(500.0)
    with pytest.raises(ridefit.InputError, match="Wk"):
        ridefit.weighting_magnitude("Wz", np.array([1.0]))
    with pytest.raises(ridefit.InputError):
        ridefit.apply_weighting("Wk", np.ones(1000), 100.0)


def test_any_float_sequence_is_accepted_and_gives_the_same_spectrum():
    rng = np.random.default_rng(7)
    signal = rng.standard_normal(4000)
    reference = ridefit.welch_psd(signal, 100.0, segment_s=4.0)["psd"]
    strided = np.repeat(signal, 2)[::2]  # a non-contiguous view
    assert not strided.flags["C_CONTIGUOUS"]
    for same in (strided, list(signal)):
        np.testing.assert_array_equal(ridefit.welch_psd(same, 100.0, segment_s=4.0)["psd"],
                                      reference)
    counts = np.round(1000 * signal).astype(np.int64)  # converted to float64 on the way in
    np.testing.assert_array_equal(ridefit.welch_psd(counts, 100.0, segment_s=4.0)["psd"],
                                  ridefit.welch_psd(counts.astype(np.float64), 100.0,
                                                    segment_s=4.0)["psd"])


def test_analyse_with_levels_equals_the_cli(tmp_path):
    passat = dataset("vehicles/passat_b8_front.yaml")
    files = []
    for force in (30, 60, 90):
        out = tmp_path / f"fc{force}.csv"
        run_cli("simulate", passat, dataset("excitations/iso8608_class_a_50kmh.yaml"),
                "--duration", 6, "--set", f"coulomb_force_N={force}", "-o", out)
        files.append(out)
    cli = run_cli("analyse", *files, "--segment", 2, "--model", passat, "--rattle-space",
                  "0.08,0.09", "--levels", "30,60,90", "--level-name", "coulomb_force_N",
                  "--json").json()
    result = ridefit.analyse(files, segment_s=2, model=passat, rattle_space_m=(0.08, 0.09),
                             levels=[30, 60, 90], level_name="coulomb_force_N")
    assert_same_numbers(result, cli, rtol=1e-9)
    body = result["spectra"]["body_acc"]
    assert body["psd"].dtype == np.float64 and body["psd"].shape == body["frequency_Hz"].shape
    # A recording as arrays: the metrics of its CSV.
    from_arrays = ridefit.analyse(read_csv(files[0]), segment_s=2)
    alone = ridefit.analyse(files[0], segment_s=2)
    for a, b in zip(from_arrays["recordings"][0]["channels"], alone["recordings"][0]["channels"]):
        assert a["rms"] == pytest.approx(b["rms"], rel=1e-12), a["channel"]
