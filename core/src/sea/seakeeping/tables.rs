//! Precomputed seakeeping tables (thesis ch. 2.5.4, last paragraph): RAOs and second-order mean
//! forces on a grid of wave frequency x ship speed x heading, and their interpolation for the
//! time-domain simulation; plus the JSON of the `section` and `rao` commands.

use super::conformal::{bulb, section_map, Form, SectionMap};
use super::motions::{response, response_as, Response};
use super::radiation::{default_multipoles, solve, Contour};
use super::strip::{default_omega_grid, RadiationTable, Ship};
use crate::as_printed::AsPrintedParams;
use crate::numerics::interp::bracket;
use num_complex::Complex64 as C;
use serde::{Deserialize, Serialize};
use serde_json::Value;
use std::f64::consts::PI;

crate::params! {
    /// The table grid (part of the scenario). Headings cover 0..180 deg; waves from port use the
    /// mirror image (sway, roll, yaw, the drift force and the drift moment change sign). The
    /// default, 40 x 8 x 13: 0.2-2.0 rad/s covers the Bretschneider sea states 2-6 of Table 2.4
    /// beyond their spectra's 1 % points; 0-35 kn in 5 kn steps (the studies' 20, 25 and 30 kn
    /// on nodes: between the 7 kn steps of the thesis-sized 6 speeds the hub motion's variance in
    /// SS6 at 25 kn came out 1.3 % lower); 15 deg steps in heading.
    #[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct SeakeepingGrid {
        pub omega_min: f64 = 0.2 => {
            label: "RAO table: lowest frequency", unit: "rad/s", range: 0.05..=5.0,
            source: "our choice: below the 1 % point of sea state 6", help: "Wave frequencies from this one...",
        },
        pub omega_max: f64 = 2.0 => {
            label: "RAO table: highest frequency", unit: "rad/s", range: 0.06..=6.0,
            source: "our choice: above the 1 % point of sea state 2", help: "...to this one, evenly spaced.",
        },
        pub n_omega: usize = 40 => {
            label: "RAO table: frequencies", unit: "-", range: 2.0..=400.0, source: "our choice",
            help: "Number of wave frequencies of the table.",
        },
        pub speed_max_kn: f64 = 35.0 => {
            label: "RAO table: top speed", unit: "kn", range: 0.0..=60.0, source: "our choice: above the ship's top speed",
            help: "Speeds from 0 to this one.",
        },
        pub n_speed: usize = 8 => {
            label: "RAO table: speeds", unit: "-", range: 1.0..=60.0, source: "our choice: 5 kn steps, 25 kn on a node",
            help: "Number of ship speeds of the table.",
        },
        pub n_heading: usize = 13 => {
            label: "RAO table: headings", unit: "-", range: 2.0..=73.0, source: "our choice: 15 deg steps",
            help: "Number of headings from 0 (following) to 180 deg (head seas).",
        },
        /// The significant amplitude of the sea sailed in is the natural choice (SS6: 2.5 m).
        pub roll_wave_amplitude_m: f64 = 2.5 => {
            label: "Roll damping wave amplitude", unit: "m", range: 0.01..=20.0,
            source: "our choice: sea state 6's significant amplitude",
            help: "Wave amplitude at which the nonlinear roll damping is linearised (eq. 2.45).",
        },
    }
}

/// Most points of an RAO table (frequencies x speeds x headings; the default has 4,160): about
/// 40 MB of table.
pub const MAX_RAO_POINTS: usize = 200_000;

/// Most work of building an RAO table: grid points times the hull's strips (the DTMB 5415 on the
/// default grid: 4,160 x 29 = 1.2e5, 0.3 s natively; 1.5e7 is about 30 s). Checked before the
/// build starts.
pub const MAX_RAO_WORK: f64 = 1.5e7;

/// Largest real or imaginary part of an RAO in a table [m/m or rad/m], and magnitude of a mean force or moment per
/// wave amplitude squared [N/m^2, N m/m^2]: far above any ship's (the 5415's heave RAO is at
/// most about 1.2, its drift forces about 1e5), far below what breaks a run.
pub const MAX_RAO_MAGNITUDE: f64 = 1.0e3;
pub const MAX_DRIFT_MAGNITUDE: f64 = 1.0e12;

impl crate::params::CrossCheck for SeakeepingGrid {
    fn cross_check(&self, v: &mut crate::checks::Validator) {
        let points = self.n_omega.saturating_mul(self.n_speed).saturating_mul(self.n_heading);
        if points > MAX_RAO_POINTS {
            v.fail(
                "n_omega",
                self.n_omega,
                format!(
                    "with n_speed = {} and n_heading = {} the table has {points} points; at most {MAX_RAO_POINTS}: fewer frequencies, speeds or headings",
                    self.n_speed, self.n_heading
                ),
            );
        }
        if self.omega_max < self.omega_min + 0.01 {
            v.fail(
                "omega_max",
                crate::checks::num(self.omega_max),
                format!("must be above {} by 0.01 or more", v.path("omega_min")),
            );
        }
    }
}

