#!/usr/bin/env python3
"""Regenerates the PDStrip comparison data of the seakeeping validation (see README.md here).

    python3 validation/pdstrip/regenerate.py PDSTRIP [--aes-sim BIN] [--date YYYY-MM-DD]

PDSTRIP is either a PDStrip checkout (a directory holding pdstrip.f90, compiled here with
gfortran -O2) or an already built pdstrip binary. The script

  1. builds PDStrip's inputs for the DTMB 5415 and the Wigley hull from this repository's own hull
     data (core/data/dtmb5415_offsets.csv; the Wigley formula of HullOffsets::wigley_sized) and
     loading (core/src/ship/hull.rs), and writes them to validation/pdstrip/inputs/<hull>/;
  2. runs PDStrip on each in a scratch directory;
  3. copies PDStrip's raw output (pdstrip.out trimmed to the cases used, relativemotions whole) to
     validation/pdstrip/outputs/<hull>/;
  4. writes core/data/pdstrip_raos.csv, converted to the STF conventions of
     core/src/sea/seakeeping/strip.rs;
  5. with --aes-sim, runs `aes-sim rao` at the same frequencies and prints the comparison.

Python 3 standard library only. Not run in CI (CI has no Fortran compiler): run it by hand.
"""

import argparse
import cmath
import datetime
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", ".."))
G = 9.81  # core/src/sea/waves.rs
RHO = 1025.0  # ship.water_density_kg_m3 default, kg/m^3
KNOT = 1852.0 / 3600.0
# PDStrip's output formats are laid out for metres, seconds and tonnes: its inputs use tonnes.
RHO_T = RHO / 1000.0

# ---------------------------------------------------------------------------------------------
# The hulls and their loading: as core/src/ship/hull.rs (`fn dtmb5415`, `fn wigley`) and
# core/src/geometry.rs (`HullOffsets::wigley`, WIGLEY_STATIONS = 19, WIGLEY_ROWS_BELOW_WL = 24).
# ---------------------------------------------------------------------------------------------
HULLS = {
    "dtmb5415": dict(
        lpp=142.0,
        draft=6.15,
        kg=7.555,
        k=(0.37 * 19.06, 0.25 * 142.0, 0.25 * 142.0),
        propeller_x=8.3,  # from the AP
        hub_above_base=0.15,
        # Largest panel on a section contour [m] (PDStrip's manual: about equal spacing).
        max_seg=0.5,
    ),
    "wigley": dict(
        lpp=100.0,
        draft=6.25,
        kg=4.5,
        k=(0.35 * 10.0, 0.25 * 100.0, 0.25 * 100.0),
        propeller_x=5.8,
        hub_above_base=0.15,
        max_seg=0.4,
    ),
}

# The cases: (hull, Froude number or None, speed [kn] (used when fn is None), heading [deg, STF:
# 180 head seas, 90 waves from starboard], quantities, wave frequencies [rad/s]).
BEAM_DTMB = [0.15, 0.25, 0.35, 0.40, 0.45, 0.50, 0.53, 0.55, 0.56, 0.565, 0.57, 0.575, 0.58, 0.59,
             0.60, 0.62, 0.65, 0.70, 0.80, 0.90, 1.00, 1.20]
BEAM_WIGLEY = [0.15, 0.30, 0.40, 0.50, 0.60, 0.65, 0.68, 0.69, 0.70, 0.705, 0.71, 0.715, 0.72, 0.73,
               0.75, 0.78, 0.80, 0.85, 0.90, 1.00, 1.20]
OBLIQUE_DTMB = [0.15, 0.20, 0.25, 0.30, 0.35, 0.38, 0.39, 0.40, 0.405, 0.41, 0.415, 0.42, 0.43, 0.45,
                0.50, 0.55, 0.60, 0.70, 0.80, 0.90, 1.00, 1.20]
OBLIQUE_WIGLEY = [0.15, 0.25, 0.30, 0.35, 0.40, 0.45, 0.50, 0.52, 0.54, 0.55, 0.56, 0.565, 0.57, 0.58,
                  0.60, 0.65, 0.70, 0.80, 0.90, 1.00, 1.20]
