//! Wageningen B-series open-water propeller (thesis ch. 2.3, eqs. 2.11-2.13).
//!
//! The Oosterveld & van Oossanen (1975) polynomials K = sum C J^s (P/D)^t (Ae/A0)^u Z^v are
//! collapsed on load into cubics in J for the chosen P/D, Ae/A0 and Z, so each evaluation in the
//! time loop costs a few multiplications.

use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// The polynomial table (core/data/wageningen_b_series.csv, with its source line).
const B_SERIES_CSV: &str = include_str!("../../data/wageningen_b_series.csv");

/// Open-water characteristics of one B-series propeller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OpenWater {
    /// kT(J) = kt[0] + kt[1] J + kt[2] J^2 + kt[3] J^3.
    kt: [f64; 4],
    /// kQ(J), same form.
    kq: [f64; 4],
    /// Advance ratio of zero thrust [-]; the single-quadrant model holds J in [0, j_max].
    pub j_max: f64,
}

/// Thrust and torque of one propeller at one instant.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PropellerLoad {
    /// Thrust T_p \[N\] (eq. 2.13).
    pub thrust_n: f64,
    /// Shaft torque Q_p [N m] (eq. 2.13), including the rotative efficiency.
    pub torque_nm: f64,
    /// Advance ratio J [-] (eq. 2.12), as used (clamped to the single-quadrant range).
    pub advance_ratio: f64,
}

/// What a propeller load depends on besides shaft and advance speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Conditions {
    /// Diameter D \[m\].
    pub diameter_m: f64,
    /// Water density [kg/m^3].
    pub rho: f64,
    /// Relative rotative efficiency eta_R [-] (divides the torque, eq. 2.11).
    pub rotative_efficiency: f64,
    /// Loss coefficients beta_T, beta_Q of eq. 2.13 [-].
    pub beta_t: f64,
    pub beta_q: f64,
}

impl Conditions {
    /// Open water, no losses, eta_R = 1.
    pub fn open_water(diameter_m: f64, rho: f64) -> Conditions {
        Conditions { diameter_m, rho, rotative_efficiency: 1.0, beta_t: 1.0, beta_q: 1.0 }
    }
}

fn poly3(c: &[f64; 4], x: f64) -> f64 {
    ((c[3] * x + c[2]) * x + c[1]) * x + c[0]
}

fn int_pow(x: f64, n: u32) -> f64 {
    // Repeated multiplication: bit-identical on every platform (powi is not guaranteed to be).
    let mut r = 1.0;
    for _ in 0..n {
        r *= x;
    }
    r
}

