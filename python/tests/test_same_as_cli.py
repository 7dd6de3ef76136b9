"""The numbers from Python equal the command line's, bit for bit (issue 58's done-when lines).

Equality is exact (``==`` on floats, ``np.array_equal`` on columns): the command line prints the
shortest text that reads back to the same double (JSON and its trace CSV alike), so any
difference in the last bit would show."""

import json
import math

import numpy as np
import pytest

import aes_sim

# A small Monte Carlo: 4 trials of 10 s on the Wigley hull in sea state 5 (about 0.4 s).
MC_PRESET = "mc-wigley"
MC_SETS = {"sim.duration_s": 10}
MC_TRIALS, MC_SEED = 4, 7


def read_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
        rows = [[float(x) for x in line.split(",")] for line in f]
    cols = np.array(rows).T
    return {name: cols[i] for i, name in enumerate(header)}


def test_startup_final_speed_equals_the_cli_to_the_bit(cli_json, tmp_path):
    csv = tmp_path / "startup.csv"
    summary = cli_json("run", "preset:startup", "--out", csv)
    cli_trace = read_csv(csv)
    r = aes_sim.run(aes_sim.preset("startup"))
    final = r.trace["ship_speed_kn"][-1]
    assert math.isfinite(final) and 24.0 < final < 26.0  # the preset orders 25 kn
    assert final.tobytes() == np.float64(cli_trace["ship_speed_kn"][-1]).tobytes()
    # The whole run: every column of the trace and the summary.
    assert list(r.trace) == list(cli_trace)
    for name, col in cli_trace.items():
        assert np.array_equal(r.trace[name], col), name
    assert r.summary == summary


@pytest.mark.parametrize("name", ["crash-stop", "quarter-turn-ss3"])
def test_other_presets_equal_the_cli(cli_json, name):
    # A shortened run: the reversing drive and a seaway (the RAO tables, the waves' seed).
    summary = cli_json("run", f"preset:{name}", "--set", "sim.duration_s=20")
    r = aes_sim.run(aes_sim.Scenario.from_preset(name).set("sim.duration_s", 20))
    assert r.summary == summary


def test_a_dict_a_file_and_a_preset_are_one_scenario(tmp_path):
    d = aes_sim.preset("startup")
    path = tmp_path / "s.json"
    path.write_text(json.dumps(d))
    a = aes_sim.Scenario(d)
    assert a == aes_sim.Scenario.from_file(path) == aes_sim.Scenario.from_preset("startup")
    assert aes_sim.run(str(path)).summary == aes_sim.run("preset:startup").summary


def test_monte_carlo_summary_equals_aes_sim_mc(cli_json):
    sets = [f"--set={p}={v}" for p, v in MC_SETS.items()]
    want = cli_json("mc", f"preset:{MC_PRESET}", "--trials", MC_TRIALS, "--seed", MC_SEED, "--quiet", *sets)
    sc = aes_sim.Scenario.from_preset(MC_PRESET).update(MC_SETS)
    got = aes_sim.monte_carlo(sc, trials=MC_TRIALS, seed=MC_SEED)
    assert got == want
    # The numbers do not depend on the threads.
    assert aes_sim.monte_carlo(sc, trials=MC_TRIALS, seed=MC_SEED, threads=1) == want


def test_shards_merge_to_the_whole_study_as_the_cli_does(cli, cli_json, tmp_path):
    sc = aes_sim.Scenario.from_preset(MC_PRESET).update(MC_SETS).update({"monte_carlo.trials": MC_TRIALS})
    path = tmp_path / "sc.json"
    path.write_text(sc.to_json())
    whole = aes_sim.study("monte-carlo", sc)
    assert whole == cli_json("mc", path, "--quiet")
    halves = [aes_sim.study("monte-carlo", sc, range=r) for r in [(2, 4), (0, 2)]]
    assert aes_sim.merge(halves) == whole
    # A shard file the command line wrote merges with one made in Python.
    shard = tmp_path / "first-half.json"
    code, _, err = cli("mc", path, "--trial-range", "0..2", "--partial", shard, "--quiet")
    assert code == 0, err
    assert json.loads(shard.read_text()) == halves[1]
    assert aes_sim.merge([shard, halves[0]]) == whole


