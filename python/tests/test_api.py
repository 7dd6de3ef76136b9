"""The package as a Python user meets it: names, units, errors, progress, Ctrl-C, the GIL."""

import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import aes_sim


def test_presets_params_and_signals_are_the_registry_s():
    p = aes_sim.presets()
    assert "startup" in p and "Start-up" in p["startup"]
    assert aes_sim.preset("startup")["name"] == "startup"
    duration = next(d for d in aes_sim.params() if d["path"] == "sim.duration_s")
    assert duration["unit"] == "s" and duration["min"] == 0
    names = [s["name"] for s in aes_sim.signals()]
    assert names[0] == "t_s" and "ship_speed_kn" in names and "bus_voltage_v" in names
    assert "monte-carlo" in aes_sim.KINDS


def test_the_trace_has_a_column_per_signal_with_its_unit():
    r = aes_sim.run(aes_sim.Scenario.from_preset("startup").set("sim.duration_s", 10))
    meta = aes_sim.signals()
    assert list(r.trace) == [s["name"] for s in meta]
    assert r.trace.units["ship_speed_kn"] == "kn" and r.units["bus_voltage_v"] == "V"
    t = r.trace["t_s"]
    assert t.dtype == np.float64 and t[0] == 0.0 and t[-1] == pytest.approx(10.0, abs=1e-9)
    assert all(len(c) == len(t) for c in r.trace.values())
    assert r.summary["final_time_s"] == t[-1]
    # The arrays are the caller's: writable, and a copy of nothing the next run shares.
    r.trace["t_s"][0] = -1.0


def test_to_pandas_when_pandas_is_installed():
    pd = pytest.importorskip("pandas")
    r = aes_sim.run(aes_sim.Scenario.from_preset("startup").set("sim.duration_s", 5))
    df = r.to_pandas()
    assert isinstance(df, pd.DataFrame) and list(df.columns) == list(r.trace)
    assert df.attrs["units"]["ship_speed_kn"] == "kn"
    assert np.array_equal(df["ship_speed_kn"].to_numpy(), r.trace["ship_speed_kn"])


def test_bad_input_raises_errors_that_name_the_field():
    with pytest.raises(aes_sim.AesSimError, match="sim.duration_s"):
        aes_sim.Scenario({"sim": {"duration_s": "long"}})
    with pytest.raises(aes_sim.AesSimError, match="trials"):
        aes_sim.monte_carlo("preset:mc-wigley", trials=0)
    with pytest.raises(aes_sim.AesSimError, match="need a < b"):
        aes_sim.study("monte-carlo", aes_sim.Scenario.from_preset("mc-wigley"), range=(3, 1))
    with pytest.raises(aes_sim.AesSimError, match="kind 'nonesuch': one of monte-carlo"):
        aes_sim.study("nonesuch", {})
    with pytest.raises(aes_sim.AesSimError, match="no shards given"):
        aes_sim.merge([])
    with pytest.raises(TypeError):
        aes_sim.run(42)
    # Several settings at once are checked together, named as several --set flags are.
    with pytest.raises(aes_sim.AesSimError, match=r"^--set sim.duration_s, stepping.dt_s: stepping.dt_s = -1"):
        aes_sim.Scenario.from_preset("startup").update({"sim.duration_s": 5, "stepping.dt_s": -1})


def small_mc():
    return aes_sim.Scenario.from_preset("mc-wigley").update({"sim.duration_s": 10, "monte_carlo.trials": 4})


def test_progress_is_reported_and_ends_at_the_total():
    calls = []
    aes_sim.monte_carlo(small_mc(), threads=1, progress=lambda done, total: calls.append((done, total)))
    assert calls and calls[-1] == (4, 4)
    assert all(0 <= d <= t == 4 for d, t in calls)
    assert [d for d, _ in calls] == sorted(d for d, _ in calls)


def test_an_exception_in_the_progress_callback_stops_the_study():
    def stop(done, total):
        raise RuntimeError("enough")

    t0 = time.monotonic()
    with pytest.raises(RuntimeError, match="enough"):
        aes_sim.monte_carlo(small_mc().set("monte_carlo.trials", 200), threads=1, progress=stop)
    # 200 trials take about 20 s; stopped at the first report (about 0.1 s) after the trial in hand.
    assert time.monotonic() - t0 < 5.0


def test_the_gil_is_released_while_rust_runs():
    sc = aes_sim.Scenario.from_preset("startup").set("sim.duration_s", 400)
    box = {}
    worker = threading.Thread(target=lambda: box.setdefault("r", aes_sim.run(sc)))
    t0 = time.monotonic()
    worker.start()
    ticks = 0
    while worker.is_alive():
        ticks += 1
        time.sleep(0.002)
    elapsed = time.monotonic() - t0
    # Holding the GIL, the run would let this loop turn once or twice in all.
    assert elapsed > 0.05 and ticks >= 10, (ticks, elapsed)
    assert box["r"].summary["final_time_s"] == pytest.approx(400.0, abs=1e-9)


def interrupted_after(script, wait_s):
    """Runs `script` in a new Python, sends it SIGINT `wait_s` after it prints its first line, and
    gives its exit status, what it printed after, and how long it took to stop [s]."""
    p = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True, cwd=os.sep)
    try:
        assert p.stdout.readline().strip() == "running"
        time.sleep(wait_s)
        t0 = time.monotonic()
        p.send_signal(signal.SIGINT)
        code = p.wait(timeout=10)
        return code, p.stdout.read(), time.monotonic() - t0
    finally:
        p.kill()


def catching(setup, call):
    """A script: `setup`, then `call` with KeyboardInterrupt caught (it prints 'interrupted' and
    exits with status 3)."""
    return f"import sys, aes_sim\n{setup}\ntry:\n    {call}\nexcept KeyboardInterrupt:\n    print('interrupted', flush=True)\n    sys.exit(3)\n"


def test_ctrl_c_stops_a_long_study_cleanly():
    setup = (
        "sc = aes_sim.Scenario.from_preset('mc-wigley').update({'sim.duration_s': 10, 'monte_carlo.trials': 400})\n"
        "def tell(done, total):\n"
        "    print('running', flush=True)"
    )
    code, out, stopped_s = interrupted_after(catching(setup, "aes_sim.monte_carlo(sc, threads=1, progress=tell)"), 0.0)
    assert code == 3 and "interrupted" in out
    # 400 trials take about 40 s on a thread: it stopped after the trial in hand.
    assert stopped_s < 5.0


def test_ctrl_c_stops_a_long_run_cleanly():
    setup = (
        "sc = aes_sim.Scenario.from_preset('startup').update({'sim.duration_s': 50000, 'sim.record_interval_s': 1})\n"
        "print('running', flush=True)"
    )
    code, out, stopped_s = interrupted_after(catching(setup, "aes_sim.run(sc)"), 0.5)
    assert code == 3 and "interrupted" in out
    # The run takes about 45 s: it stopped within a chunk of steps.
    assert stopped_s < 3.0
