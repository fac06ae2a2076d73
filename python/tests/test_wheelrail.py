"""Wheel–rail scenes from Python (docs/python.md): the CLI's result folder bit for bit, CONTACT's
printed results of the Manchester benchmark's first case, and each entry point refusing the other
kind of scene with the one that takes it."""

import numpy as np
import pytest

import creepbench
from conftest import ROOT, run_cli

MANCHESTER = ROOT / "scenes" / "wheelrail" / "mbench_a22_left.toml"


def test_simulate_wheelrail_equals_the_cli(tmp_path):
    cli = run_cli("simulate", MANCHESTER, "--solver", "contact", "--solver", "fastsim", "--out", tmp_path)
    assert cli.returncode == 0, cli.stderr
    sim = creepbench.simulate_wheelrail(MANCHESTER, ["contact", "fastsim"])
    assert sim.solvers == ["contact", "fastsim"]
    folder = tmp_path / sim.name
    files = sim.files()
    assert sorted(files) == sorted(p.name for p in folder.iterdir() if not p.name.startswith("."))
    for name, text in files.items():
        assert (folder / name).read_text() == text, name
    for model in sim.solvers:
        for df, name in ((sim.totals[model], f"{model}.csv"), (sim.patches[model], f"{model}_patches.csv")):
            header, *rows = [line.split(",") for line in (folder / name).read_text().splitlines()]
            assert df.columns == header
            for k, c in enumerate(header):
                theirs = np.array([float(r[k]) for r in rows])
                assert np.array_equal(df[c].cast(float).to_numpy(), theirs), (name, c)
    saved = sim.save(tmp_path / "again")
    for name, text in files.items():
        assert (tmp_path / "again" / sim.name / name).read_text() == text, name
    assert saved.endswith(sim.name)


def test_the_manchester_benchmarks_first_case_is_contacts_printed_one():
    sim = creepbench.simulate_wheelrail(MANCHESTER, ["contact"])
    totals, patches = sim.totals["contact"], sim.patches["contact"]
    assert totals.height == 21 and list(totals["contact_case"]) == list(range(1, 22))
    first = totals.row(0, named=True)
    patch = patches.filter(patches["contact_case"] == 1).row(0, named=True)
    # examples/mbench_a22_left.ref_out, case 1, each within one unit of its printed digit (the
    # gate's rule "CONTACT wheel-rail": 2 half-units; FS is 1.002 half-units off, the rest < 1).
    printed = [
        (first["fy_tr_n"], -36.24, 0.01),
        (first["fz_tr_n"], 10000.0, 1.0),
        (patch["fn_n"], 9997.0, 1.0),
        (patch["fs_n"], 253.6, 0.1),
        (patch["mn_nmm"], 4605.0, 1.0),
        (patch["ycp_r_mm"], 8.6600, 1e-4),
        (patch["cksi"], -5.665e-05, 1e-8),
    ]
    for ours, theirs, unit in printed:
        assert abs(ours - theirs) <= unit, (ours, theirs)
    assert (patch["npot"], patch["ncon"]) == (3999, 1291)


def test_each_entry_point_names_the_one_that_takes_the_other_kind_of_scene():
    with pytest.raises(creepbench.SceneError, match="simulate_wheelrail"):
        creepbench.simulate(MANCHESTER)
    with pytest.raises(creepbench.SceneError, match=r"\[wheelrail\]"):
        creepbench.simulate_wheelrail(ROOT / "scenes" / "thesis" / "step_cx001.toml")
    with pytest.raises(creepbench.SceneError, match="solvers"):
        creepbench.simulate_wheelrail(MANCHESTER, ["nope"])