def test_a_refused_parameter_raises_the_cli_message(cli):
    code, _, err = cli("run", "preset:startup", "--set", "sim.duration_s=-5")
    assert code == 1 and err.startswith("aes-sim: ")
    sc = aes_sim.Scenario.from_preset("startup")
    with pytest.raises(aes_sim.AesSimError) as e:
        sc.set("sim.duration_s", -5)
    assert str(e.value) == err.removeprefix("aes-sim: ").rstrip("\n")
    assert "sim.duration_s" in str(e.value)
    # Refused, the scenario is as it was.
    assert sc == aes_sim.Scenario.from_preset("startup")


def test_several_settings_refused_together_name_them_as_the_cli_does(cli):
    code, _, err = cli("run", "preset:startup", "--set", "sim.duration_s=1", "--set", "stepping.dt_s=0.003")
    assert code == 1 and err.startswith("aes-sim: --set sim.duration_s, stepping.dt_s: ")
    sc = aes_sim.Scenario.from_preset("startup")
    with pytest.raises(aes_sim.AesSimError) as e:
        sc.update({"sim.duration_s": 1, "stepping.dt_s": 0.003})
    assert str(e.value) == err.removeprefix("aes-sim: ").rstrip("\n")


def test_an_unknown_preset_raises_the_cli_message(cli):
    code, _, err = cli("preset", "nonesuch")
    assert code == 1
    with pytest.raises(aes_sim.AesSimError) as e:
        aes_sim.preset("nonesuch")
    assert str(e.value) == err.removeprefix("aes-sim: ").rstrip("\n")


def test_fuel_per_mile_equals_the_cli(cli_json):
    want = cli_json(
        "fuel-per-mile", "preset:head-seas-ss6", "--speeds", "20,25", "--seeds", 1, "--set", "sim.duration_s=20", "--quiet"
    )
    sc = aes_sim.Scenario.from_preset("head-seas-ss6").set("sim.duration_s", 20)
    assert aes_sim.fuel_per_mile(sc, speeds_kn=[20, 25], seeds=1) == want


def test_operability_equals_the_cli(cli_json):
    want = cli_json("operability", "--speeds", "10,20", "--headings", "180,90", "--sea-states", "4", "--quiet")
    got = aes_sim.operability(speeds_kn=[10, 20], headings_deg=[180, 90], sea_states=[4], threads=1)
    assert got == want


def test_storage_sizing_equals_the_cli(cli_json):
    want = cli_json(
        "storage-sizing", "preset:head-seas-ss6-storage", "--energy-mj", "50,100", "--power-mw", "10", "--duration-s", 20,
        "--json", "--quiet",
    )
    got = aes_sim.storage_sizing("preset:head-seas-ss6-storage", energies_mj=[50, 100], powers_mw=[10], duration_s=20)
    assert got == want


def test_maneuvers_and_schedule_equal_the_cli(cli_json):
    assert aes_sim.maneuvers(tracks=False) == cli_json("maneuvers", "--no-tracks")
    got = aes_sim.schedule()
    assert got == cli_json("schedule", "--json")["schedule"] and got["cells"]


def test_the_stability_map_equals_the_cli(cli_json):
    assert aes_sim.stability_map("preset:acceleration") == cli_json("stability-map", "preset:acceleration")
    x, y = ("plant.loads.ship_service_w", 1e6, 2e7, 3), ("plant.loads.filter_capacitance_f", 0.005, 0.04, 2)
    want = cli_json(
        "stability-map", "preset:acceleration", "--x", "plant.loads.ship_service_w=1e6:2e7:3",
        "--y", "plant.loads.filter_capacitance_f=0.005:0.04:2", "--quiet",
    )
    assert aes_sim.stability_map("preset:acceleration", x, y) == want
    with pytest.raises(aes_sim.AesSimError, match="give both x and y"):
        aes_sim.stability_map("preset:acceleration", x)