HEAD_DTMB = [0.15, 0.25, 0.30, 0.35, 0.40, 0.45, 0.50, 0.53, 0.56, 0.59, 0.62, 0.65, 0.68, 0.71,
             0.75, 0.80, 0.85, 0.90, 1.00, 1.10, 1.20]
# At rest in head seas: the long-wave check of the conventions (heave -> 1, relative motion -> 0).
HEAD_DTMB_REST = [0.15, 0.25, 0.35, 0.45, 0.55, 0.65, 0.80, 1.00, 1.20]
SPEED_25KN = 25.0
CASES = [
    ("dtmb5415", 0.0, None, 90.0, ["sway_m_per_m", "roll_rad_per_m"], BEAM_DTMB),
    ("dtmb5415", 0.2, None, 90.0, ["sway_m_per_m", "roll_rad_per_m"], BEAM_DTMB),
    ("dtmb5415", None, SPEED_25KN, 135.0, ["sway_m_per_m", "roll_rad_per_m", "yaw_rad_per_m"], OBLIQUE_DTMB),
    ("dtmb5415", None, SPEED_25KN, 180.0, ["heave_m_per_m", "pitch_rad_per_m", "rel_motion_stern_m_per_m"], HEAD_DTMB),
    ("dtmb5415", 0.0, None, 180.0, ["heave_m_per_m", "pitch_rad_per_m", "rel_motion_stern_m_per_m"], HEAD_DTMB_REST),
    ("wigley", 0.0, None, 90.0, ["sway_m_per_m", "roll_rad_per_m"], BEAM_WIGLEY),
    ("wigley", 0.2, None, 90.0, ["sway_m_per_m", "roll_rad_per_m"], BEAM_WIGLEY),
    ("wigley", 0.2, None, 135.0, ["sway_m_per_m", "roll_rad_per_m", "yaw_rad_per_m"], OBLIQUE_WIGLEY),
]


def case_speed(hull, fn, kn):
    """Ship speed [m/s] of a case."""
    if fn is not None:
        return fn * math.sqrt(G * HULLS[hull]["lpp"])
    return kn * KNOT


def case_fn(hull, fn, kn):
    return case_speed(hull, fn, kn) / math.sqrt(G * HULLS[hull]["lpp"])


# ---------------------------------------------------------------------------------------------
# Offsets and hydrostatics, as core/src/geometry.rs computes them.
# ---------------------------------------------------------------------------------------------
def read_offsets_csv(path):
    stations = []
    with open(path) as f:
        header = False
        for line in f:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            if not header:
                header = True
                continue
            idx, x, z, hb = (float(v) for v in line.split(","))
            if stations and stations[-1]["index"] == idx:
                stations[-1]["z"].append(z)
                stations[-1]["hb"].append(hb)
            else:
                stations.append(dict(index=idx, x=x, z=[z], hb=[hb]))
    return stations


def wigley_offsets(lpp=100.0, beam=10.0, draft=6.25, n=19, rows=24):
    """HullOffsets::wigley_sized."""
    stations = []
    for i in range(n):
        x = 0.5 * lpp * (1.0 - math.cos(math.pi * i / (n - 1)))
        xi = 2.0 * x / lpp - 1.0
        long = max(1.0 - xi * xi, 0.0)
        z = [draft * j / rows for j in range(rows + 1)] + [draft * (1.0 + j / 8.0) for j in range(1, 5)]
        hb = []
        for zz in z:
            d = max((draft - zz) / draft, 0.0)
            hb.append(0.5 * beam * long * (1.0 - d * d))
        stations.append(dict(index=float(i), x=x, z=z, hb=hb))
    return stations


def hb_at(s, zq):
    z, hb = s["z"], s["hb"]
    for i in range(1, len(z)):
        if zq <= z[i]:
            f = (zq - z[i - 1]) / (z[i] - z[i - 1])
            return hb[i - 1] + f * (hb[i] - hb[i - 1])
    return hb[-1]


def keel_of(s):
    first = next((i for i, h in enumerate(s["hb"]) if h > 0.0), None)
    if first is None:
        return None
    return s["z"][0] if first == 0 else s["z"][first - 1]


