"""The package as a Python user reads it (issue 47 item 8): one exception hierarchy, simulate
for a scene and simulate_study for a study, a string is TOML only when it is not an existing
path, and no default that depends on the current folder."""

import inspect
import os

import pytest

import creepbench
from conftest import ROOT

STUDY = ROOT / "scenes" / "thesis" / "study_sine_freq.toml"
SCENE = ROOT / "scenes" / "thesis" / "step_cx001.toml"


def test_every_error_is_a_creepbench_error():
    assert issubclass(creepbench.SceneError, creepbench.CreepbenchError)
    assert issubclass(creepbench.SceneError, ValueError)
    assert issubclass(creepbench.RunError, creepbench.CreepbenchError)
    assert issubclass(creepbench.RunError, RuntimeError)
    with pytest.raises(creepbench.CreepbenchError):
        creepbench.simulate(ROOT / "scenes" / "no_such_scene.toml")
    with pytest.raises(creepbench.CreepbenchError) as e:
        creepbench.simulate(42)
    assert isinstance(e.value, creepbench.SceneError) and e.value.field == "scene" and e.value.value == "int"


def test_simulate_gives_one_result_and_simulate_study_a_list():
    sim = creepbench.simulate(SCENE, ["fastsim"])
    assert isinstance(sim, creepbench.Simulation)
    sims = creepbench.simulate_study(STUDY, ["fastsim"])
    assert isinstance(sims, list) and len(sims) > 1
    assert all(isinstance(s, creepbench.Simulation) for s in sims)
    assert len({s.name for s in sims}) == len(sims)


def test_a_study_goes_to_simulate_study_and_a_scene_to_simulate():
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.simulate(STUDY)
    assert e.value.field == "scene" and "simulate_study" in e.value.allowed
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.simulate_study(SCENE)
    assert e.value.field == "scene" and "simulate()" in e.value.allowed


def test_a_string_is_toml_only_when_it_is_not_an_existing_path(tmp_path, monkeypatch):
    text = SCENE.read_text()
    # A file whose name holds "=" is still a path.
    odd = tmp_path / "a=b.toml"
    odd.write_text(text)
    monkeypatch.chdir(tmp_path)
    by_path = creepbench.simulate("a=b.toml", ["fastsim"])
    by_text = creepbench.simulate(text, ["fastsim"])
    assert by_path.files()["fastsim.csv"] == by_text.files()["fastsim.csv"]
    # A missing path is named as a path, not parsed as TOML.
    with pytest.raises(creepbench.CreepbenchError) as e:
        creepbench.simulate("missing.toml")
    assert "missing.toml" in str(e.value) and "malformed TOML" not in str(e.value)


@pytest.mark.parametrize("function", [creepbench.check, creepbench.run, creepbench.Simulation.check])
def test_no_default_depends_on_the_current_folder(function):
    for name, p in inspect.signature(function).parameters.items():
        if isinstance(p.default, (str, os.PathLike)):
            pytest.fail(f"{function.__qualname__}({name}={p.default!r}): a path relative to the current folder")


def test_check_wants_exactly_one_baseline(tmp_path):
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.check("scenes/thesis", reference="reference")
    assert e.value.field == "golden, against"
    with pytest.raises(creepbench.SceneError):
        creepbench.check("scenes/thesis", reference="reference", golden="golden", against=tmp_path)