impl OpenWater {
    /// Collapses the B-series polynomials for one geometry.
    pub fn b_series(pitch_ratio: f64, blade_area_ratio: f64, blades: u32) -> Result<OpenWater, String> {
        let mut kt = [0.0; 4];
        let mut kq = [0.0; 4];
        let mut n_t = 0;
        let mut n_q = 0;
        for (lineno, line) in B_SERIES_CSV.lines().enumerate() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') || line.starts_with("coefficient_of") {
                continue;
            }
            let f: Vec<&str> = line.split(',').collect();
            let bad = || format!("wageningen_b_series.csv line {}: cannot read '{line}'", lineno + 1);
            if f.len() != 6 {
                return Err(bad());
            }
            let c: f64 = f[1].parse().map_err(|_| bad())?;
            let e: Vec<u32> = f[2..6].iter().map(|x| x.parse::<u32>()).collect::<Result<_, _>>().map_err(|_| bad())?;
            if e[0] > 3 {
                return Err(bad());
            }
            let term = c * int_pow(pitch_ratio, e[1]) * int_pow(blade_area_ratio, e[2]) * int_pow(blades as f64, e[3]);
            match f[0] {
                "KT" => {
                    kt[e[0] as usize] += term;
                    n_t += 1;
                }
                "KQ" => {
                    kq[e[0] as usize] += term;
                    n_q += 1;
                }
                _ => return Err(bad()),
            }
        }
        if n_t != 39 || n_q != 47 {
            return Err(format!("wageningen_b_series.csv: expected 39 KT and 47 KQ terms, found {n_t} and {n_q}"));
        }
        let mut ow = OpenWater { kt, kq, j_max: 0.0 };
        // Zero-thrust advance ratio by bisection on [0, 2]: kT falls monotonically in the first quadrant.
        if ow.kt(0.0) <= 0.0 || ow.kt(2.0) > 0.0 {
            return Err("B-series thrust coefficient has no zero in J = 0..2 for this geometry".into());
        }
        ow.j_max = crate::numerics::bisect(|j| ow.kt(j), 0.0, 2.0, 80);
        Ok(ow)
    }

    /// From the scenario's propeller parameters.
    pub fn from_params(p: &PropellerParams) -> Result<OpenWater, String> {
        OpenWater::b_series(p.pitch_ratio, p.blade_area_ratio, p.blades)
    }

    /// Thrust coefficient kT(J) [-].
    pub fn kt(&self, j: f64) -> f64 {
        poly3(&self.kt, j)
    }

    /// Torque coefficient kQ(J) [-].
    pub fn kq(&self, j: f64) -> f64 {
        poly3(&self.kq, j)
    }

    /// Open-water efficiency eta_0 = J kT / (2 pi kQ) [-].
    pub fn efficiency(&self, j: f64) -> f64 {
        let kq = self.kq(j);
        if kq <= 0.0 {
            0.0
        } else {
            j * self.kt(j) / (2.0 * PI * kq)
        }
    }

    /// Thrust and torque (eq. 2.13) at shaft speed `n_hz` [rev/s] and advance speed `va` [m/s]
    /// (eq. 2.12: va = u (1 - w)).
    ///
    /// Single-quadrant model: J is held in [0, j_max]; a shaft turning backwards is mirrored
    /// (the four-quadrant model takes over for braking and reversing).
    pub fn load(&self, n_hz: f64, va: f64, c: &Conditions) -> PropellerLoad {
        let Conditions { diameter_m, rho, rotative_efficiency, beta_t, beta_q } = *c;
        let n_abs = n_hz.abs();
        if n_abs < 1e-9 {
            return PropellerLoad { thrust_n: 0.0, torque_nm: 0.0, advance_ratio: self.j_max };
        }
        let j = (va / (n_abs * diameter_m)).clamp(0.0, self.j_max);
        let d2 = diameter_m * diameter_m;
        let n2d4 = rho * n_hz * n_abs * d2 * d2; // signed: rho n |n| D^4
        PropellerLoad {
            thrust_n: beta_t * self.kt(j) * n2d4,
            torque_nm: beta_q * self.kq(j) * n2d4 * diameter_m / rotative_efficiency,
            advance_ratio: j,
        }
    }

    /// Calm-water equilibrium advance ratio J* at which `n_prop` propellers (with beta_T = 1)
    /// balance a resistance R = c_r u^2: n_prop kT(J) rho D^2 (1-w)^2 / J^2 = c_r.
    pub fn equilibrium_advance_ratio(&self, c_r: f64, n_prop: f64, diameter_m: f64, rho: f64, wake: f64) -> f64 {
        let f =
            |j: f64| n_prop * self.kt(j) * rho * diameter_m * diameter_m * (1.0 - wake) * (1.0 - wake) - c_r * j * j;
        crate::numerics::bisect(f, 0.0, self.j_max, 100)
    }
}

/// Four-quadrant open-water data (Fourier series in the hydrodynamic pitch angle).
const FOUR_QUADRANT_CSV: &str = include_str!("../../data/four_quadrant_b4_70.csv");

/// Number of Fourier terms (k = 0..20).
const N_FOURIER: usize = 21;

/// Four-quadrant propeller: thrust and torque for any sign of advance speed and shaft speed, from
/// the Wageningen B4-70 (P/D = 1.0) Fourier series of van Lammeren et al. (1969) as quoted by
/// Smogeli (2006). Used for AC braking (thesis ch. 5.2.2, after Rubis \[60\]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FourQuadrant {
    at: [f64; N_FOURIER],
    bt: [f64; N_FOURIER],
    aq: [f64; N_FOURIER],
    bq: [f64; N_FOURIER],
}