impl SeakeepingGrid {
    /// Errors name the field, its value and the allowed range.
    pub fn validate(&self) -> Result<(), String> {
        let mut v = crate::checks::Validator::new();
        v.section("seakeeping.grid", |v| crate::params::Section::check_fields(self, v));
        v.finish().map_err(|e| e.to_string())
    }

    pub fn omegas(&self) -> Vec<f64> {
        lin(self.omega_min, self.omega_max, self.n_omega)
    }
    /// Speeds [m/s].
    pub fn speeds(&self) -> Vec<f64> {
        lin(0.0, self.speed_max_kn * crate::numerics::units::KNOT_M_S, self.n_speed)
    }
    /// Headings \[rad\].
    pub fn headings(&self) -> Vec<f64> {
        lin(0.0, PI, self.n_heading)
    }
}

fn lin(a: f64, b: f64, n: usize) -> Vec<f64> {
    if n <= 1 {
        return vec![a];
    }
    (0..n).map(|i| a + (b - a) * i as f64 / (n - 1) as f64).collect()
}

/// Runs `f(i)` for every i in 0..n, in any order, side by side where it can: core has no
/// threads ([`Serial`] is a loop), the command line passes one that spreads the parts over its
/// threads.
pub trait ForEach: Sync {
    fn for_each(&self, n: usize, f: &(dyn Fn(usize) + Sync));
}

/// One part after another.
pub struct Serial;

impl ForEach for Serial {
    fn for_each(&self, n: usize, f: &(dyn Fn(usize) + Sync)) {
        (0..n).for_each(f)
    }
}

/// `f(i)` for i in 0..n by `each`, in the order of i.
fn collect<T: Send>(each: &dyn ForEach, n: usize, f: &(dyn Fn(usize) -> T + Sync)) -> Result<Vec<T>, String> {
    let slots: Vec<std::sync::Mutex<Option<T>>> = (0..n).map(|_| std::sync::Mutex::new(None)).collect();
    each.for_each(n, &|i| {
        let v = f(i);
        if let Ok(mut s) = slots[i].lock() {
            *s = Some(v);
        }
    });
    let parts: Vec<T> = slots.into_iter().filter_map(|s| s.into_inner().ok().flatten()).collect();
    if parts.len() == n {
        Ok(parts)
    } else {
        Err(format!("the RAO table's build lost {} of its {n} parts", n - parts.len()))
    }
}

/// Interpolated response at one (omega0, U, beta).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rao {
    pub omega_e: f64,
    /// Complex RAOs: sway, heave [m/m]; roll, pitch, yaw [rad/m].
    pub sway: C,
    pub heave: C,
    pub roll: C,
    pub pitch: C,
    pub yaw: C,
    /// Mean forces per wave amplitude squared, ship axes [N/m^2]: x (forward) and y (port).
    pub fx: f64,
    pub fy: f64,
    /// Mean yaw moment about the centre of gravity per wave amplitude squared, positive bow to
    /// port (M_add of eqs. 2.19 and 2.24; `Response::drift_moment`) [N m/m^2].
    pub mz: f64,
}

/// RAOs on the grid.
#[derive(Debug, Clone)]
pub struct RaoTable {
    pub grid: SeakeepingGrid,
    omegas: Vec<f64>,
    speeds: Vec<f64>,
    headings: Vec<f64>,
    /// (cos, sin) of every heading (libm, once: `interpolate` weighs the added-resistance force
    /// by them at each corner).
    heading_cs: Vec<(f64, f64)>,
    /// [omega][speed][heading]
    data: Vec<Response>,
}

fn cos_sin(headings: &[f64]) -> Vec<(f64, f64)> {
    headings.iter().map(|&b| (libm::cos(b), libm::sin(b))).collect()
}

impl RaoTable {
    /// Computes the table for `ship`: the sectional coefficients on the encounter-frequency grid,
    /// then strip theory at every grid point.
    pub fn compute(ship: &Ship, grid: &SeakeepingGrid) -> Result<RaoTable, String> {
        Self::compute_as(ship, grid, &AsPrintedParams::default())
    }

    /// `compute` with the strip-theory switches of `printed` (Appendix A, eq. 2.47).
    pub fn compute_as(ship: &Ship, grid: &SeakeepingGrid, printed: &AsPrintedParams) -> Result<RaoTable, String> {
        Self::compute_with(ship, grid, printed, &Serial)
    }

