//! Open-water thrust and torque of a propeller from its blade geometry, as a table in the
//! advance ratio built once per geometry (thesis ch. 3.2 and 6.1), with the four-quadrant B4-70
//! series taking over astern and past zero thrust (ch. 5.2.2), scaled to the geometry's own
//! bollard and zero-thrust points so the hand-over is continuous.

use crate::plant::blade::{BladeGeometry, Flow};
use crate::plant::propeller::{Conditions, FourQuadrant, OpenWater, PropellerLoad};
use serde::Serialize;
use std::f64::consts::PI;
use std::sync::{Arc, Mutex, OnceLock};

/// Advance ratios at which the geometry is analysed, from bollard pull to zero thrust.
const ANALYSED: usize = 33;
/// Points of the fine uniform table a time step interpolates linearly in (the monotone cubic
/// through the analysed points, sampled): the table's own error is below 3e-5 in kT.
const TABLE: usize = 513;
/// The search for zero thrust: J from 0 in steps of `J_STEP` up to `J_SEARCH`.
const J_STEP: f64 = 0.05;
const J_SEARCH: f64 = 2.5;
const J_FIRST: f64 = 1.6;
/// Tables kept, the oldest dropped first (a table is 8 kB).
const MAX_TABLES: usize = 8;

/// The geometry's own points the four-quadrant series is scaled to, and where it takes over.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Handover {
    /// Bollard thrust and torque coefficients kT(0), kQ(0) of the geometry \[-\].
    pub kt0: f64,
    pub kq0: f64,
    /// Advance ratio of zero thrust J0 \[-\]: the geometry model holds 0 <= J <= J0 ahead.
    pub j0: f64,
    /// kQ at J0 \[-\] (the torque the series meets there).
    pub kq_j0: f64,
    /// The series' scale factors on C_T and C_Q (the geometry's bollard over the series').
    pub thrust_scale: f64,
    pub torque_scale: f64,
}

/// A propeller whose first quadrant is its geometry's open-water table and whose other
/// quadrants are the scaled four-quadrant series.
#[derive(Debug, Clone, PartialEq)]
pub struct GeometryPropeller {
    /// kT, kQ at J = i J0 / (TABLE - 1).
    kt: Arc<[f64]>,
    kq: Arc<[f64]>,
    pub handover: Handover,
    series: FourQuadrant,
    /// The hydrodynamic pitch angle of J0 (atan2(J0, 0.7 pi)) and the series' own \[rad\].
    beta0: f64,
    beta_s0: f64,
    /// The torque coefficient step at beta0 faded out by beta = pi/2 (continuity) \[-\].
    cq_step: f64,
}

/// What produces the first quadrant: kT and kQ at each advance ratio of `js`.
pub type Curves = dyn Fn(&BladeGeometry, &[f64]) -> Result<Vec<(f64, f64)>, String>;

/// The B-series propeller a geometry is compared with.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SeriesEquivalent {
    /// Blades Z \[-\].
    pub blades: u32,
    /// P/D at 0.7 R \[-\].
    pub pitch_ratio: f64,
    /// Expanded blade area ratio Ae/A0 from the chords \[-\].
    pub area_ratio: f64,
    /// Whether any of the three lay outside the series' polynomial ranges (Z 2..7, P/D 0.5..1.4,
    /// Ae/A0 0.3..1.05) and was held at the range's end.
    pub held: bool,
}

/// The geometry's B-series equivalent: its Z, P/D at 0.7 R and expanded area from the chords,
/// each held within the series' ranges.
pub fn series_equivalent(g: &BladeGeometry) -> SeriesEquivalent {
    let (p, a) = (pitch_at_07(g), area_ratio(g));
    let (blades, pitch_ratio, area_ratio) = (g.blades.clamp(2, 7), p.clamp(0.5, 1.4), a.clamp(0.3, 1.05));
    let held = blades != g.blades || pitch_ratio != p || area_ratio != a;
    SeriesEquivalent { blades, pitch_ratio, area_ratio, held }
}