def section(s, t):
    keel = keel_of(s)
    if keel is None or keel >= t:
        return dict(x=s["x"], beam=0.0, draft=0.0, area=0.0, zc=t)
    zs = [keel] + [z for z in s["z"] if keel < z < t] + [t]
    area = moment = 0.0
    for z0, z1 in zip(zs, zs[1:]):
        b0, b1 = 2 * hb_at(s, z0), 2 * hb_at(s, z1)
        a = 0.5 * (b0 + b1) * (z1 - z0)
        area += a
        zc = z0 + (z1 - z0) * (b0 + 2 * b1) / (3 * (b0 + b1)) if b0 + b1 > 0 else 0.5 * (z0 + z1)
        moment += a * zc
    return dict(x=s["x"], beam=2 * hb_at(s, t), draft=t - keel, area=area, zc=moment / area if area > 0 else t)


def hydrostatics(stations, t):
    secs = [section(s, t) for s in stations]
    vol = mx = mz = awp = ax = it = il = 0.0
    for a, b in zip(secs, secs[1:]):
        dx = b["x"] - a["x"]
        tr = lambda fa, fb: 0.5 * (fa + fb) * dx  # noqa: E731
        vol += tr(a["area"], b["area"])
        mx += tr(a["area"] * a["x"], b["area"] * b["x"])
        mz += tr(a["area"] * a["zc"], b["area"] * b["zc"])
        awp += tr(a["beam"], b["beam"])
        ax += tr(a["beam"] * a["x"], b["beam"] * b["x"])
        it += tr(a["beam"] ** 3 / 12, b["beam"] ** 3 / 12)
        il += tr(a["beam"] * a["x"] ** 2, b["beam"] * b["x"] ** 2)
    xf = ax / awp
    return dict(volume=vol, lcb=mx / vol, kb=mz / vol, awp=awp, bmt=it / vol, bml=(il - awp * xf * xf) / vol,
                secs=secs)


# ---------------------------------------------------------------------------------------------
# PDStrip's input.
# ---------------------------------------------------------------------------------------------
MIN_HB = 0.03  # [m] half-breadth given to rows inside a wet section that have none (5415 stem gap)


def contour(s, t, max_seg):
    """A closed section contour for PDStrip (sym = .false.): from the starboard waterline down to
    the keel and up to the port waterline, y to port, z up from the waterline (input axes). Rows
    with no breadth between the keel and the waterline (the 5415's stem above its sonar dome) get
    MIN_HB; long panels are split so none exceeds max_seg; a very sharp keel is blunted."""
    keel = keel_of(s)
    zs = [z for z in s["z"] if keel < z < t]
    half = [(hb_at(s, z) if hb_at(s, z) > 0.0 else MIN_HB, z - t) for z in zs] + [(hb_at(s, t), 0.0)]
    # A keel sharper than about 8.5 deg either side (the Wigley's end stations: 2.6 deg) puts
    # PDStrip's sources outside the contour: such a keel is blunted to a flat of half-width w
    # (0.04 m on the Wigley, 0.6 % of its end strips' area).
    y1, z1 = half[0]
    w = 0.0 if y1 >= 0.15 * (z1 - (keel - t)) else 0.15 * (z1 - (keel - t))
    # Port half from the keel up, then split long panels.
    port = [(w, keel - t)] + half
    fine = [port[0]]
    for (y0, z0), (y1, z1) in zip(port, port[1:]):
        # Where the section is thin (the 5415's stem above its dome) panels are kept under six
        # half-breadths: PDStrip places its sources 1/20 of a panel inside the contour and tests
        # them against a contour 1/9 of a panel inside ("Unsuitable section discretisation").
        seg = max_seg if min(y0, y1) <= 0.0 else min(max_seg, max(6.0 * min(y0, y1), 0.05))
        n = max(1, math.ceil(math.hypot(y1 - y0, z1 - z0) / seg))
        for j in range(1, n + 1):
            fine.append((y0 + (y1 - y0) * j / n, z0 + (z1 - z0) * j / n))
    stbd = [(-y, z) for (y, z) in reversed(fine if w > 0.0 else fine[1:])]
    return stbd + fine