    /// `compute_as` with its independent parts (each strip's sectional coefficients, then each
    /// wave frequency's row of the grid) run by `each`, side by side where it can: the same
    /// arithmetic part by part, so the same bits as one after another.
    pub fn compute_with(
        ship: &Ship,
        grid: &SeakeepingGrid,
        printed: &AsPrintedParams,
        each: &dyn ForEach,
    ) -> Result<RaoTable, String> {
        grid.validate()?;
        let points = grid.n_omega * grid.n_speed * grid.n_heading;
        let work = points as f64 * ship.strips.len() as f64;
        if work > MAX_RAO_WORK {
            return Err(format!(
                "seakeeping.grid: {points} points x {} strips of the hull = {work:.3e} units of work to build the RAO table; at most {MAX_RAO_WORK:e} (about 30 s): fewer grid points (n_omega, n_speed, n_heading) or fewer hull stations",
                ship.strips.len()
            ));
        }
        let omegas_e = default_omega_grid();
        let strips = collect(each, ship.strips.len(), &|i| ship.strip_radiation(i, &omegas_e))?;
        let rad = RadiationTable { omegas: omegas_e, data: strips };
        let (omegas, speeds, headings) = (grid.omegas(), grid.speeds(), grid.headings());
        let rows = collect(each, omegas.len(), &|i| {
            let mut row = Vec::with_capacity(speeds.len() * headings.len());
            for &u in &speeds {
                for &b in &headings {
                    row.push(response_as(ship, &rad, omegas[i], u, b, grid.roll_wave_amplitude_m, printed));
                }
            }
            row
        })?;
        let data = rows.into_iter().flatten().collect();
        let t = RaoTable { grid: *grid, omegas, speeds, heading_cs: cos_sin(&headings), headings, data };
        t.check().map_err(|e| format!("the RAO table of this hull: {e}"))?;
        Ok(t)
    }

    pub fn from_radiation(ship: &Ship, rad: &RadiationTable, grid: &SeakeepingGrid) -> RaoTable {
        Self::from_radiation_as(ship, rad, grid, &AsPrintedParams::default())
    }

    pub fn from_radiation_as(
        ship: &Ship,
        rad: &RadiationTable,
        grid: &SeakeepingGrid,
        printed: &AsPrintedParams,
    ) -> RaoTable {
        let (omegas, speeds, headings) = (grid.omegas(), grid.speeds(), grid.headings());
        let mut data = Vec::with_capacity(omegas.len() * speeds.len() * headings.len());
        for &w in &omegas {
            for &u in &speeds {
                for &b in &headings {
                    data.push(response_as(ship, rad, w, u, b, grid.roll_wave_amplitude_m, printed));
                }
            }
        }
        RaoTable { grid: *grid, omegas, speeds, heading_cs: cos_sin(&headings), headings, data }
    }

    fn idx(&self, i: usize, j: usize, k: usize) -> &Response {
        &self.data[(i * self.speeds.len() + j) * self.headings.len() + k]
    }

    /// Numbers per grid point in `values`.
    pub const VALUES_PER_POINT: usize = 20;

    /// The table as flat numbers (every grid point's response, in the grid's order): what a web
    /// worker that built it hands to the others, so the table is built once. Per point, in order:
    /// 0 omega0, 1 omega_e, 2 k; 3-12 the RAOs sway, heave, roll, pitch, yaw as (re, im) pairs;
    /// 13 f_add, 14 added_resistance, 15 drift_force, 16 added_resistance_gb, 17 b44_viscous,
    /// 18 drift_moment, 19 f_add_sway.
    pub fn values(&self) -> Vec<f64> {
        let mut v = Vec::with_capacity(self.data.len() * Self::VALUES_PER_POINT);
        for r in &self.data {
            v.extend_from_slice(&[r.omega0, r.omega_e, r.k]);
            for c in [r.sway, r.heave, r.roll, r.pitch, r.yaw] {
                v.extend_from_slice(&[c.re, c.im]);
            }
            v.extend_from_slice(&[r.f_add, r.added_resistance, r.drift_force, r.added_resistance_gb, r.b44_viscous]);
            v.push(r.drift_moment);
            v.push(r.f_add_sway);
        }
        v
    }

