#!/usr/bin/env python3
"""Heave and pitch RAOs of the DTMB 5415 in head seas at Fn 0.28 (and at rest), from `aes-sim rao`.

Usage: python3 scripts/plot_rao.py [path/to/aes-sim] [out.png]   (needs matplotlib; not part of the build)
"""
import json, math, subprocess, sys

exe = sys.argv[1] if len(sys.argv) > 1 else "target/release/aes-sim"
out = sys.argv[2] if len(sys.argv) > 2 else "docs/rao_dtmb5415.png"
L, g = 142.0, 9.81
lam = [0.3 + 0.025 * i for i in range(109)]  # lambda / L from 0.3 to 3.0
omegas = [math.sqrt(2 * math.pi * g / (l * L)) for l in lam]
fn = 0.28
u_kn = fn * math.sqrt(g * L) / (1852 / 3600)

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

fig, ax = plt.subplots(1, 3, figsize=(13, 4))
for speed, style, label in [(u_kn, "-", f"Fn {fn} ({u_kn:.1f} kn)"), (0.0, "--", "Fn 0")]:
    r = json.loads(subprocess.check_output([exe, "rao", "--speed-kn", f"{speed}", "--heading-deg", "180",
                                            "--omega", ",".join(f"{w:.6f}" for w in omegas)]))
    k = [w * w / g for w in omegas]
    ax[0].plot(lam, r["heave"]["amp"], style, label=label)
    ax[1].plot(lam, [p / kk for p, kk in zip(r["pitch"]["amp"], k)], style, label=label)
    b = 19.06
    ax[2].plot(lam, [x / (1025 * g * b * b / L) for x in r["added_resistance_n_per_m2"]], style, label=label + " Salvesen")
    ax[2].plot(lam, [x / (1025 * g * b * b / L) for x in r["added_resistance_gerritsma_beukelman_n_per_m2"]], style,
               alpha=0.5, label=label + " Gerritsma-Beukelman")
ax[0].set(xlabel="lambda / L", ylabel="heave amplitude / wave amplitude", title="Heave, head seas")
ax[1].set(xlabel="lambda / L", ylabel="pitch amplitude / (k wave amplitude)", title="Pitch, head seas")
ax[2].set(xlabel="lambda / L", ylabel="R_aw / (rho g a^2 B^2 / L)", title="Added resistance, head seas")
for a in ax:
    a.grid(alpha=0.3)
    a.legend(fontsize=7)
fig.suptitle("DTMB 5415 (aes-sim strip theory: Lewis/bulb sections, Ursell-Tasai multipoles, STF 1970)")
fig.tight_layout()
fig.savefig(out, dpi=90)
print(out)