def build_case_grid(hull):
    """Wave frequencies and speeds PDStrip is run at for a hull: the union of its cases'."""
    omegas = sorted({w for c in CASES if c[0] == hull for w in c[5]})
    speeds = sorted({round(case_speed(c[0], c[1], c[2]), 6) for c in CASES if c[0] == hull})
    return omegas, speeds


def write_inputs(hull, outdir):
    h = HULLS[hull]
    stations = (read_offsets_csv(os.path.join(REPO, "core", "data", "dtmb5415_offsets.csv"))
                if hull == "dtmb5415" else wigley_offsets())
    t = h["draft"]
    hs = hydrostatics(stations, t)
    lcg = hs["lcb"]
    mass_kg = RHO * hs["volume"]
    gm_t = hs["kb"] + hs["bmt"] - h["kg"]
    # The stations our strip theory uses (Ship::new): beam, draft and area at the waterline.
    wet = [s for s, sec in zip(stations, hs["secs"]) if sec["beam"] > 1e-3 and sec["draft"] > 1e-3
           and sec["area"] > 1e-6]
    geo = ["%d f %.4f" % (len(wet), t)]
    for s in wet:
        pts = contour(s, t, h["max_seg"])
        geo.append("%.4f %d 0" % (s["x"] - lcg, len(pts)))
        geo.append(" ".join("%.4f" % p[0] for p in pts))
        geo.append(" ".join("%.4f" % p[1] for p in pts))
    omegas, speeds = build_case_grid(hull)
    wavelengths = [2 * math.pi * G / (w * w) for w in omegas]
    hub = (h["propeller_x"] - lcg, 0.0, h["hub_above_base"] - t)
    kxx, kyy, kzz = h["k"]
    zg = h["kg"] - t
    # Transom wetted? The 5415's small immersed transom (0.54 m) runs dry at speed; the Wigley has
    # none (its aftmost wet station closes the body: "wetted").
    trwet = ["t" if (v == 0.0 or hull == "wigley") else "f" for v in speeds]
    inp = [
        "0 t t f                 npres, section data?, transfer functions?, significant amplitudes?",
        "'%s: hull data of aes-sim (validation/pdstrip/regenerate.py)'" % hull,
        "%.2f %.4f 0.0 -1e6 0.0  g, rho [t/m^3], z of waterline, z of bottom (deep), z for drift" % (G, RHO_T),
        "3 0. 45. 90.            wave angles (also 135 and 180 are computed)",
        "%s.geo" % hull,
        "f                       intersection forces?",
        "%.4f 0.0 0.0 %.4f %.4f %.4f %.4f 0.0 0.0 0.0   mass [t], xG yG zG, kxx^2 kyy^2 kzz^2, products"
        % (mass_kg / 1000.0, zg, kxx * kxx, kyy * kyy, kzz * kzz),
        " ".join("0" for _ in wet) + "   flow separation",
        "0.0 0.0                 wave steepness, max. height: no cross-flow drag (potential damping only)",
        "0                       fins",
        "0                       sails",
        "0                       motion-dependent forces",
        "0.0 0.0 0.0 0.0 0.0     suspended weight",
        "1                       motion points",
        "%.4f %.4f %.4f   propeller hub (centreline)" % hub,
        "%d" % len(wavelengths),
        " ".join("%.5f" % lam for lam in wavelengths),
        "%d %s" % (len(speeds), " ".join("%.6f %s" % (v, tw) for v, tw in zip(speeds, trwet))),
    ]
    d = os.path.join(outdir, hull)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "pdstrip.inp"), "w") as f:
        f.write("\n".join(inp) + "\n")
    with open(os.path.join(d, hull + ".geo"), "w") as f:
        f.write("\n".join(geo) + "\n")
    return dict(lcg=lcg, mass_kg=mass_kg, gm_t=gm_t, hub=hub, omegas=omegas, speeds=speeds,
                volume=hs["volume"], n_sections=len(wet), wavelengths=wavelengths)


