"""The All Electric Ship simulator (aes-sim) from Python.

The same core as the ``aes-sim`` command and the browser page, through a thin native module
(``aes_sim._aes_sim``, Rust); this file only turns its JSON and bytes into dicts and numpy arrays.
Numbers equal the command line's to the bit: a scenario crosses as the same JSON text.

    import aes_sim
    r = aes_sim.run(aes_sim.preset("startup"))
    r.trace["ship_speed_kn"][-1], r.trace.units["ship_speed_kn"], r.summary["final_speed_kn"]

See docs/python.md ("From Python").
"""

from __future__ import annotations

import json
import os
from collections.abc import Callable, Iterable, Mapping
from typing import Any

import numpy as np

try:
    from . import _aes_sim
except ImportError as e:  # pragma: no cover - a set-up problem, said in words
    raise ImportError(
        f"aes_sim: its native module is missing next to {__file__}: this is the source folder "
        "(python/aes_sim: run from another folder), or the package is not built (./build.sh, or "
        "pip install ./python; docs/python.md)"
    ) from e
from ._aes_sim import KINDS, AesSimError

__all__ = [
    "AesSimError",
    "KINDS",
    "Result",
    "Scenario",
    "Trace",
    "fuel_per_mile",
    "maneuvers",
    "merge",
    "monte_carlo",
    "operability",
    "params",
    "preset",
    "presets",
    "run",
    "schedule",
    "signals",
    "stability_map",
    "storage_sizing",
    "study",
]

Progress = Callable[[int, int], Any]


def presets() -> dict[str, str]:
    """The preset scenarios' names with their descriptions (``aes-sim presets``)."""
    return dict(_aes_sim.presets())


def preset(name: str) -> dict:
    """A preset scenario as a dict (``aes-sim preset NAME``); ``AesSimError`` for an unknown name."""
    return json.loads(_aes_sim.preset_json(name))


def params() -> list[dict]:
    """Every scenario parameter's declaration (``aes-sim params --json``): path, kind, label, unit,
    default, min, max, choices, ..."""
    return json.loads(_aes_sim.params_json())


def signals() -> list[dict]:
    """Every trace signal in column order: name, unit, label, description (``aes-sim signals --json``)."""
    return json.loads(_aes_sim.signals_json())


def _value_text(value: Any) -> str:
    # A Python value as the JSON text `--set PATH=VALUE` would give (a str stays a string).
    return json.dumps(value)


class Scenario:
    """A checked scenario. ``Scenario(d)`` from a dict, ``Scenario.from_file(path)``,
    ``Scenario.from_preset(name)``; ``.set(path, value)`` changes one parameter, refused with the
    command line's message; ``.to_dict()`` / ``.to_json()`` give it back."""

    __slots__ = ("_json",)

    def __init__(self, scenario: Mapping | "Scenario" | None = None, *, _source: str = "scenario"):
        if scenario is None:
            scenario = {}
        if isinstance(scenario, Scenario):
            self._json = scenario._json
            return
        if not isinstance(scenario, Mapping):
            raise TypeError(f"Scenario: expected a dict or a Scenario, got {type(scenario).__name__}")
        self._json = _aes_sim.scenario_json(json.dumps(dict(scenario)), _source)

    @classmethod
    def from_json(cls, text: str, source: str = "scenario") -> "Scenario":
        """From JSON text (a scenario file's content); ``source`` names it in errors."""
        s = cls.__new__(cls)
        s._json = _aes_sim.scenario_json(text, source)
        return s

    @classmethod
    def from_file(cls, path: str | os.PathLike) -> "Scenario":
        """From a scenario JSON file, as ``aes-sim run FILE`` reads it."""
        with open(path, encoding="utf-8") as f:
            return cls.from_json(f.read(), os.fspath(path))

    @classmethod
    def from_preset(cls, name: str) -> "Scenario":
        """A preset scenario (``aes-sim presets`` lists them)."""
        return cls.from_json(_aes_sim.preset_json(name), f"preset:{name}")

    def set(self, path: str, value: Any) -> "Scenario":
        """Sets one parameter (``--set PATH=VALUE``: ``aes_sim.params()`` lists them) and returns
        the scenario; a refused value raises ``AesSimError`` with the command line's message and
        leaves the scenario as it was."""
        self._json = _aes_sim.scenario_set(self._json, [(path, _value_text(value))])
        return self

    def update(self, settings: Mapping[str, Any]) -> "Scenario":
        """Sets several parameters at once (checked together, as several ``--set`` flags are)."""
        self._json = _aes_sim.scenario_set(self._json, [(p, _value_text(v)) for p, v in settings.items()])
        return self

    def copy(self) -> "Scenario":
        return Scenario(self)

    def to_json(self) -> str:
        return self._json

    def to_dict(self) -> dict:
        return json.loads(self._json)

    def __getitem__(self, path: str) -> Any:
        """A parameter by its dotted path, e.g. ``sc["sim.duration_s"]``."""
        node: Any = self.to_dict()
        for key in path.split("."):
            node = node[int(key)] if isinstance(node, list) else node[key]
        return node

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Scenario) and self._json == other._json

    def __repr__(self) -> str:
        d = self.to_dict()
        return f"Scenario(name={d.get('name', '')!r})"


