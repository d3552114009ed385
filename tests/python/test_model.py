"""Models from YAML files and dicts, and `modes`, against `ridefit modes --json`."""

import pytest
import ridefit
from conftest import assert_same_numbers, dataset, read_flat_yaml, run_cli, write_flat_yaml


def test_modes_equal_the_cli(passat):
    cli = run_cli("modes", passat, "--json").json()
    python = ridefit.modes(ridefit.load_model(passat))
    assert_same_numbers(python, cli)
    assert set(python["states"]) == {"slip", "stick"}


def test_modes_of_one_state_with_an_override_equal_the_cli(passat):
    cli = run_cli("modes", passat, "--state", "stick", "--set",
                  "top_mount_stiffness_N_per_m=707e3", "--json").json()
    model = ridefit.load_model(passat, overrides={"top_mount_stiffness_N_per_m": 707e3})
    assert_same_numbers(ridefit.modes(model, state="stick"), cli)


def test_a_dict_model_gives_the_same_modes_as_its_file(passat):
    mapping = read_flat_yaml(passat)
    from_dict = ridefit.model_from_dict(mapping, name=passat)
    assert from_dict.kind == "quarter_car"
    assert ridefit.modes(from_dict) == ridefit.modes(ridefit.load_model(passat))


def _refused_like_the_cli(tmp_path, change):
    mapping = read_flat_yaml(dataset("vehicles/passat_b8_front.yaml"))
    change(mapping)
    path = tmp_path / "bad.yaml"
    write_flat_yaml(path, mapping)
    message = run_cli("modes", path, expect=2).error_message()
    with pytest.raises(ridefit.InputError) as from_file:
        ridefit.load_model(path)
    with pytest.raises(ridefit.InputError) as from_dict:
        ridefit.model_from_dict(mapping, name=str(path))
    assert str(from_file.value) == message
    assert str(from_dict.value) == message
    return message


def test_an_unknown_key_is_refused_with_the_cli_message(tmp_path):
    message = _refused_like_the_cli(tmp_path, lambda m: m.update(sprung_mas_kg=400.0))
    assert "sprung_mas_kg" in message


def test_a_negative_mass_is_refused_with_the_cli_message(tmp_path):
    message = _refused_like_the_cli(tmp_path, lambda m: m.update(sprung_mass_kg=-385.4))
    assert "sprung_mass_kg" in message


def test_input_error_is_a_value_error_and_names_the_dict():
    assert issubclass(ridefit.InputError, ValueError)
    assert issubclass(ridefit.RunError, RuntimeError)
    with pytest.raises(ValueError, match="<dict>"):
        ridefit.model_from_dict({"model": "quarter_car", "sprung_mass_kg": 1.0})


def test_a_half_car_loads_and_its_modes_equal_the_cli():
    path = dataset("vehicles/ajayi_half_car.yaml")
    car = ridefit.load_model(path)
    assert car.kind == "half_car"
    cli = run_cli("modes", path, "--json").json()
    python = ridefit.modes(car)
    assert_same_numbers(python, cli)
    assert list(python["states"]) == ["passive"]
    assert len(python["states"]["passive"]["modes"]) == 7
    with pytest.raises(ridefit.InputError, match="passive axles only"):
        ridefit.modes(car, state="stick")


def test_docstrings_show_in_help():
    for function in (ridefit.simulate, ridefit.load_model, ridefit.welch_psd, ridefit.modes,
                     ridefit.fit_hysteresis, ridefit.fit_psd, ridefit.diagnose, ridefit.optimise,
                     ridefit.vibration_metrics, ridefit.apply_weighting):
        assert function.__doc__ and len(function.__doc__) > 80, function


def test_the_type_stubs_cover_the_extension():
    import ast
    import pathlib

    import ridefit._ridefit as extension

    stubs = pathlib.Path(ridefit.__file__).with_name("_ridefit.pyi")
    tree = ast.parse(stubs.read_text())
    stubbed = {node.name for node in tree.body
               if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    public = {name for name in dir(extension) if not name.startswith("__")}
    assert public - stubbed == set()
    assert stubs.with_name("py.typed").exists()


def test_parameters_are_the_file_values_with_the_overrides(passat):
    model = ridefit.load_model(passat, overrides={"coulomb_force_N": 30}, damper_state="slip")
    assert model.damper_state == "slip"
    expected = read_flat_yaml(passat)
    for key in ("model", "damper_state"):
        del expected[key]
    expected["coulomb_force_N"] = 30
    for key, value in expected.items():
        assert model.parameters[key] == float(value), key


def test_an_unknown_state_is_refused(passat):
    with pytest.raises(ridefit.InputError, match="state: 'both'"):
        ridefit.modes(passat, state="both")