impl FourQuadrant {
    /// The embedded B4-70 series.
    pub fn b4_70() -> Result<FourQuadrant, String> {
        let mut fq =
            FourQuadrant { at: [0.0; N_FOURIER], bt: [0.0; N_FOURIER], aq: [0.0; N_FOURIER], bq: [0.0; N_FOURIER] };
        let mut seen = [false; N_FOURIER];
        for (lineno, line) in FOUR_QUADRANT_CSV.lines().enumerate() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') || line.starts_with("k,") {
                continue;
            }
            let bad = || format!("four_quadrant_b4_70.csv line {}: cannot read '{line}'", lineno + 1);
            let f: Vec<f64> =
                line.split(',').map(|x| x.trim().parse::<f64>()).collect::<Result<_, _>>().map_err(|_| bad())?;
            if f.len() != 5 || f[0] < 0.0 || f[0] as usize >= N_FOURIER {
                return Err(bad());
            }
            let k = f[0] as usize;
            fq.at[k] = f[1];
            fq.bt[k] = f[2];
            fq.aq[k] = f[3];
            fq.bq[k] = f[4];
            seen[k] = true;
        }
        if seen.iter().any(|s| !s) {
            return Err("four_quadrant_b4_70.csv: terms k = 0..20 are not all present".into());
        }
        Ok(fq)
    }

    /// C_T(beta) and C_Q(beta) [-], beta the hydrodynamic pitch angle \[rad\]. The harmonics come from
    /// one sine and cosine by the angle-addition recurrence (cheap and the same on every platform).
    pub fn coefficients(&self, beta: f64) -> (f64, f64) {
        let (s1, c1) = (libm::sin(beta), libm::cos(beta));
        let (mut s, mut c) = (0.0, 1.0);
        let (mut ct, mut cq) = (0.0, 0.0);
        for k in 0..N_FOURIER {
            ct += self.at[k] * c + self.bt[k] * s;
            cq += self.aq[k] * c + self.bq[k] * s;
            let (sn, cn) = (s * c1 + c * s1, c * c1 - s * s1);
            s = sn;
            c = cn;
        }
        (ct, cq)
    }

    /// Thrust \[N\] and shaft torque [N m] at shaft speed `n_hz` [rev/s] and advance speed `va`
    /// [m/s], any signs: beta = atan2(Va, 0.7 pi n D), T = C_T (1/2) rho V_r^2 (pi/4) D^2,
    /// Q = C_Q (1/2) rho V_r^2 (pi/4) D^3 / eta_R, V_r^2 = Va^2 + (0.7 pi n D)^2.
    pub fn load(&self, n_hz: f64, va: f64, c: &Conditions) -> PropellerLoad {
        let Conditions { diameter_m, rho, rotative_efficiency, beta_t, beta_q } = *c;
        let vt = 0.7 * PI * n_hz * diameter_m;
        let vr2 = va * va + vt * vt;
        let beta = libm::atan2(va, vt);
        let (ct, cq) = self.coefficients(beta);
        let q = 0.5 * rho * vr2 * PI / 4.0 * diameter_m * diameter_m;
        let j = if n_hz.abs() > 1e-9 { va / (n_hz * diameter_m) } else { 0.0 };
        PropellerLoad {
            thrust_n: beta_t * ct * q,
            torque_nm: beta_q * cq * q * diameter_m / rotative_efficiency,
            advance_ratio: j,
        }
    }
}

#[cfg(test)]
mod four_quadrant_tests {
    use super::*;

    /// The series against its file's own first-quadrant check values (KT(0) = 0.445,
    /// KT(0.6) = 0.219, KQ(0) = 0.0666, three figures) and against the B4-70 polynomial within 0.02 in KT and 0.0025 in KQ (two fits of the same MARIN tests; they
    /// differ by 0.010 at J = 0 already).
    #[test]
    fn first_quadrant_matches_b_series() {
        let fq = FourQuadrant::b4_70().unwrap();
        let ow = OpenWater::b_series(1.0, 0.70, 4).unwrap();
        let (n, d, rho) = (2.0, 4.0, 1025.0);
        let (d4, d5) = (crate::numerics::powi(d, 4), crate::numerics::powi(d, 5));
        let kt = |j: f64| fq.load(n, j * n * d, &Conditions::open_water(d, rho)).thrust_n / (rho * n * n * d4);
        let kq = |j: f64| fq.load(n, j * n * d, &Conditions::open_water(d, rho)).torque_nm / (rho * n * n * d5);
        assert!((kt(0.0) - 0.445).abs() < 0.0015, "KT(0) = {}", kt(0.0));
        assert!((kt(0.6) - 0.219).abs() < 0.0015, "KT(0.6) = {}", kt(0.6));
        assert!((kq(0.0) - 0.0666).abs() < 0.00015, "KQ(0) = {}", kq(0.0));
        for i in 0..=8 {
            let j = 0.1 * i as f64;
            println!("J {j:.1}: KT {:.4} vs {:.4}, KQ {:.5} vs {:.5}", kt(j), ow.kt(j), kq(j), ow.kq(j));
            assert!((kt(j) - ow.kt(j)).abs() < 0.02, "J = {j}: {} vs {}", kt(j), ow.kt(j));
            assert!((kq(j) - ow.kq(j)).abs() < 0.0025, "J = {j}: {} vs {}", kq(j), ow.kq(j));
        }
    }