# ---------------------------------------------------------------------------------------------
# Running PDStrip and reading its output.
# ---------------------------------------------------------------------------------------------
def pdstrip_binary(path, scratch):
    if os.path.isdir(path):
        src = os.path.join(path, "pdstrip.f90")
        exe = os.path.join(scratch, "pdstrip")
        subprocess.run(["gfortran", "-O2", "-o", exe, src], check=True, cwd=scratch)
        return exe
    return os.path.abspath(path)


def run_pdstrip(exe, inputs_dir, hull, scratch):
    wd = os.path.join(scratch, hull)
    shutil.copytree(os.path.join(inputs_dir, hull), wd)
    subprocess.run([exe], cwd=wd, check=True, stdout=subprocess.DEVNULL)
    # PDStrip stops on bad input with a message at the end of pdstrip.out and exit status 0.
    if os.path.getsize(os.path.join(wd, "relativemotions")) == 0:
        tail = open(os.path.join(wd, "pdstrip.out"), encoding="latin-1").read().strip().split("\n")[-1]
        sys.exit("%s: PDStrip stopped: %s" % (hull, tail.strip()))
    return wd


# Fixed-width fields run into their labels ("wave length2739.47").
HEADER = re.compile(r" Wave circ\. frequency\s*(\S+)\s+encounter frequ\.\s*(-?[\d.]+)\s+wave length\s*([\d.]+)"
                    r"\s+wave number\s*([\d.]+)\s+wave angle\s*(-?[\d.]+)")


def parse_out(path):
    """The per-case blocks of pdstrip.out: header values, translations, rotations/k, relative
    motions at the motion points; and the lines of each block (for trimming)."""
    lines = open(path, encoding="latin-1").read().split("\n")
    blocks, cur, head_end = [], None, None
    for i, line in enumerate(lines):
        if line.startswith(" Wave circ. frequency"):
            if head_end is None:
                head_end = i - 1  # the dashed line before the first block
            p = [float(v) for v in HEADER.match(line).groups()]
            cur = dict(om=p[0], ome=p[1], lam=p[2], k=p[3], mu=p[4], start=i - 1, rel=[])
            blocks.append(cur)
        elif cur is not None and line.startswith(" speed"):
            cur["speed"] = float(line.split()[1])
        elif cur is not None and line.startswith(" Translation"):
            v = [float(x) for x in line.split()[1:]]
            cur["trans"] = [complex(v[3 * i], v[3 * i + 1]) for i in range(3)]
        elif cur is not None and line.startswith(" Relative motions"):
            cur["in_rel"] = True
        elif cur is not None and line.startswith(" at point") and cur.get("in_rel"):
            v = [float(x) for x in line.split()[3:]]
            cur["rel"].append([complex(v[3 * i], v[3 * i + 1]) for i in range(3)])
        if cur is not None:
            cur["end"] = i
    return lines, head_end, blocks


def read_motions(path):
    """File `relativemotions`: the 6 complex motions of each case (list-directed), in the order of
    the blocks of pdstrip.out."""
    text = open(path).read().replace("\n", " ")
    nums = []
    for tok in text.replace("(", " ").replace(")", " ").replace(",", " ").split():
        nums.append(float(tok))
    out = []
    for i in range(0, len(nums), 12):
        out.append([complex(nums[i + 2 * j], nums[i + 2 * j + 1]) for j in range(6)])
    return out


# PDStrip's results are in its axes (1 forward, 2 starboard, 3 down; rotations right-handed about
# them: roll starboard down, pitch bow up, yaw bow to starboard) per unit complex amplitude of the
# downward water-surface displacement at the origin (its z axis points down: a positive real
# amplitude is a trough at the origin at t = 0). STF (ours): y to port, z up; roll port up, pitch
# bow down, yaw bow to port; per unit elevation (up): a crest at the origin at t = 0. Both use
# Re{A e^{i omega_e t}} and the same spatial phase e^{-i k (x cos mu + y_port sin mu)} with mu = beta
# (0 following, 90 from starboard, 180 head). A response r_stf = s r_pd (s = +1 where both axes
# agree) per wave eta_up = -eta_down: H_stf = -s H_pd, i.e.
#   sway: s = -1 -> H_stf = H_pd;  heave: s = -1 -> H_pd;  roll: s = +1 -> -H_pd;
#   pitch: s = -1 -> H_pd;  yaw: s = -1 -> H_pd;
#   relative motion (PDStrip: point minus water, downward = our hub depth's increase): -H_pd.
FACTOR = {"sway": 1, "heave": 1, "roll": -1, "pitch": 1, "yaw": 1, "rel": -1}