/// The B-series polynomial of the geometry's equivalent (`series_equivalent`): a comparison
/// curve, not the geometry model's.
pub fn b_series_equivalent_curves(g: &BladeGeometry, js: &[f64]) -> Result<Vec<(f64, f64)>, String> {
    let e = series_equivalent(g);
    let ow = OpenWater::b_series(e.pitch_ratio, e.area_ratio, e.blades)?;
    Ok(js.iter().map(|&j| (ow.kt(j), ow.kq(j))).collect())
}

/// The lifting line's curves (`blade::open_water`) in `flow`: the lattice's comparison.
pub fn lifting_line_curves(flow: Flow) -> impl Fn(&BladeGeometry, &[f64]) -> Result<Vec<(f64, f64)>, String> {
    move |g, js| Ok(crate::plant::blade::open_water(g, js, &flow)?.into_iter().map(|a| (a.kt, a.kq)).collect())
}

/// The vortex lattice's curves of `g` in `flow` (`blade::vortex_lattice`): the geometry model's
/// table. The lattice is built once for `g` (its wake table kept between calls); the closure's
/// own geometry argument is not read.
pub fn lattice_curves(g: &BladeGeometry, flow: Flow) -> Result<Box<Curves>, String> {
    let lattice = crate::plant::blade::vortex_lattice::Lattice::new(g, &flow)?;
    Ok(Box::new(move |_: &BladeGeometry, js: &[f64]| {
        Ok(lattice.curve(js)?.into_iter().map(|a| (a.kt, a.kq)).collect())
    }))
}

/// Local P/D at r/R = 0.7, linear between rows \[-\].
pub fn pitch_at_07(g: &BladeGeometry) -> f64 {
    let r = &g.rows;
    let i = r.iter().position(|x| x.r_r >= 0.7).unwrap_or(r.len() - 1).max(1);
    let (a, b) = (&r[i - 1], &r[i]);
    let w = ((0.7 - a.r_r) / (b.r_r - a.r_r)).clamp(0.0, 1.0);
    a.p_d + w * (b.p_d - a.p_d)
}

/// Expanded blade area ratio Ae/A0 = (2 Z / pi) times the integral of c/D over r/R from the hub
/// to the tip \[-\]: the root chord held down to the hub, trapezoids between rows, and an
/// elliptic tip (c proportional to sqrt(1 - r/R)) over the last interval when its chord is 0.
pub fn area_ratio(g: &BladeGeometry) -> f64 {
    let r = &g.rows;
    let n = r.len();
    let tip = r[n - 1].c_d <= 0.0;
    let inner = if tip { n - 1 } else { n };
    let mut int = r[0].c_d * (r[0].r_r - g.hub_ratio).max(0.0);
    int += r[..inner].windows(2).map(|w| 0.5 * (w[0].c_d + w[1].c_d) * (w[1].r_r - w[0].r_r)).sum::<f64>();
    if tip {
        int += 2.0 / 3.0 * r[n - 2].c_d * (1.0 - r[n - 2].r_r);
    }
    2.0 * g.blades as f64 * int / PI
}

/// C_T or C_Q of the four-quadrant convention from kT or kQ at J: 8 K / (pi (J^2 + (0.7 pi)^2)).
fn to_c(k: f64, j: f64) -> f64 {
    8.0 * k / (PI * (j * j + 0.49 * PI * PI))
}

/// Fritsch-Carlson monotone cubic through (x, y) on uniform x, evaluated at `at`.
fn monotone_cubic(x: &[f64], y: &[f64], at: f64) -> f64 {
    let n = x.len();
    let h = x[1] - x[0];
    let i = (((at - x[0]) / h) as usize).min(n - 2);
    let d: Vec<f64> = y.windows(2).map(|w| (w[1] - w[0]) / h).collect();
    let slope = |k: usize| -> f64 {
        if k == 0 {
            d[0]
        } else if k == n - 1 {
            d[n - 2]
        } else if d[k - 1] * d[k] <= 0.0 {
            0.0
        } else {
            // Harmonic mean: keeps the cubic within the data's monotone pieces.
            2.0 * d[k - 1] * d[k] / (d[k - 1] + d[k])
        }
    };
    let (m0, m1) = (slope(i), slope(i + 1));
    let t = ((at - x[i]) / h).clamp(0.0, 1.0);
    let (t2, t3) = (t * t, t * t * t);
    (2.0 * t3 - 3.0 * t2 + 1.0) * y[i]
        + (t3 - 2.0 * t2 + t) * h * m0
        + (-2.0 * t3 + 3.0 * t2) * y[i + 1]
        + (t3 - t2) * h * m1
}

