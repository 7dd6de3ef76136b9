#!/usr/bin/env python3
"""A sweep of ordered speed and sea state from Python, and one row of the validation report.

    python3 python/examples/sweep_speed_sea.py [--plot sweep.png] [--duration 40]

1. The head-seas-ss6 preset (the hub at the ballast depth h0 = 3.5 m) at 15, 20 and 25 kn in sea
   states 4, 5 and 6: per run the least h/R (hub depth over propeller radius; ventilation below
   about 1.1), the least bus voltage and the mean motor power (per unit). With --plot (and matplotlib
   installed) h/R and the bus voltage against time, one line per run.
2. Table 5.7's generator efficiency at 25 kn from the startup preset, as docs/validation.md prints
   it (`aes-sim validate`): the thesis' 0.95, ours, and the report's tolerance of +- 0.01.
"""

import argparse
import pathlib
import sys

import numpy as np

import aes_sim

ROOT = pathlib.Path(__file__).resolve().parents[2]
SPEEDS_KN = [15, 20, 25]
SEA_STATES = [4, 5, 6]


def sweep(duration_s):
    base = aes_sim.Scenario.from_preset("head-seas-ss6").set("sim.duration_s", duration_s)
    runs = []
    for ss in SEA_STATES:
        for kn in SPEEDS_KN:
            # Start at the ordered speed, so the whole run is in the seaway at that speed.
            sc = base.copy().update({"sea.sea_state": ss, "commands.0.speed_kn": kn, "initial.speed_kn": kn})
            runs.append((ss, kn, aes_sim.run(sc)))
    return runs


def report_row(name):
    """The 'ours' column of a row of docs/validation.md, as printed."""
    for line in (ROOT / "docs" / "validation.md").read_text().splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if cells and cells[0] == name:
            return cells[1], cells[3]
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--plot", help="write h/R and the bus voltage against time to this image (needs matplotlib)")
    ap.add_argument("--duration", type=float, default=40.0, help="seconds simulated per run (default 40)")
    a = ap.parse_args()

    runs = sweep(a.duration)
    print("sea state  speed [kn]  min h/R [-]  min bus [V]  mean motor power [pu]")
    for ss, kn, r in runs:
        t = r.trace
        print(
            f"{ss:9d}  {kn:10.0f}  {t['h_over_r'].min():11.3f}  {t['bus_voltage_v'].min():11.0f}"
            f"  {np.mean(t['im_power_pu']):21.3f}"
        )

    if a.plot:
        try:
            import matplotlib

            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            print("--plot: matplotlib is not installed (pip install matplotlib); no figure", file=sys.stderr)
        else:
            fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(9, 6))
            for ss, kn, r in runs:
                t = r.trace
                ax1.plot(t["t_s"], t["h_over_r"], lw=0.8, label=f"SS{ss}, {kn} kn")
                ax2.plot(t["t_s"], t["bus_voltage_v"] / 1e3, lw=0.8)
            ax1.axhline(1.1, color="k", ls=":", lw=0.8, label="h/R = 1.1 (ventilation below)")
            ax1.set_ylabel(f"h/R [{runs[0][2].units['h_over_r']}]")
            ax2.set_ylabel("bus voltage [kV]")
            ax2.set_xlabel("time [s]")
            ax1.legend(fontsize=7, ncol=3)
            fig.tight_layout()
            fig.savefig(a.plot, dpi=120)
            print(f"wrote {a.plot}")

    # Table 5.7: the generator efficiency at 25 kn (the validation report's start-up to 25 kn is the
    # startup preset).
    thesis, tolerance = 0.95, 0.01
    ours = aes_sim.run("preset:startup").summary["efficiency"]["generator"]
    ok = abs(ours - thesis) <= tolerance
    print(f"\nTable 5.7, generator efficiency at 25 kn: thesis {thesis}, ours {ours:.4f} (+- {tolerance}: {'within' if ok else 'outside'})")
    row = report_row("generator efficiency at 25 kn")
    if row:
        print(f"docs/validation.md prints: reference {row[0]}, ours {row[1]}")
        if row[1] != f"{ours:.4f}":
            print("this differs from the report: regenerate it with ./build.sh validate", file=sys.stderr)
            return 1
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