    /// Beyond zero thrust the propeller windmills: thrust and torque both reverse (the ship drives the
    /// shaft), and a locked propeller (n = 0) drags.
    #[test]
    fn windmilling_and_locked() {
        let fq = FourQuadrant::b4_70().unwrap();
        let wm = fq.load(1.0, 1.5 * 4.0, &Conditions::open_water(4.0, 1025.0));
        assert!(wm.thrust_n < 0.0 && wm.torque_nm < 0.0, "{wm:?}");
        let locked = fq.load(0.0, 5.0, &Conditions::open_water(4.0, 1025.0));
        assert!(locked.thrust_n < 0.0, "{locked:?}");
    }
}

crate::params! {
    /// Wageningen B-series propeller, one per shaft (eqs. 2.11-2.13, Table 5.1).
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct PropellerParams {
        pub model: PropellerModelKind = PropellerModelKind::BSeries => {
            label: "Propeller model", source: "ch. 2.3 (B-series); ch. 5.2.2 (four-quadrant)", group: "plant",
            help: "The four-quadrant model is needed for braking.",
        },
        pub diameter_m: f64 = 4.5 => {
            label: "Propeller diameter", unit: "m", range: 0.1..=15.0, source: "Table 5.1", group: "plant",
            help: "Diameter D of each propeller.",
        },
        pub pitch_ratio: f64 = 1.0 => {
            label: "Pitch ratio P/D", unit: "-", range: 0.5..=1.4, source: "Table 5.1", group: "plant",
            help: "Within the Wageningen B-series regression (0.5 to 1.4).",
        },
        /// Typical of a five-bladed destroyer propeller sized against cavitation at 30+ knots.
        pub blade_area_ratio: f64 = 0.75 => {
            label: "Blade area ratio Ae/A0", unit: "-", range: 0.3..=1.05,
            source: "our choice: a five-bladed destroyer propeller (not given in the thesis)",
            help: "Expanded blade area over disc area, within the B-series regression.",
        },
        pub blades: u32 = 5 => {
            label: "Blades", unit: "-", range: 2.0..=7.0, source: "our choice: as on the DDG-51 class", group: "plant",
            help: "Number of blades Z, within the Wageningen B-series (2 to 7).",
        },
        /// Holtrop's twin-screw regression, 0.9737 + 0.111 (C_P - 0.0225 lcb) - 0.06325 P/D with
        /// C_P = 0.6, lcb = -1.5 %.
        pub rotative_efficiency: f64 = 0.98 => {
            label: "Relative rotative efficiency eta_R", unit: "-", range: 0.8..=1.2,
            source: "our choice: Holtrop's twin-screw regression",
            help: "Behind-hull over open-water torque efficiency (eq. 2.11).",
        },
        pub shaft_inertia_kg_m2: f64 = 1.33e5 => {
            label: "Shaft line inertia", unit: "kg m²", range: 1.0..=1.0e8, source: "Table 5.1",
            help: "Propeller, shaft and motor rotor of one shaft line.",
        },
        pub beta_t: f64 = 1.0 => {
            label: "Fixed thrust loss beta_T", unit: "-", range: 0.0..=1.0, source: "eq. 2.13: 1 in deep calm water",
            help: "Thrust kept, held for the whole run (waves add their own losses).",
        },
        pub beta_q: f64 = 1.0 => {
            label: "Fixed torque loss beta_Q", unit: "-", range: 0.0..=1.0, source: "eq. 2.13: 1 in deep calm water",
            help: "Torque kept, held for the whole run.",
        },
        /// The blades `model = "geometry"` analyses; the other models ignore it.
        #[serde(skip_serializing_if = "Option::is_none")]
        pub geometry: Option<crate::plant::propeller_geometry::GeometrySpec> = None => {},
    }
}

