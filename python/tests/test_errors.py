"""Invalid input raises SceneError carrying field, value and allowed, with the CLI's text."""

import numpy as np
import pytest

import creepbench
from conftest import CONTACT, GRID, ROOT, run_cli

SCENE = {
    "name": "bad",
    "solvers": ["uba"],
    "contact": dict(CONTACT),
    "material": {"g_mpa": 82000.0, "poisson": 0.28},
    "grid": dict(GRID),
    "rolling": {"v_mm_s": 1000.0, "courant": 1.0},
    "creepage": {"kind": "step", "c": 0.001, "steps": 4},
}


def test_a_bad_file_names_file_field_value_and_allowed_as_the_cli_does(tmp_path):
    scene = tmp_path / "bad.toml"
    text = (ROOT / "scenes" / "thesis" / "step_cx001.toml").read_text().replace("mu = 0.4", "mu = -0.4")
    scene.write_text(text)
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.simulate(scene)
    assert e.value.field == f"{scene}: contact.mu"
    assert e.value.value == "-0.4"
    assert e.value.allowed
    cli = run_cli("simulate", scene, "--out", tmp_path / "out")
    assert cli.returncode == 2
    assert str(e.value) in cli.stderr
    assert isinstance(e.value, ValueError)


@pytest.mark.parametrize(
    "change, field, value",
    [
        (("contact", "fn_n", -1.0), "contact.fn_n", "-1"),
        (("grid", "mx", 0), "grid.mx", "0"),
        ((None, "solvers", ["uba", "nope"]), "solvers[1]", '"nope"'),
    ],
)
def test_a_bad_dict_names_the_field(change, field, value):
    scene = {k: (dict(v) if isinstance(v, dict) else v) for k, v in SCENE.items()}
    section, key, v = change
    (scene[section] if section else scene)[key] = v
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.simulate(scene)
    assert (e.value.field, e.value.value) == (field, value)
    assert str(e.value) == f"invalid input: `{field}` = {value}: allowed: {e.value.allowed}"


def test_bad_toml_text_names_line_and_column():
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.simulate("name = \n")
    assert "line 1" in str(e.value) or "1:" in str(e.value)


def test_a_value_toml_cannot_hold_is_refused():
    scene = dict(SCENE, name=object())
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.simulate(scene)
    assert e.value.field == "name"


def test_steady_refuses_bad_arrays_and_models():
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.steady("fastsim", np.zeros((4, 2)), contact=CONTACT, grid=GRID)
    assert e.value.field == "creepages"
    bad = np.zeros((4, 3))
    bad[2, 1] = np.nan
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.steady("fastsim", bad, contact=CONTACT, grid=GRID)
    assert e.value.field == "creepages[2, 1]"
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.steady("nope", np.zeros((1, 3)), contact=CONTACT, grid=GRID)
    assert e.value.field == "model" and "fastsim" in e.value.allowed
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.steady("fastsim", np.zeros((1, 3)), contact=dict(CONTACT, mu=-1.0), grid=GRID)
    assert e.value.field == "contact.mu"


def test_stepper_refuses_a_bad_load():
    s = creepbench.Stepper("uba", contact=CONTACT, grid=GRID)
    with pytest.raises(creepbench.SceneError) as e:
        s.step(0.001, 0.0, 0.0, -5.0, 0.4)
    assert e.value.field == "fn_n"
    assert s.steps == 0


def test_only_a_scene_solver_can_be_chosen():
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.simulate(SCENE, ["fastsim"])
    assert e.value.field == "--solver"