impl GeometryPropeller {
    /// The table of `g` from the vortex lattice in `flow`, remembered per geometry and flow (a run,
    /// its Monte Carlo trials and the page's repeated runs build it once).
    pub fn new(g: &BladeGeometry, flow: Flow) -> Result<GeometryPropeller, String> {
        type Cache = Mutex<Vec<((BladeGeometry, Flow), GeometryPropeller)>>;
        static CACHE: OnceLock<Cache> = OnceLock::new();
        let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
        if let Ok(c) = cache.lock() {
            if let Some((_, p)) = c.iter().find(|((kg, kf), _)| kg == g && *kf == flow) {
                return Ok(p.clone());
            }
        }
        flow.check().map_err(|e| format!("propeller.geometry: the design flow's {e}"))?;
        let p = GeometryPropeller::build(g, &lattice_curves(g, flow)?)?;
        if let Ok(mut c) = cache.lock() {
            if c.len() >= MAX_TABLES {
                c.remove(0);
            }
            c.push(((g.clone(), flow), p.clone()));
        }
        Ok(p)
    }

    /// Builds the table of `g` from `curves` (not remembered).
    pub fn build(g: &BladeGeometry, curves: &Curves) -> Result<GeometryPropeller, String> {
        // Zero thrust: the first sign change of kT on a coarse grid (up to J_FIRST, where most
        // propellers have theirs, then on to J_SEARCH), then secant steps.
        let grid = |to: f64| -> Vec<f64> { (0..=(to / J_STEP).round() as usize).map(|i| i as f64 * J_STEP).collect() };
        let mut coarse = grid(J_FIRST);
        let mut k = curves(g, &coarse)?;
        if k.iter().all(|p| p.0 > 0.0) {
            coarse = grid(J_SEARCH);
            k = curves(g, &coarse)?;
        }
        if !(k[0].0 > 0.0 && k[0].1 > 0.0) {
            return Err(format!(
                "propeller.geometry: the blades give no bollard thrust and torque (kT(0) = {:.4}, kQ(0) = {:.5})",
                k[0].0, k[0].1
            ));
        }
        let Some(i) = k.iter().position(|p| p.0 <= 0.0) else {
            return Err(format!("propeller.geometry: thrust does not fall to zero by J = {J_SEARCH}"));
        };
        let (mut a, mut b, mut ka, mut kb) = (coarse[i - 1], coarse[i], k[i - 1].0, k[i].0);
        for _ in 0..6 {
            let m = a - ka * (b - a) / (kb - ka);
            let km = curves(g, &[m])?[0].0;
            if km > 0.0 {
                (a, ka) = (m, km);
            } else {
                (b, kb) = (m, km);
            }
            if (b - a) < 1e-9 || km.abs() < 1e-10 {
                break;
            }
        }
        let j0 = a - ka * (b - a) / (kb - ka);
        let xs: Vec<f64> = (0..ANALYSED).map(|i| j0 * i as f64 / (ANALYSED - 1) as f64).collect();
        let k = curves(g, &xs)?;
        let (mut kts, kqs): (Vec<f64>, Vec<f64>) = k.into_iter().unzip();
        kts[ANALYSED - 1] = 0.0;
        if let Some(bad) = kts.iter().chain(&kqs).find(|v| !v.is_finite()) {
            return Err(format!("propeller.geometry: the open-water analysis gave {bad}"));
        }
        let fine = |ys: &[f64]| -> Arc<[f64]> {
            (0..TABLE).map(|i| monotone_cubic(&xs, ys, j0 * i as f64 / (TABLE - 1) as f64)).collect()
        };
        let (kt, kq) = (fine(&kts), fine(&kqs));
        let series = FourQuadrant::b4_70()?;
        let (ct_s0, cq_s0) = series.coefficients(0.0);
        let beta_s0 = crate::numerics::bisect(|b| series.coefficients(b).0, 0.0, 0.5 * PI, 80);
        let beta0 = libm::atan2(j0, 0.7 * PI);
        let thrust_scale = to_c(kt[0], 0.0) / ct_s0;
        let torque_scale = to_c(kq[0], 0.0) / cq_s0;
        let kq_j0 = kq[TABLE - 1];
        let cq_step = to_c(kq_j0, j0) - torque_scale * series.coefficients(beta_s0).1;
        Ok(GeometryPropeller {
            handover: Handover { kt0: kt[0], kq0: kq[0], j0, kq_j0, thrust_scale, torque_scale },
            kt,
            kq,
            series,
            beta0,
            beta_s0,
            cq_step,
        })
    }