    /// The table of `grid` from `values` (the same bits as the table they came from).
    pub fn from_values(grid: &SeakeepingGrid, values: &[f64]) -> Result<RaoTable, String> {
        grid.validate()?;
        let (omegas, speeds, headings) = (grid.omegas(), grid.speeds(), grid.headings());
        let n = omegas.len() * speeds.len() * headings.len();
        if values.len() != n * Self::VALUES_PER_POINT || !values.iter().all(|v| v.is_finite()) {
            return Err(format!("an RAO table of this grid has {} finite values", n * Self::VALUES_PER_POINT));
        }
        let c = |v: &[f64], i: usize| C::new(v[i], v[i + 1]);
        let data = values
            .chunks_exact(Self::VALUES_PER_POINT)
            .map(|v| Response {
                omega0: v[0],
                omega_e: v[1],
                k: v[2],
                sway: c(v, 3),
                heave: c(v, 5),
                roll: c(v, 7),
                pitch: c(v, 9),
                yaw: c(v, 11),
                f_add: v[13],
                added_resistance: v[14],
                drift_force: v[15],
                added_resistance_gb: v[16],
                b44_viscous: v[17],
                drift_moment: v[18],
                f_add_sway: v[19],
            })
            .collect();
        let t = RaoTable { grid: *grid, omegas, speeds, heading_cs: cos_sin(&headings), headings, data };
        t.check().map_err(|e| format!("RAO table values: {e}"))?;
        Ok(t)
    }

    /// What every table must hold, computed here or loaded from another worker: each point's
    /// wave frequency is its grid's, its encounter frequency and wave number positive and within
    /// what the grid allows, its RAOs' parts within [`MAX_RAO_MAGNITUDE`], its mean forces and moments
    /// within [`MAX_DRIFT_MAGNITUDE`], every number finite.
    pub fn check(&self) -> Result<(), String> {
        let (ns, nh) = (self.speeds.len(), self.headings.len());
        let u_max = self.speeds.last().copied().unwrap_or(0.0);
        for (at, r) in self.data.iter().enumerate() {
            let w = self.omegas[at / (ns * nh)];
            // omega_e = |omega0 - k U cos(beta)|, k = omega0^2 / g: at most omega0 + omega0^2 U / 9.
            let we_max = w + w * w * u_max / 9.0 + 1.0;
            let rao = [r.sway, r.heave, r.roll, r.pitch, r.yaw]
                .iter()
                .map(|c| c.re.abs().max(c.im.abs()))
                .fold(0.0, f64::max);
            let drift = [
                r.f_add,
                r.added_resistance,
                r.drift_force,
                r.added_resistance_gb,
                r.b44_viscous,
                r.drift_moment,
                r.f_add_sway,
            ]
            .iter()
            .map(|x| x.abs())
            .fold(0.0, f64::max);
            let finite = [r.omega0, r.omega_e, r.k, rao, drift].iter().all(|x| x.is_finite());
            let why = if !finite {
                Some("a number that is not finite".to_string())
            } else if r.omega0 != w {
                Some(format!("omega0 = {}: the grid's frequency there is {w}", crate::checks::num(r.omega0)))
            } else if !(r.omega_e > 0.0 && r.omega_e <= we_max) {
                Some(format!("omega_e = {}: must be in (0, {we_max:.3}]", crate::checks::num(r.omega_e)))
            } else if !(r.k > 0.0 && r.k <= w * w / 9.0) {
                Some(format!("k = {}: must be omega0^2 / g", crate::checks::num(r.k)))
            } else if rao > MAX_RAO_MAGNITUDE {
                Some(format!("an RAO part of {}: at most {MAX_RAO_MAGNITUDE:e}", crate::checks::num(rao)))
            } else if drift > MAX_DRIFT_MAGNITUDE {
                Some(format!(
                    "a mean force or moment of {}: at most {MAX_DRIFT_MAGNITUDE:e}",
                    crate::checks::num(drift)
                ))
            } else {
                None
            };
            if let Some(why) = why {
                return Err(format!("point {at} (of {}): {why}", self.data.len()));
            }
        }
        Ok(())
    }