def extract(hull, wd, info):
    lines, head_end, blocks = parse_out(os.path.join(wd, "pdstrip.out"))
    motions = read_motions(os.path.join(wd, "relativemotions"))
    if len(motions) != len(blocks):
        sys.exit("%s: %d blocks in pdstrip.out but %d motion records" % (hull, len(blocks), len(motions)))
    rows, keep = [], []
    for c in CASES:
        if c[0] != hull:
            continue
        v = case_speed(*c[:3])
        fn = case_fn(*c[:3])
        for w in c[5]:
            lam = 2 * math.pi * G / (w * w)
            found = [i for i, b in enumerate(blocks)
                     if abs(b["lam"] - lam) < 0.006 + 1e-4 * lam and abs(b["speed"] - v) < 0.006
                     and abs(b["mu"] - c[3]) < 0.06]
            if len(found) != 1:
                sys.exit("%s: case v=%.3f mu=%.0f omega=%.3f: %d blocks" % (hull, v, c[3], w, len(found)))
            i = found[0]
            b, m = blocks[i], motions[i]
            keep.append(i)
            # Cross-check: the printed translations are the stored motions rounded.
            for j in range(3):
                if abs(b["trans"][j] - m[j]) > 1.5e-3:
                    sys.exit("%s: printed and stored motions differ" % hull)
            val = {"sway_m_per_m": FACTOR["sway"] * m[1], "heave_m_per_m": FACTOR["heave"] * m[2],
                   "roll_rad_per_m": FACTOR["roll"] * m[3], "pitch_rad_per_m": FACTOR["pitch"] * m[4],
                   "yaw_rad_per_m": FACTOR["yaw"] * m[5],
                   "rel_motion_stern_m_per_m": FACTOR["rel"] * b["rel"][0][2]}
            for q in c[4]:
                z = val[q]
                # Phases of the relative motion are from the printed 3 decimals: keep them only where
                # the amplitude is well above that rounding.
                trust = not (q.startswith("rel") and abs(z) < 0.02)
                rows.append((hull, fn, c[3], w, q, abs(z), math.degrees(cmath.phase(z)) if trust else None))
    return rows, lines, head_end, blocks, sorted(set(keep))


def write_trimmed(lines, head_end, blocks, keep, path):
    out = lines[:head_end]
    out.append(" [regenerate.py: only the blocks of the compared cases are kept below; the full run"
               " prints every speed at wave angles 0, 45, 90, 135 and 180 deg]")
    for i in keep:
        out.extend(lines[blocks[i]["start"]:blocks[i]["end"] + 1])
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


# ---------------------------------------------------------------------------------------------
# Our RAOs, for the comparison.
# ---------------------------------------------------------------------------------------------
def ours(aes_sim, hull, kn, heading, omegas, scratch, roll_amp, bare):
    """`aes-sim rao`. With `bare`, the viscous roll damping as small as the CLI allows: no bilge
    keels (the 5415's own are removed through a scenario file); the caller picks the wave amplitude
    the damping is linearised at (0.01 m is the smallest --roll-wave-amplitude). Ikeda's lift term
    (linear in speed) and the hull friction stay: the CLI has no switch for them."""
    if bare:
        scen = os.path.join(scratch, "scenario_%s.json" % hull)
        if not os.path.exists(scen):
            base = json.loads(subprocess.run([aes_sim, "preset", "startup"], check=True, capture_output=True,
                                             text=True).stdout)
            base["ship"]["hull"] = {"name": hull, "bilge_keels": {"length_m": 0.0, "breadth_m": 0.0}}
            with open(scen, "w") as f:
                json.dump(base, f)
        which = ["--scenario", scen]
    else:
        which = ["--hull", hull]
    out = subprocess.run([aes_sim, "rao"] + which + ["--speed-kn", "%.6f" % kn, "--heading-deg",
                          "%g" % heading, "--omega", ",".join("%g" % w for w in omegas),
                          "--roll-wave-amplitude", "%g" % roll_amp], check=True, capture_output=True, text=True)
    d = json.loads(out.stdout)
    res = {}
    for q, key in (("sway_m_per_m", "sway"), ("heave_m_per_m", "heave"), ("roll_rad_per_m", "roll"),
                   ("pitch_rad_per_m", "pitch"), ("yaw_rad_per_m", "yaw")):
        res[q] = [a * cmath.exp(1j * math.radians(p)) for a, p in zip(d[key]["amp"], d[key]["phase_deg"])]
    return res