    /// kT and kQ of the table at 0 <= J <= J0 (linear between its points) \[-\].
    pub fn table(&self, j: f64) -> (f64, f64) {
        let x = (j / self.handover.j0).clamp(0.0, 1.0) * (TABLE - 1) as f64;
        let i = (x as usize).min(TABLE - 2);
        let w = x - i as f64;
        (self.kt[i] + w * (self.kt[i + 1] - self.kt[i]), self.kq[i] + w * (self.kq[i + 1] - self.kq[i]))
    }

    /// C_T, C_Q \[-\] outside the first quadrant: the series at the hydrodynamic pitch angle
    /// `beta` \[rad\] mapped so its zero thrust meets the geometry's (beta0 to pi onto beta_s0 to pi;
    /// negative angles unchanged), scaled to the geometry's bollard, with the torque's step at
    /// beta0 faded out linearly by pi/2.
    pub fn handover_coefficients(&self, beta: f64) -> (f64, f64) {
        let b = if beta > self.beta0 {
            self.beta_s0 + (beta - self.beta0) * (PI - self.beta_s0) / (PI - self.beta0)
        } else {
            beta
        };
        let (ct, cq) = self.series.coefficients(b);
        let fade = if beta > self.beta0 { (1.0 - (beta - self.beta0) / (0.5 * PI - self.beta0)).max(0.0) } else { 0.0 };
        (self.handover.thrust_scale * ct, self.handover.torque_scale * cq + fade * self.cq_step)
    }

    /// Whether shaft speed `n_hz` and advance speed `va` lie in the geometry's own range
    /// (ahead, 0 <= J <= J0).
    pub fn in_first_quadrant(&self, n_hz: f64, va: f64, diameter_m: f64) -> bool {
        n_hz > 1e-9 && va >= 0.0 && va <= self.handover.j0 * n_hz * diameter_m
    }