ScenarioLike = Scenario | Mapping | str


def _scenario(s: ScenarioLike) -> Scenario:
    # A Scenario, a dict, "preset:NAME" or a file name, as the command line's FILE argument.
    if isinstance(s, Scenario):
        return s
    if isinstance(s, Mapping):
        return Scenario(s)
    if isinstance(s, (str, os.PathLike)):
        text = os.fspath(s)
        if text.startswith("preset:"):
            return Scenario.from_preset(text[len("preset:"):])
        return Scenario.from_file(text)
    raise TypeError(f"expected a Scenario, a dict, 'preset:NAME' or a file name, got {type(s).__name__}")


class Trace(dict):
    """A run's trace: one numpy array (float64) per signal name, in column order, with
    ``.units`` and ``.labels`` by name (from the signal table, ``aes_sim.signals()``)."""

    units: dict[str, str]
    labels: dict[str, str]


class Result:
    """A finished run: ``.summary`` (the dict ``aes-sim run`` prints), ``.trace`` (a :class:`Trace`),
    ``.scenario`` (what ran), ``.to_pandas()``."""

    def __init__(self, scenario: Scenario, summary: dict, trace: Trace):
        self.scenario = scenario
        self.summary = summary
        self.trace = trace

    @property
    def units(self) -> dict[str, str]:
        return self.trace.units

    def to_pandas(self):
        """The trace as a pandas DataFrame (columns by signal name, units in ``df.attrs["units"]``);
        needs pandas, which this package does not require."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the machine
            raise ImportError("Result.to_pandas() needs pandas: pip install pandas") from e
        df = pd.DataFrame(dict(self.trace))
        df.attrs["units"] = dict(self.trace.units)
        return df

    def __repr__(self) -> str:
        rows = len(next(iter(self.trace.values()))) if self.trace else 0
        return f"Result({self.scenario!r}, {rows} rows)"


def run(scenario: ScenarioLike) -> Result:
    """Runs a scenario to its end (``aes-sim run``); the GIL is released while it runs. A run that
    fails (a bad scenario, a run that left the model's range) raises ``AesSimError`` with the
    command line's message."""
    sc = _scenario(scenario)
    summary, data, rows = _aes_sim.run(sc.to_json())
    meta = signals()
    cols = np.frombuffer(data, dtype="<f8").reshape(len(meta), rows)
    trace = Trace((m["name"], cols[i]) for i, m in enumerate(meta))
    trace.units = {m["name"]: m["unit"] for m in meta}
    trace.labels = {m["name"]: m["label"] for m in meta}
    return Result(sc, json.loads(summary), trace)


def monte_carlo(
    scenario: ScenarioLike,
    trials: int | None = None,
    seed: int | None = None,
    threads: int | None = None,
    progress: Progress | None = None,
) -> dict:
    """A Monte Carlo study (``aes-sim mc FILE --trials N --seed S --threads T``) through the same
    pipeline: its summary dict, equal to the command's. ``trials`` and ``seed`` default to the
    scenario's ``monte_carlo.trials`` and ``sim.seed``; ``threads`` to every core (the numbers do
    not depend on it). ``progress(done, total)`` is called about ten times a second; an exception
    it raises, or Ctrl-C, stops the study and is raised."""
    return json.loads(_aes_sim.monte_carlo(_scenario(scenario).to_json(), trials, seed, threads, progress))


def _spec_text(spec: Mapping) -> str:
    d = dict(spec)
    if isinstance(d.get("scenario"), (Scenario, str, os.PathLike)):
        d["scenario"] = _scenario(d["scenario"]).to_dict()
    return json.dumps(d)


def study(
    kind: str,
    spec: Mapping | Scenario,
    *,
    range: tuple[int, int] | None = None,
    threads: int | None = None,
    progress: Progress | None = None,
) -> dict:
    """Any study on the pipeline by its kind (one of ``aes_sim.KINDS``) and its definition (the
    ``spec`` of its shard files; for ``monte-carlo`` a scenario). Whole: its summary dict. With
    ``range=(a, b)``: only items a..b, and the shard (a dict, as ``--partial`` writes it) for
    :func:`merge`."""
    text = spec.to_json() if isinstance(spec, Scenario) else _spec_text(spec)
    summary, shard = _aes_sim.run_study(kind, text, range, threads, progress)
    return json.loads(shard) if range is not None else json.loads(summary)


def fuel_per_mile(
    scenario: ScenarioLike = "preset:head-seas-ss6",
    speeds_kn: Iterable[float] = (12, 15, 18, 21, 24, 27),
    seeds: int = 3,
    from_s: float | None = None,
    *,
    threads: int | None = None,
    progress: Progress | None = None,
) -> dict:
    """Fuel per nautical mile against ordered speed over ``seeds`` seas each (``aes-sim
    fuel-per-mile FILE --speeds ... --seeds N --from S``, the same defaults): its summary dict.
    ``from_s`` (the start of the measurement) defaults to half the run."""
    sc = _scenario(scenario)
    if from_s is None:
        from_s = 0.5 * sc["sim.duration_s"]
    spec = {"scenario": sc, "speeds_kn": [float(v) for v in speeds_kn], "seeds": seeds, "from_s": from_s}
    return study("fuel-per-mile", spec, threads=threads, progress=progress)


def operability(
    scenario: ScenarioLike = "preset:startup",
    speeds_kn: Iterable[float] | None = None,
    headings_deg: Iterable[float] | None = None,
    sea_states: Iterable[int] | None = None,
    seas: Iterable[tuple[float, float]] | None = None,
    scatter: str | os.PathLike | None = None,
    *,
    threads: int | None = None,
    progress: Progress | None = None,
) -> dict:
    """The operability polar (``aes-sim operability FILE --speeds --headings --sea-states --seas
    --scatter``, the same defaults): speeds [kn], wave headings relative to the ship [deg] (180 head
    seas), sea states of Table 2.4 or seas of one's own as (H_1/3 m, T_p s) pairs, and a wave scatter
    diagram CSV file (``"none"`` for none; by default the IACS Rec. 34 North Atlantic)."""
    request: dict[str, Any] = {}
    if speeds_kn is not None:
        request["speeds_kn"] = [float(v) for v in speeds_kn]
    if headings_deg is not None:
        request["headings_deg"] = [float(v) for v in headings_deg]
    if sea_states is not None:
        request["sea_states"] = list(sea_states)
    if seas is not None:
        request["seas"] = [[float(h), float(t)] for h, t in seas]
    if scatter is not None:
        if os.fspath(scatter) == "none":
            request["scatter_csv"] = "none"
        else:
            with open(scatter, encoding="utf-8") as f:
                request["scatter_csv"] = f.read()
            request["scatter_name"] = os.fspath(scatter)
    return study("operability", {"scenario": _scenario(scenario), "request": request}, threads=threads, progress=progress)


def storage_sizing(
    scenario: ScenarioLike = "preset:head-seas-ss6",
    energies_mj: Iterable[float] = (25, 50, 100, 200, 400),
    powers_mw: Iterable[float] = (2.5, 5, 10, 20),
    duration_s: float = 600.0,
    *,
    threads: int | None = None,
    progress: Progress | None = None,
) -> dict:
    """Storage sizing (``aes-sim storage-sizing FILE --energy-mj --power-mw --duration-s --json``,
    the same defaults): one run per storage energy on each bus [MJ] and power rating [MW], each
    ``duration_s`` long; its summary dict."""
    sc = _scenario(scenario).copy().set("sim.duration_s", duration_s)
    spec = {
        "scenario": sc,
        "energies_j": [float(v) * 1e6 for v in energies_mj],
        "powers_w": [float(v) * 1e6 for v in powers_mw],
    }
    return study("storage-sizing", spec, threads=threads, progress=progress)


def maneuvers(scenario: ScenarioLike = "preset:turn-360", tracks: bool = True) -> dict:
    """The standard maneuvers booklet of the scenario's ship (``aes-sim maneuvers FILE --json``,
    IMO MSC.137(76)): the turning circle, the zig-zags, coasting, the crash stop and IMO's
    verdicts; ``tracks=False`` leaves the tracks empty, as ``--no-tracks`` does."""
    b = json.loads(_aes_sim.maneuvers(_scenario(scenario).to_json()))
    if not tracks:
        for key in ("turning", "zigzag_10", "zigzag_20", "stopping"):
            if b.get(key) is not None:
                b[key]["track"] = []
    return b


def schedule(scenario: ScenarioLike = "preset:startup") -> dict:
    """How many gas turbines should run, speed by speed and sea state by sea state (``aes-sim
    schedule FILE --json``'s ``schedule``, thesis ch. 6.1)."""
    return json.loads(_aes_sim.schedule(_scenario(scenario).to_json()))


def stability_map(
    scenario: ScenarioLike,
    x: tuple[str, float, float, int] | None = None,
    y: tuple[str, float, float, int] | None = None,
    *,
    threads: int | None = None,
    progress: Progress | None = None,
) -> dict:
    """The bus's stability (``aes-sim stability-map FILE [--x PATH=FROM:TO:N --y ...]``): without
    axes the eigenvalues at the scenario's operating point (its ``initial.speed_kn``, above 0);
    with ``x`` and ``y`` as ``(path, from, to, n)`` the map over those two parameters."""
    return json.loads(_aes_sim.stability_map(_scenario(scenario).to_json(), x, y, threads, progress))


def merge(shards: Iterable[Mapping | str | os.PathLike]) -> dict:
    """Merges shards of one study (dicts, or shard files from ``--partial``) and gives its summary,
    as ``aes-sim merge`` does."""
    texts = []
    for s in shards:
        if isinstance(s, Mapping):
            texts.append(json.dumps(dict(s)))
        else:
            with open(s, encoding="utf-8") as f:
                texts.append(f.read())
    summary, _ = _aes_sim.merge(texts)
    return json.loads(summary)
