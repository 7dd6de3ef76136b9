#!/usr/bin/env python3
"""Rice's rate of Table 5.8 (thesis eqs. 5.1-5.3) for readings of the hub depth that the simulator
has no switch for, from the RAOs `aes-sim rao` prints (standard library only).

The hub depth per unit wave: e^{i s_w k x_p cos beta} - H3 + s_p x_p H5 (pitch STF: bow down).
s_p = +1, s_w = +1 is eq. 2.57 as printed (the simulator's `thesis_eq_2_57`), s_p = -1, s_w = +1 the
consistent depth, s_w = -1 eq. 5.2's e^{+ikx_s} read literally. Bretschneider SS6 over 0.6-4 omega_n,
cos^2 spreading (61 directions, headings 90-180 deg interpolated every 10 deg), 25 kn. Its M0 is within
0.3 % of the simulator's Rice (core/src/studies/montecarlo.rs), which reads the RAO table.

Usage: scripts/rice_candidates.py [path/to/aes-sim]   (prints one line per reading)
"""
import bisect, cmath, json, math, subprocess, sys

G = 9.80665
EXE = sys.argv[1] if len(sys.argv) > 1 else "./target/release/aes-sim"
HEADINGS = list(range(90, 181, 10))
OMEGAS = ",".join("%.3f" % (0.25 + 0.01 * i) for i in range(226))


def raos(h):
    out = subprocess.run([EXE, "rao", "--scenario", "preset:mc-arrival", "--speed-kn", "25", "--heading-deg",
                          str(h), "--omega", OMEGAS], check=True, capture_output=True, text=True).stdout
    d = json.loads(out)
    c = lambda k: [a * cmath.exp(1j * math.radians(p)) for a, p in zip(d[k]["amp"], d[k]["phase_deg"])]
    return d["omega0"], c("heave"), c("pitch")


R = {h: raos(h) for h in HEADINGS}


def interp(x, xs, ys):
    i = max(0, min(len(xs) - 2, bisect.bisect_right(xs, x) - 1))
    f = (x - xs[i]) / (xs[i + 1] - xs[i])
    return ys[i] * (1 - f) + ys[i + 1] * f


def bret(w, H=16.4 * 0.3048, wn=0.507):  # eq. 2.58, Table 2.4's SS6
    return 5 / 16 * wn**4 / w**5 * H * H * math.exp(-1.25 * (wn / w) ** 4)


def moments(xp=62.0, s_p=1, s_w=1, spread=2.0, u=25 * 1852 / 3600, absfreq=False, nw=400, nd=61):
    lo, hi = 0.6 * 0.507, 4 * 0.507
    dw = (hi - lo) / nw
    if spread > 0:
        dd = math.pi / nd
        ds = [-math.pi / 2 + (j + 0.5) * dd for j in range(nd)]
        wt = [math.cos(x) ** spread for x in ds]
        wt = [x / sum(wt) for x in wt]
    else:
        ds, wt = [0.0], [1.0]
    m0 = m2 = 0.0
    for d, p in zip(ds, wt):
        b = math.pi - abs(d)
        deg = math.degrees(b)
        h1 = max(90, min(180, 10 * math.floor(deg / 10)))
        h2 = min(180, h1 + 10)
        f = (deg - h1) / 10 if h2 != h1 else 0.0
        cb = math.cos(b)
        for i in range(nw):
            w = lo + (i + 0.5) * dw
            he = (1 - f) * interp(w, R[h1][0], R[h1][1]) + f * interp(w, R[h2][0], R[h2][1])
            pi = (1 - f) * interp(w, R[h1][0], R[h1][2]) + f * interp(w, R[h2][0], R[h2][2])
            k = w * w / G
            hp = cmath.exp(1j * s_w * k * xp * cb) - he + s_p * xp * pi
            sy = abs(hp) ** 2 * bret(w) * p * dw
            we = w if absfreq else abs(w - k * u * cb)
            m0 += sy
            m2 += sy * we * we
    return m0, m2


def rate(m0, m2, z):  # eq. 5.3
    return math.sqrt(m2 / m0) / (2 * math.pi) * math.exp(-z * z / (2 * m0))


print("s_p s_w x_p spread absfreq | sigma  nu0    | rate at Z = 2.88, 3.36, 3.88 m | Z for 0.044 1/s")
for s_p in (1, -1):
    for s_w in (1, -1):
        for xp in (62.0, 75.0):
            for spread in (2.0, 0.0):
                for absfreq in (False, True):
                    m0, m2 = moments(xp, s_p, s_w, spread, absfreq=absfreq)
                    nu0 = math.sqrt(m2 / m0) / (2 * math.pi)
                    z44 = math.sqrt(2 * m0 * math.log(nu0 / 0.044)) if nu0 > 0.044 else float("nan")
                    print("%+d  %+d  %3.0f  %3.0f  %d | %5.3f %6.4f | %.4f %.4f %.4f | %.2f" % (
                        s_p, s_w, xp, spread, absfreq, math.sqrt(m0), nu0,
                        rate(m0, m2, 2.88), rate(m0, m2, 3.36), rate(m0, m2, 3.88), z44))