    /// Interpolation (complex RAOs component-wise) at wave frequency `omega0` [rad/s], speed `u`
    /// [m/s] and heading `beta` [rad, any angle; 180 deg head seas]: Catmull-Rom's cubic in
    /// frequency (`frequency_weights`), linear in speed and heading; values outside the grid are
    /// held at its edge.
    pub fn interpolate(&self, omega0: f64, u: f64, beta: f64) -> Rao {
        // Fold the heading into [0, pi]; beyond pi the waves come from port: mirror.
        let b = beta.rem_euclid(2.0 * PI);
        let (bf, mirror) = if b > PI { (2.0 * PI - b, true) } else { (b, false) };
        let (i0, fi) = bracket(&self.omegas, omega0);
        let (j0, fj) = bracket(&self.speeds, u);
        let (k0, fk) = bracket(&self.headings, bf);
        // Complex values are interpolated component-wise (amplitude-and-phase interpolation was
        // tried and is less accurate on the default grid: the heave RAO's sharp drop past the
        // resonance dominates the error, not the turning phase).
        let mut acc = [C::new(0.0, 0.0); 5];
        let (mut fx, mut fy, mut mz, mut we) = (0.0, 0.0, 0.0, 0.0);
        for (i, wi) in frequency_weights(self.omegas.len(), i0, fi) {
            for (dj, wj) in [(0, 1.0 - fj), (1, fj)] {
                for (dk, wk) in [(0, 1.0 - fk), (1, fk)] {
                    let w = wi * wj * wk;
                    if w == 0.0 {
                        continue;
                    }
                    let r = self.idx(i, (j0 + dj).min(self.speeds.len() - 1), (k0 + dk).min(self.headings.len() - 1));
                    for (a, v) in acc.iter_mut().zip([r.sway, r.heave, r.roll, r.pitch, r.yaw]) {
                        *a += v * w;
                    }
                    let (cos_hb, sin_hb) = self.heading_cs[(k0 + dk).min(self.headings.len() - 1)];
                    fx += w * cos_hb * r.f_add;
                    fy += w * sin_hb * r.f_add_sway;
                    // The moment is interpolated as stored (it carries its own sin(beta) and lever).
                    mz += w * r.drift_moment;
                    we += w * r.omega_e;
                }
            }
        }
        let s = if mirror { -1.0 } else { 1.0 };
        Rao {
            omega_e: we,
            sway: acc[0] * s,
            heave: acc[1],
            roll: acc[2] * s,
            pitch: acc[3],
            yaw: acc[4] * s,
            fx,
            fy: fy * s,
            mz: mz * s,
        }
    }
}

/// The weights of the table's frequencies at `omega0` in segment `i0`, fraction `f` ([`bracket`]):
/// Catmull-Rom's cubic on the four nearest frequencies (the grid is even), linear in the first and
/// last segments. The linear blend cuts the chord across the heave and pitch resonance: on the
/// former 40 x 6 x 13 grid it took 6 % off the variance of the DTMB 5415's hub motion in SS6 at
/// 25 kn (1.3 % of it from the 6 speeds); the cubic on the default grid leaves under 1 %
/// (`frequency_interpolation_keeps_the_hub_variance`). At a node the weights are exactly 1 and 0.
fn frequency_weights(n: usize, i0: usize, f: f64) -> [(usize, f64); 4] {
    if i0 >= 1 && i0 + 2 < n {
        let (f2, f3) = (f * f, f * f * f);
        [
            (i0 - 1, 0.5 * (-f3 + 2.0 * f2 - f)),
            (i0, 0.5 * (3.0 * f3 - 5.0 * f2 + 2.0)),
            (i0 + 1, 0.5 * (-3.0 * f3 + 4.0 * f2 + f)),
            (i0 + 2, 0.5 * (f3 - f2)),
        ]
    } else {
        let last = n.saturating_sub(1);
        [(i0.min(last), 1.0 - f), ((i0 + 1).min(last), f), (0, 0.0), (0, 0.0)]
    }
}

/// Which conformal form the `section` command uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FormChoice {
    Auto,
    Lewis,
    Bulb,
}

/// Sectional coefficients of one section as the JSON of `aes-sim section`: per-unit-length added
/// mass [kg/m] and damping [kg/(m s)] in heave and sway, roll [kg m, kg m/s] and the sway-roll
/// coupling [kg, kg/s], plus the map and the far-field damping check.
pub fn section_json(
    beam: f64,
    draft: f64,
    sigma: f64,
    form: FormChoice,
    omegas: &[f64],
    rho: f64,
    g: f64,
) -> Result<Value, String> {
    let chk = |name: &str, v: f64, lo: f64, hi: f64| -> Result<(), String> {
        if v.is_finite() && v > lo && v <= hi {
            Ok(())
        } else {
            Err(format!("{name} = {} is outside ({lo}, {hi}]", crate::checks::num(v)))
        }
    };
    chk("beam", beam, 0.0, 200.0)?;
    chk("draft", draft, 0.0, 100.0)?;
    chk("area-coeff", sigma, 0.0, 3.0)?;
    if omegas.is_empty() || omegas.len() > 10_000 {
        return Err(format!("omega: give 1 to 10000 frequencies (got {})", omegas.len()));
    }
    for &w in omegas {
        // Below 1e-3 rad/s the multipole series loses every digit (deep water's long-wave limit).
        chk("omega", w, 0.0, 50.0)?;
        if w < MIN_OMEGA {
            return Err(format!("omega = {}: must be from {MIN_OMEGA} to 50 rad/s", crate::checks::num(w)));
        }
    }
    let map: SectionMap = match form {
        FormChoice::Auto => section_map(0.5 * beam, draft, sigma),
        FormChoice::Lewis => section_map(0.5 * beam, draft, sigma).filter(|m| m.form == Form::Lewis),
        FormChoice::Bulb => bulb(0.5 * beam, draft, sigma),
    }
    .ok_or_else(|| format!("no {form:?} form has beam {beam}, draft {draft} and area coefficient {sigma}"))?;
    let c = Contour::new(&map);
    let rs: Vec<_> = omegas.iter().map(|&w| solve(&map, &c, w, rho, g, default_multipoles(w * w / g, &map))).collect();
    let col = |f: &dyn Fn(&super::radiation::Radiation2d) -> f64| -> Vec<f64> { rs.iter().map(f).collect() };
    let mode = |a: &dyn Fn(&super::radiation::Radiation2d) -> f64,
                b: &dyn Fn(&super::radiation::Radiation2d) -> f64,
                far: Option<usize>| SectionMode {
        added_mass: col(a),
        damping: col(b),
        damping_far_field: far.map(|k| col(&|r| r.b_far[k])),
    };
    let out = SectionCoefficients {
        form: map.form,
        clamped: map.clamped,
        scale_m: map.scale,
        coefficients: map.coeffs.clone(),
        area_coefficient: map.area_coefficient(),
        omega: omegas.to_vec(),
        heave: mode(&|r| r.a33, &|r| r.b33, Some(1)),
        sway: mode(&|r| r.a22, &|r| r.b22, Some(0)),
        roll: mode(&|r| r.a44, &|r| r.b44, Some(2)),
        sway_roll: mode(&|r| r.a24, &|r| r.b24, None),
        multipoles: rs.iter().map(|r| r.multipoles).collect(),
    };
    crate::checks::check_finite(&out)
        .map_err(|e| format!("the section's coefficients are not finite ({e}): try another form or frequency"))?;
    serde_json::to_value(out).map_err(|e| e.to_string())
}