impl PropellerParams {
    /// The B-series propeller these parameters describe (a "b_series" geometry is its equivalent).
    pub fn b_series_of(&self) -> crate::plant::propeller_geometry::BSeriesOf {
        crate::plant::propeller_geometry::BSeriesOf {
            blades: self.blades,
            pitch_ratio: self.pitch_ratio,
            blade_area_ratio: self.blade_area_ratio,
        }
    }
}

impl crate::params::CrossCheck for PropellerParams {
    fn cross_check(&self, v: &mut crate::checks::Validator) {
        match (&self.geometry, self.model) {
            (Some(g), _) => v.section("geometry", |v| g.validate(&self.b_series_of(), v)),
            (None, PropellerModelKind::Geometry) => v.fail(
                "geometry",
                "null",
                "model = \"geometry\" needs a blade geometry: {\"name\": \"b_series\"} (the ship's B-series \
                 equivalent), \"dtmb4119\", or \"custom\" with its rows",
            ),
            _ => {}
        }
    }
}

crate::choices! {
    /// Which open-water model the propellers follow.
    pub enum PropellerModelKind {
        /// Wageningen B-series polynomials, first quadrant only (eqs. 2.11-2.13).
        BSeries = "b_series", "Wageningen B-series (ahead only)",
        /// Four-quadrant B4-70 Fourier series (ch. 5.2.2): any sign of thrust, torque and speed.
        FourQuadrant = "four_quadrant", "four-quadrant B4-70 (ahead and astern)",
        /// From `propeller.geometry`'s blades (ch. 3.2), first quadrant; the four-quadrant series,
        /// scaled to the geometry's bollard and zero-thrust points, astern and past zero thrust.
        Geometry = "geometry", "from the blade geometry (astern: four-quadrant, scaled)",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// B4-70, P/D = 1.0: the polynomial values quoted in core/data/four_quadrant_b4_70.csv
    /// (kT(0) = 0.455, kT(0.6) = 0.226, kQ(0) = 0.0675), three significant figures.
    #[test]
    fn b4_70_matches_published_values() {
        let ow = OpenWater::b_series(1.0, 0.70, 4).unwrap();
        assert!((ow.kt(0.0) - 0.455).abs() < 0.0015, "kT(0) = {}", ow.kt(0.0));
        assert!((ow.kt(0.6) - 0.226).abs() < 0.0015, "kT(0.6) = {}", ow.kt(0.6));
        assert!((ow.kq(0.0) - 0.0675).abs() < 0.00015, "kQ(0) = {}", ow.kq(0.0));
        // Zero thrust near J = 1.0 to 1.1 for P/D = 1 (Kuiper 1992, B4-70 chart).
        assert!(ow.j_max > 0.95 && ow.j_max < 1.15, "J0 = {}", ow.j_max);
    }

    /// Peak open-water efficiency of B4-70 at P/D = 1 is about 0.68-0.70 near J = 0.8
    /// (Kuiper 1992 charts); tolerance 0.02.
    #[test]
    fn b4_70_peak_efficiency() {
        let ow = OpenWater::b_series(1.0, 0.70, 4).unwrap();
        let (mut best, mut jbest) = (0.0, 0.0);
        for i in 0..1000 {
            let j = i as f64 * ow.j_max / 1000.0;
            if ow.efficiency(j) > best {
                best = ow.efficiency(j);
                jbest = j;
            }
        }
        assert!((best - 0.69).abs() < 0.02, "eta0 max = {best} at J = {jbest}");
        assert!(jbest > 0.7 && jbest < 0.95, "J at eta0 max = {jbest}");
    }

    #[test]
    fn thrust_scales_with_n_squared_at_fixed_j() {
        let ow = OpenWater::b_series(1.0, 0.75, 5).unwrap();
        let ow_45 = Conditions::open_water(4.5, 1025.0);
        let a = ow.load(2.0, 2.0 * 0.5 * 4.5, &ow_45);
        let b = ow.load(4.0, 4.0 * 0.5 * 4.5, &ow_45);
        assert!((b.thrust_n / a.thrust_n - 4.0).abs() < 1e-12);
        assert!((b.torque_nm / a.torque_nm - 4.0).abs() < 1e-12);
        let stopped = ow.load(0.0, 5.0, &ow_45);
        assert_eq!(stopped.thrust_n, 0.0);
    }
}