    /// Thrust and torque (eq. 2.13) at shaft speed `n_hz` [rev/s] and advance speed `va` [m/s],
    /// any signs; `advance_ratio` is J = va / (n D), signed (0 with the shaft stopped).
    pub fn load(&self, n_hz: f64, va: f64, c: &Conditions) -> PropellerLoad {
        let Conditions { diameter_m, rho, rotative_efficiency, beta_t, beta_q } = *c;
        let d2 = diameter_m * diameter_m;
        if self.in_first_quadrant(n_hz, va, diameter_m) {
            let j = va / (n_hz * diameter_m);
            let (kt, kq) = self.table(j);
            let n2d4 = rho * n_hz * n_hz * d2 * d2;
            return PropellerLoad {
                thrust_n: beta_t * kt * n2d4,
                torque_nm: beta_q * kq * n2d4 * diameter_m / rotative_efficiency,
                advance_ratio: j,
            };
        }
        // The four-quadrant form of FourQuadrant::load.
        let vt = 0.7 * PI * n_hz * diameter_m;
        let (ct, cq) = self.handover_coefficients(libm::atan2(va, vt));
        let q = 0.5 * rho * (va * va + vt * vt) * PI / 4.0 * d2;
        PropellerLoad {
            thrust_n: beta_t * ct * q,
            torque_nm: beta_q * cq * q * diameter_m / rotative_efficiency,
            advance_ratio: if n_hz.abs() > 1e-9 { va / (n_hz * diameter_m) } else { 0.0 },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plant::propeller_geometry::b_series_equivalent;

    fn kt_kq(p: &GeometryPropeller, n: f64, va: f64) -> (f64, f64) {
        let (d, rho) = (4.0, 1025.0);
        let l = p.load(n, va, &Conditions::open_water(d, rho));
        // Normalised by V_r^2 so both sides of a quadrant boundary compare (C_T, C_Q).
        let vt = 0.7 * PI * n * d;
        let q = 0.5 * rho * (va * va + vt * vt) * PI / 4.0 * d * d;
        (l.thrust_n / q, l.torque_nm / (q * d))
    }

    /// The hand-over is continuous: across J = 0 ahead, across J0, across a stopped shaft
    /// (beta = pi/2) and across beta = pi, C_T and C_Q on the two sides of each boundary differ by
    /// less than 1e-3 of the bollard values at a step of 1e-7 in the angle.
    #[test]
    fn handover_is_continuous() {
        let g = b_series_equivalent(5, 1.0, 0.75, 0.167).unwrap();
        let p = GeometryPropeller::new(&g, Flow::sea_water(4.0, 5.0)).unwrap();
        let (ct0, cq0) = kt_kq(&p, 1.0, 0.0);
        let d = 4.0;
        let at = |beta: f64| {
            let (n, va) = (libm::cos(beta) / (0.7 * PI * d), libm::sin(beta));
            kt_kq(&p, n, va)
        };
        for beta in [0.0, p.beta0, 0.5 * PI, PI - 1e-7] {
            let (a, b) = (at(beta - 1e-7), at(beta + 1e-7));
            assert!((a.0 - b.0).abs() < 1e-3 * ct0, "C_T at {beta}: {a:?} vs {b:?}");
            assert!((a.1 - b.1).abs() < 1e-3 * cq0, "C_Q at {beta}: {a:?} vs {b:?}");
        }
        // Past zero thrust the propeller windmills; astern the thrust is astern.
        let (ct, _) = at(p.beta0 + 0.3);
        assert!(ct < 0.0, "past J0: C_T = {ct}");
        assert!(at(PI).0 < 0.0, "astern");
    }

    /// With the B-series curves the first quadrant is the polynomial within the table's own
    /// interpolation error (3e-5 in kT, 3e-6 in kQ, largest in the end intervals) and J0 its zero thrust within 1e-6.
    #[test]
    fn table_reproduces_its_curves() {
        let g = b_series_equivalent(5, 1.0, 0.75, 0.167).unwrap();
        let p = GeometryPropeller::build(&g, &b_series_equivalent_curves).unwrap();
        let ow = OpenWater::b_series(pitch_at_07(&g), area_ratio(&g), 5).unwrap();
        assert!((p.handover.j0 - ow.j_max).abs() < 1e-6, "{} vs {}", p.handover.j0, ow.j_max);
        for i in 0..=40 {
            let j = p.handover.j0 * i as f64 / 40.0;
            let (kt, kq) = p.table(j);
            assert!((kt - ow.kt(j)).abs() < 3e-5 && (kq - ow.kq(j)).abs() < 3e-6, "J {j}: {kt} {kq}");
        }
    }
}

#[cfg(test)]
mod lifting_line_tests {
    use super::*;
    use crate::plant::blade::Flow;

    /// The table builds from the vortex lattice for DTMB 4119 at full scale (4.5 m, 3.5 rev/s):
    /// bollard kT and kQ positive, J0 between 1.0 and 1.6 (the measured curve reaches kT 0 near
    /// J = 1.2, Jessup 1989), and the hand-over scaled to it; the lifting line's table beside it
    /// builds too. Prints the build times.
    #[test]
    fn builds_from_the_lattice_and_the_lifting_line() {
        let g = crate::plant::propeller_geometry::GeometrySpec { name: "dtmb4119".into(), ..Default::default() }
            .resolve(&crate::plant::propeller::PropellerParams::default().b_series_of())
            .unwrap();
        let flow = Flow::sea_water(4.5, 3.5);
        for (name, curves) in [
            ("vortex lattice", lattice_curves(&g, flow).unwrap()),
            ("lifting line", Box::new(lifting_line_curves(flow))),
        ] {
            let t = std::time::Instant::now();
            let p = GeometryPropeller::build(&g, &curves).unwrap();
            println!("4119 table from the {name}: {:?} in {:?}", p.handover, t.elapsed());
            assert!(p.handover.kt0 > 0.0 && p.handover.kq0 > 0.0);
            assert!(p.handover.j0 > 1.0 && p.handover.j0 < 1.6, "J0 = {}", p.handover.j0);
        }
    }
}

#[cfg(test)]
mod run_tests {
    use crate::scenario::presets::preset;
    use crate::scenario::PropellerModelKind;

    /// head-seas-ss6 on the ship's B-series-equivalent geometry (Z 5, P/D 1.0, Ae/A0 0.75) through
    /// the vortex lattice's table, against the polynomial of the same Z, P/D, Ae/A0. The two curves
    /// are different models: at the run's mean J 0.735 the lattice's kT is 9 % and its kQ 6 % above
    /// the polynomial's (on B4-70 it is within 7 % over J 0.2-0.8, docs/propeller.md). Measured:
    /// turbine power -4.1 %, shaft speed -2.3 %, ship speed -0.24 %, thrust -0.7 %. Asserted: power
    /// within 5 % and rpm within 3 % (the stronger kT turns the shaft slower; power follows kQ n^3),
    /// ship speed and thrust within 1 % (the speed order holds the speed, so the thrust is the hull's
    /// resistance at it, whichever curve makes it). The run stays in the first quadrant, and the
    /// summary's note names the lattice.
    #[test]
    fn head_seas_on_the_b_series_equivalent_matches_the_polynomial() {
        let base = preset("head-seas-ss6").unwrap();
        let mut geo = base.clone();
        geo.propeller.model = PropellerModelKind::Geometry;
        geo.propeller.geometry = Some(Default::default());
        let g = geo.propeller.geometry.as_ref().unwrap().resolve(&geo.propeller.b_series_of()).unwrap();
        let flow = geo.propeller_design_flow();
        let t = std::time::Instant::now();
        let p = super::GeometryPropeller::build(&g, &super::lattice_curves(&g, flow).unwrap()).unwrap();
        println!("table for the default geometry at {flow:?}: {:?} in {:?}", p.handover, t.elapsed());
        let (a, b) = (crate::sim::run(&base).unwrap().summary, crate::sim::run(&geo).unwrap().summary);
        let j = b.signals["advance_ratio"].mean;
        let ow = crate::plant::propeller::OpenWater::from_params(&base.propeller).unwrap();
        println!(
            "mean J {j:.3}: vortex lattice kT {:.4} kQ {:.5}, polynomial kT {:.4} kQ {:.5}",
            p.table(j).0,
            p.table(j).1,
            ow.kt(j),
            ow.kq(j)
        );
        for (name, tol) in [("p_turbine_w", 0.05), ("ship_speed_kn", 0.01), ("prop_rpm", 0.03), ("thrust_kn", 0.01)] {
            let (x, y) = (a.signals[name].mean, b.signals[name].mean);
            println!("{name}: b_series {x:.5e}, geometry {y:.5e}, {:+.2} %", 100.0 * (y - x) / x);
            assert!((y - x).abs() < tol * x.abs(), "{name}: {x} vs {y}");
        }
        assert!(a.propeller.is_none());
        let note = b.propeller.unwrap();
        assert!(note.note.contains("from the vortex lattice"), "{}", note.note);
        assert_eq!(note.rows_handed_over, 0, "{}", note.note);
    }
}