/// Lowest wave frequency `section` and `rao` accept [rad/s].
pub const MIN_OMEGA: f64 = 1.0e-3;

/// One mode's sectional coefficients over frequency (`aes-sim section`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SectionMode {
    pub added_mass: Vec<f64>,
    pub damping: Vec<f64>,
    /// The damping from the radiated waves' energy flux (the check of the near-field value).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub damping_far_field: Option<Vec<f64>>,
}

/// The JSON of `aes-sim section`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SectionCoefficients {
    pub form: Form,
    pub clamped: bool,
    pub scale_m: f64,
    pub coefficients: Vec<f64>,
    pub area_coefficient: f64,
    pub omega: Vec<f64>,
    pub heave: SectionMode,
    pub sway: SectionMode,
    pub roll: SectionMode,
    pub sway_roll: SectionMode,
    pub multipoles: Vec<usize>,
}

/// Amplitude and phase of one mode over frequency (`aes-sim rao`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RaoMode {
    pub amp: Vec<f64>,
    pub phase_deg: Vec<f64>,
}

/// The JSON of `aes-sim rao`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RaoReport {
    pub speed_kn: f64,
    pub heading_deg: f64,
    pub omega0: Vec<f64>,
    pub omega_e: Vec<f64>,
    pub heave: RaoMode,
    pub pitch: RaoMode,
    pub sway: RaoMode,
    pub roll: RaoMode,
    pub yaw: RaoMode,
    pub added_resistance_n_per_m2: Vec<f64>,
    pub drift_force_n_per_m2: Vec<f64>,
    pub added_resistance_gerritsma_beukelman_n_per_m2: Vec<f64>,
}