def rel_motion(res, hull, beta, omegas, lcg):
    """Eq. 2.57 with the consistent sign (SternMotion::Consistent) on the centreline: the wave at
    the hub minus heave minus x_p pitch (STF: pitch bow down), per unit wave amplitude."""
    x_aft = lcg - HULLS[hull]["propeller_x"]
    out = []
    for i, w in enumerate(omegas):
        k = w * w / G
        wave = cmath.exp(1j * k * x_aft * math.cos(math.radians(beta)))
        out.append(wave - res["heave_m_per_m"][i] - x_aft * res["pitch_rad_per_m"][i])
    return out


def compare(aes_sim, pd_rows, info, scratch):
    print("\nComparison with `aes-sim rao` (amplitudes per metre of wave amplitude; diff = ours / PDStrip - 1)")
    print("  ours-min: no bilge keels, roll damping linearised at a 0.01 m wave (the least viscous damping the CLI")
    print("  allows); ours-default: the hull as the simulator uses it (5415 bilge keels, 1 m wave).")
    peaks = []
    for c in CASES:
        hull, fn0, kn0, beta, qs, omegas = c
        kn = case_speed(hull, fn0, kn0) / KNOT
        fn = case_fn(hull, fn0, kn0)
        o = ours(aes_sim, hull, kn, beta, omegas, scratch, 0.01, True)
        o1 = ours(aes_sim, hull, kn, beta, omegas, scratch, 1.0, False)
        for r in (o, o1):
            r["rel_motion_stern_m_per_m"] = rel_motion(r, hull, beta, omegas, info[hull]["lcg"])
        print("\n%s Fn %.3f (%.2f kn) heading %g deg" % (hull, fn, kn, beta))
        for q in qs:
            print("  %s" % q)
            print("    omega   PDStrip   ours-min   diff%   phase PDStrip / ours-min [deg]   ours-default")
            pd = [next(r for r in pd_rows if r[0] == hull and abs(r[1] - fn) < 1e-6 and r[2] == beta
                       and r[3] == w and r[4] == q) for w in omegas]
            for i, w in enumerate(omegas):
                a = abs(o[q][i])
                ph = ("%7.1f / %7.1f" % (pd[i][6], math.degrees(cmath.phase(o[q][i])))
                      if pd[i][6] is not None else "      - /    -   ")
                print("    %5.3f  %9.4f  %9.4f  %6.1f   %s   %12.4f" % (
                    w, pd[i][5], a, 100 * (a / pd[i][5] - 1) if pd[i][5] > 0 else float("nan"), ph, abs(o1[q][i])))
            ip = max(range(len(omegas)), key=lambda i: pd[i][5])
            io = max(range(len(omegas)), key=lambda i: abs(o[q][i]))
            i1 = max(range(len(omegas)), key=lambda i: abs(o1[q][i]))
            peaks.append((hull, fn, beta, q, omegas[ip], pd[ip][5], omegas[io], abs(o[q][io]), omegas[i1],
                          abs(o1[q][i1])))
    print("\nPeaks on the grid: omega [rad/s] and amplitude; diff = ours-min / PDStrip - 1")
    for p in peaks:
        print("  %-8s Fn %.3f %5g deg %-26s PDStrip %.3f: %8.4f  ours-min %.3f: %8.4f (%+6.1f %%)  ours-default %.3f: %8.4f"
              % (p[:4] + (p[4], p[5], p[6], p[7], 100 * (p[7] / p[5] - 1), p[8], p[9])))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("pdstrip", help="PDStrip checkout (with pdstrip.f90) or a built pdstrip binary")
    ap.add_argument("--aes-sim", help="aes-sim binary: also print the comparison with `aes-sim rao`")
    ap.add_argument("--date", default=datetime.date.today().isoformat())
    ap.add_argument("--source", default="github.com/eriove/pdstrip commit bb895d445186575c886bf900352795e88c245d8b",
                    help="what the PDStrip source is, for the CSV header")
    a = ap.parse_args()
    inputs = os.path.join(HERE, "inputs")
    outputs = os.path.join(HERE, "outputs")
    scratch = tempfile.mkdtemp(prefix="pdstrip-")
    exe = pdstrip_binary(a.pdstrip, scratch)
    info, all_rows = {}, []
    for hull in HULLS:
        info[hull] = write_inputs(hull, inputs)
        wd = run_pdstrip(exe, inputs, hull, scratch)
        rows, lines, head_end, blocks, keep = extract(hull, wd, info[hull])
        all_rows += rows
        od = os.path.join(outputs, hull)
        os.makedirs(od, exist_ok=True)
        write_trimmed(lines, head_end, blocks, keep, os.path.join(od, "pdstrip.out"))
        shutil.copy(os.path.join(wd, "relativemotions"), os.path.join(od, "relativemotions"))
        i = info[hull]
        gm_pd = next((float(l.split(":")[1]) for l in lines if l.startswith("Transverse metacentric height")), None)
        print("%s: %d sections, volume %.1f m^3, mass %.0f t, LCG %.3f m from the AP, GM_T ours %.3f m, "
              "PDStrip %.3f m; hub %s" % (hull, i["n_sections"], i["volume"], i["mass_kg"] / 1000, i["lcg"], i["gm_t"],
                                          gm_pd, ", ".join("%.3f" % v for v in i["hub"])))
    csv = os.path.join(REPO, "core", "data", "pdstrip_raos.csv")
    with open(csv, "w") as f:
        f.write("# Strip-theory RAOs of PDStrip (H. Soeding and V. Bertram's public-domain strip method), source %s,\n"
                % a.source)
        f.write("# compiled with gfortran -O2, run by validation/pdstrip/regenerate.py on %s (inputs and raw output in\n"
                % a.date)
        f.write("# validation/pdstrip/). Hulls and loading as core/src/ship/hull.rs (dtmb5415 at 6.15 m, wigley), deep water,\n")
        f.write("# rho 1025 kg/m^3, g 9.81 m/s^2, potential damping only (no cross-flow drag, no fins or bilge keels).\n")
        f.write("# Conventions converted to ours (core/src/sea/seakeeping/strip.rs, STF): heading_deg 180 head seas,\n")
        f.write("# 90 waves from starboard; sway to port and heave up at the waterline point above G; roll port side up;\n")
        f.write("# pitch bow down; yaw bow to port; rel_motion_stern = wave elevation at the propeller hub minus the hub's\n")
        f.write("# rise (the change of its depth, eq. 2.57 with the consistent sign), hub 8.3 m forward of the AP on the\n")
        f.write("# centreline. omega_rad_s is the wave frequency; fn = U / sqrt(g Lpp) (5415 25 kn: Fn 0.3446).\n")
        f.write("# amplitude per unit wave amplitude (m/m or rad/m); phase_deg of Re{A e^{i omega_e t}} relative to the\n")
        f.write("# wave crest at the origin (empty where the printed precision does not support it).\n")
        f.write("hull,fn,heading_deg,omega_rad_s,quantity,amplitude,phase_deg\n")
        for r in all_rows:
            f.write("%s,%.4f,%g,%g,%s,%.6g,%s\n" % (r[0], r[1], r[2], r[3], r[4], r[5],
                                                  "" if r[6] is None else "%.2f" % r[6]))
    print("wrote %s (%d rows)" % (os.path.relpath(csv, REPO), len(all_rows)))
    if a.aes_sim:
        compare(os.path.abspath(a.aes_sim), all_rows, info, scratch)
    shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()