/// RAOs of `ship` as the JSON of `aes-sim rao`: amplitudes (m/m for heave and sway, rad/m for
/// roll, pitch and yaw) and phases \[deg\] relative to the wave crest at the centre of gravity.
pub fn rao_json(
    ship: &Ship,
    speed: f64,
    heading: f64,
    omegas: &[f64],
    roll_wave_amplitude: f64,
) -> Result<Value, String> {
    if !(speed.is_finite() && (0.0..=30.0).contains(&speed)) {
        return Err(format!("speed = {:.3} kn is outside [0, 58.3] kn", speed / crate::numerics::units::KNOT_M_S));
    }
    if !heading.is_finite() {
        return Err(format!("heading = {heading} is not a number"));
    }
    if omegas.is_empty() || omegas.len() > 10_000 {
        return Err(format!("omega: give 1 to 10000 frequencies (got {})", omegas.len()));
    }
    for &w in omegas {
        if !(w.is_finite() && (MIN_OMEGA..=10.0).contains(&w)) {
            return Err(format!("omega = {} rad/s: must be from {MIN_OMEGA} to 10 rad/s", crate::checks::num(w)));
        }
    }
    let rad = ship.radiation_table(&default_omega_grid());
    let rs: Vec<Response> =
        omegas.iter().map(|&w| response(ship, &rad, w, speed, heading, roll_wave_amplitude)).collect();
    let mode = |f: &dyn Fn(&Response) -> C| RaoMode {
        amp: rs.iter().map(|r| f(r).norm_sqr().sqrt()).collect(),
        phase_deg: rs
            .iter()
            .map(|r| {
                let c = f(r);
                libm::atan2(c.im, c.re).to_degrees()
            })
            .collect(),
    };
    let out = RaoReport {
        speed_kn: speed / crate::numerics::units::KNOT_M_S,
        heading_deg: heading.to_degrees(),
        omega0: omegas.to_vec(),
        omega_e: rs.iter().map(|r| r.omega_e).collect(),
        heave: mode(&|r| r.heave),
        pitch: mode(&|r| r.pitch),
        sway: mode(&|r| r.sway),
        roll: mode(&|r| r.roll),
        yaw: mode(&|r| r.yaw),
        added_resistance_n_per_m2: rs.iter().map(|r| r.added_resistance).collect(),
        drift_force_n_per_m2: rs.iter().map(|r| r.drift_force).collect(),
        added_resistance_gerritsma_beukelman_n_per_m2: rs.iter().map(|r| r.added_resistance_gb).collect(),
    };
    crate::checks::check_finite(&out)
        .map_err(|e| format!("the RAOs are not finite ({e}): check the hull, draft and mass properties"))?;
    serde_json::to_value(out).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::complex::cabs;

    /// At grid nodes the interpolation returns the direct strip-theory result; waves from port
    /// mirror those from starboard; between nodes it stays close to the direct result in heave
    /// and pitch: 0.04 per metre between frequency nodes (0.034 reached; linear blending gave
    /// 0.045 on the 21 kn node of the former 6-speed grid), 0.03 between speed and heading nodes
    /// as well (0.024; linear 0.068). The default grid (40 x 8 x 13) is coarse where the heave
    /// RAO drops from 1 to 0.05 within 0.15 rad/s past the resonance at 25 kn; a scenario can
    /// refine it.
    #[test]
    fn interpolation_matches_direct_results() {
        let ship = Ship::dtmb5415();
        let grid = SeakeepingGrid::default();
        let rad = ship.radiation_table(&default_omega_grid());
        let tab = RaoTable::from_radiation(&ship, &rad, &grid);
        let (w, u, b) = (grid.omegas()[7], grid.speeds()[5], grid.headings()[10]);
        let d = response(&ship, &rad, w, u, b, grid.roll_wave_amplitude_m);
        let r = tab.interpolate(w, u, b);
        assert!(cabs(r.heave - d.heave) < 1e-12 && cabs(r.roll - d.roll) < 1e-12);
        assert!((r.fx - libm::cos(b) * d.f_add).abs() < 1e-6 * d.f_add.abs().max(1.0));
        let m = tab.interpolate(w, u, 2.0 * PI - b);
        assert!(cabs(m.heave - r.heave) < 1e-12 && cabs(m.sway + r.sway) < 1e-12 && (m.fy + r.fy).abs() < 1e-9);
        // Between frequency nodes (at a grid speed and heading) and between all three.
        for (u, b, tol) in [(grid.speeds()[5], PI, 0.04), (10.0, 170f64.to_radians(), 0.03)] {
            let mut worst: f64 = 0.0;
            for i in 0..25 {
                let w = 0.3 + 0.033 * i as f64;
                let d = response(&ship, &rad, w, u, b, grid.roll_wave_amplitude_m);
                let r = tab.interpolate(w, u, b);
                worst = worst.max(cabs(r.heave - d.heave)).max(cabs((r.pitch - d.pitch) / d.k));
            }
            println!(
                "U {u:.2} m/s beta {:.0} deg: worst interpolation error in heave and pitch/k {worst:.4}",
                b.to_degrees()
            );
            assert!(worst < tol);
        }
    }

    /// The drift moment in the table: at grid nodes `mz` is the direct `drift_moment` (to 1e-9),
    /// waves from port give the opposite moment, between heading nodes it is the linear blend of
    /// the nodes' moments, and `values` / `from_values` carry it bit for bit (a small grid:
    /// 4 frequencies x 2 speeds x 5 headings).
    #[test]
    fn drift_moment_in_the_table() {
        let ship = Ship::dtmb5415();
        let grid = SeakeepingGrid {
            n_omega: 4,
            omega_min: 0.4,
            omega_max: 1.0,
            n_speed: 2,
            n_heading: 5,
            ..Default::default()
        };
        let rad = ship.radiation_table(&default_omega_grid());
        let tab = RaoTable::from_radiation(&ship, &rad, &grid);
        let (w, u) = (grid.omegas()[2], grid.speeds()[1]);
        let hs = grid.headings();
        for &b in &hs {
            let d = response(&ship, &rad, w, u, b, grid.roll_wave_amplitude_m);
            let r = tab.interpolate(w, u, b);
            assert!((r.mz - d.drift_moment).abs() <= 1e-9 * d.drift_moment.abs().max(1.0), "beta {b}");
            let m = tab.interpolate(w, u, 2.0 * PI - b);
            assert!((m.mz + r.mz).abs() <= 1e-9 * r.mz.abs().max(1.0));
        }
        let (d3, d4) = (response(&ship, &rad, w, u, hs[3], 2.5), response(&ship, &rad, w, u, hs[4], 2.5));
        let mid = tab.interpolate(w, u, 0.5 * (hs[3] + hs[4]));
        assert!((mid.mz - 0.5 * (d3.drift_moment + d4.drift_moment)).abs() <= 1e-9 * d3.drift_moment.abs());
        assert!(tab.interpolate(w, u, hs[3]).mz.abs() > 1e3 && tab.interpolate(w, u, PI).mz.abs() < 1e-6);
        let v = tab.values();
        assert_eq!(v.len(), 4 * 2 * 5 * RaoTable::VALUES_PER_POINT);
        let back = RaoTable::from_values(&grid, &v).unwrap();
        assert_eq!(back.values(), v);
        assert_eq!(back.interpolate(w, u, 2.0).mz, tab.interpolate(w, u, 2.0).mz);
    }

    /// Issue 34: an RAO table is built within a work budget, checked before the build starts
    /// (the grid's maximum with a custom hull took 7 min and 297 MB), and a table loaded from
    /// another worker is checked as a computed one is: the 5415's default table passes, one
    /// with a value of 1e308, a wrong frequency or a NaN does not.
    #[test]
    fn tables_are_built_within_a_budget_and_checked() {
        let most = SeakeepingGrid { n_omega: 400, n_speed: 60, n_heading: 73, ..Default::default() };
        let e = most.validate().unwrap_err();
        assert!(e.contains("seakeeping.grid.n_omega = 400: with n_speed = 60 and n_heading = 73 the table has 1752000 points; at most 200000"), "{e}");
        let mut ship = Ship::dtmb5415();
        let extra: Vec<_> = ship.strips.iter().cycle().take(171).cloned().collect();
        ship.strips.extend(extra);
        let big = SeakeepingGrid { n_omega: 400, n_speed: 20, n_heading: 20, ..Default::default() };
        let t0 = std::time::Instant::now();
        let e = RaoTable::compute(&ship, &big).unwrap_err();
        assert!(e.contains("160000 points x 200 strips of the hull = 3.200e7 units of work"), "{e}");
        assert!(t0.elapsed().as_secs_f64() < 0.1, "refused before the build: {:?}", t0.elapsed());
        let grid = SeakeepingGrid::default();
        let good = RaoTable::compute(&Ship::dtmb5415(), &grid).unwrap().values();
        assert!(RaoTable::from_values(&grid, &good).is_ok());
        let n = RaoTable::VALUES_PER_POINT;
        for (at, v, want) in [
            (n + 5, 1e308, "point 1 (of 4160): an RAO part of 1e308"),
            (n * 7, 0.5, "omega0 = 0.5"),
            (14, 1e300, "a mean force"),
        ] {
            let mut bad = good.clone();
            bad[at] = v;
            let e = RaoTable::from_values(&grid, &bad).unwrap_err();
            assert!(e.contains(want), "{e}");
        }
    }

    /// Issue 31: a table built part by part in another order (as threads finish them) is the
    /// one-after-another table to the bit.
    #[test]
    fn parts_in_any_order_give_the_same_table() {
        struct Reversed;
        impl ForEach for Reversed {
            fn for_each(&self, n: usize, f: &(dyn Fn(usize) + Sync)) {
                (0..n).rev().for_each(f)
            }
        }
        let ship = Ship::dtmb5415();
        let grid = SeakeepingGrid { n_omega: 7, n_speed: 3, n_heading: 5, ..Default::default() };
        let printed = AsPrintedParams::default();
        let a = RaoTable::compute_as(&ship, &grid, &printed).unwrap().values();
        let b = RaoTable::compute_with(&ship, &grid, &printed, &Reversed).unwrap().values();
        assert!(a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits()) && a.len() == b.len());
    }

    #[test]
    fn bad_grid_names_the_field() {
        let g = SeakeepingGrid { n_omega: 0, ..Default::default() };
        assert!(g.validate().unwrap_err().contains("seakeeping.grid.n_omega = 0"));
        let g = SeakeepingGrid { omega_max: f64::NAN, ..Default::default() };
        assert!(g.validate().unwrap_err().contains("omega_max"));
    }
}
