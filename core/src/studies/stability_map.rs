//! Is the bus stable at this operating point (thesis ch. 6.1: "is the IPS stable under conditions
//! X at operating point Y?")? The whole plant linearised about its calm-water steady state with
//! its bus loads and storage, and a map of its stability over two parameters.
//!
//! The model: every dynamic state of the plant (turbines, fields, buses, shafts, the ship service
//! filters, the storages and the ship's surge) by central differences of `Plant::evaluate`, the
//! discrete controllers (governors, exciters, slip) held at their steady outputs as in
//! `sim::linearize` (the loop a constant-power load closes is the filter's, at tens of hertz,
//! far faster than they act; the storage's controller is continuous and part of the plant). Its
//! spectral abscissa, the largest real part of the eigenvalues, is negative where the bus is
//! stable; the map colours it over a grid of two parameters (any two numbers of the scenario, by
//! their paths) and draws the boundary where it crosses zero.
//!
//! The closed form it is checked against (`plant::bus_loads`): a stiff bus feeding a constant
//! power P through L_f, R_f, C_f is stable while P < R_f C_f v_f^2 / L_f.

use crate::scenario::{BusParts, Scenario};
use crate::sim::plant::{part_slot, slot, Outputs, NX, N_SETS, N_SHAFTS, SURGE};
use crate::sim::Simulation;
use crate::studies::study::{merge_records, records_of, Study};
use nalgebra::DMatrix;
use num_complex::Complex64;
use serde::{Deserialize, Serialize};

/// Relative step of the central differences.
const STEP: f64 = 1e-6;

/// Most cells of a map (each a steady state, a linearisation and an eigenvalue problem of at
/// most 23 states: about 0.2 ms).
pub const MAX_CELLS: usize = 10_000;

/// Most values on one axis of a map.
pub const MAX_AXIS_VALUES: usize = 200;

/// Units of work of one cell ([`crate::scenario::WORK_PER_S`] a second), for the estimate said
/// before a map starts: a cell's scenario, steady state and linearisation took 15 ms on one core
/// (a 200 x 50 map of head-seas-ss6 over ship.hull.kxx_m, 146 s); the acceleration preset's
/// cells are faster.
pub const CELL_WORK: f64 = 0.015 * crate::scenario::WORK_PER_S;

/// Linearisations of a row's boundary besides its cells (the bisection's halvings).
const BOUNDARY_HALVINGS: u32 = 40;

/// The plant linearised about its steady state.
#[derive(Debug, Clone, Serialize)]
pub struct BusModel {
    /// State names, in the order of the matrix.
    pub states: Vec<String>,
    /// dz/dt = A z with z each state over its scale (its steady value, at least 1) \[1/s\].
    #[serde(skip)]
    pub a: DMatrix<f64>,
    /// Eigenvalues \[1/s\], real and imaginary parts.
    pub eigenvalues: Vec<[f64; 2]>,
    /// The largest real part \[1/s\]: negative where the plant is stable.
    pub spectral_abscissa: f64,
    /// The frequency of the least damped mode \[Hz\].
    pub least_damped_hz: f64,
}

/// The states taken, each a group moved together, with their names. Both shafts are alike and
/// independent but for the ship they push, and their steady state is symmetric: their differences
/// decouple, and the model keeps the symmetric part (as `sim::linearize`), where a constant-power
/// load on both buses acts together.
fn states(sc: &Scenario) -> Vec<(Vec<usize>, String)> {
    let sets = |f: fn(usize) -> usize| (0..N_SETS).map(f).collect::<Vec<_>>();
    let shafts = |f: fn(usize) -> usize| (0..N_SHAFTS).map(f).collect::<Vec<_>>();
    let mut s = vec![
        (sets(slot::turbine_speed), "turbine_speed".to_string()),
        (sets(slot::field_current), "field_current".into()),
        (shafts(slot::bus_voltage), "bus_voltage".into()),
        (shafts(slot::shaft_speed), "shaft_speed".into()),
    ];
    // Each bus part's states where it takes part (`BusPart::linearized`), in their order.
    for (states, _) in BusParts::STATES.iter().zip(BusParts::linearized(&sc.plant)).filter(|(_, on)| *on) {
        for name in states.iter() {
            let slots = (0..N_SHAFTS).filter_map(|b| part_slot(name, b)).collect();
            s.push((slots, name.to_string()));
        }
    }
    s.push((vec![SURGE], "ship_speed".into()));
    s
}

/// Linearises the scenario's plant at its initial speed (`initial.speed_kn`, above 0).
pub fn linearize(sc: &Scenario) -> Result<BusModel, String> {
    if sc.initial.speed_kn.is_nan() || sc.initial.speed_kn <= 0.0 {
        return Err(format!(
            "initial.speed_kn = {}: the bus's stability is judged at a steady state under way (above 0 knots)",
            sc.initial.speed_kn
        ));
    }
    // The steady state is calm water's and the plant's equations do not read the sea: without
    // it the simulation builds no seaway, so no RAO table (a map over a hull parameter in a sea
    // built one a cell, about 2 s each, for nothing). The abscissa moves by rounding only (head
    // seas SS6: -0.019679121583758345 1/s in the sea, ...355 without).
    let mut calm = sc.clone();
    calm.sea.kind = crate::scenario::SeaKind::Calm;
    let sim = Simulation::new(&calm).map_err(|e| e.to_string())?;
    let (x0, h0) = (*sim.state(), *sim.held());
    let plant = sim.plant();
    let st = states(sc);
    let n = st.len();
    let scale: Vec<f64> = st.iter().map(|(g, _)| x0[g[0]].abs().max(1.0)).collect();
    // The groups' mean rates with group j moved by d (in its own unit).
    let f = |j: usize, d: f64| -> Vec<f64> {
        let mut x = x0;
        for &i in &st[j].0 {
            x[i] += d;
        }
        let (mut out, mut dx) = (Outputs::default(), [0.0; NX]);
        plant.evaluate(&x, &h0, &mut out, &mut dx);
        st.iter().map(|(g, _)| g.iter().map(|&i| dx[i]).sum::<f64>() / g.len() as f64).collect()
    };
    let mut a = DMatrix::zeros(n, n);
    for j in 0..n {
        let h = STEP * scale[j];
        let (fp, fm) = (f(j, h), f(j, -h));
        for i in 0..n {
            // In per unit of each state's scale (a diagonal similarity: the same eigenvalues, a
            // matrix whose entries the Schur iteration handles without scaling trouble).
            a[(i, j)] = (fp[i] - fm[i]) / (2.0 * h) * scale[j] / scale[i];
        }
    }
    if a.iter().any(|v| !v.is_finite()) {
        return Err("the linearised plant has non-finite entries".into());
    }
    let eig = crate::numerics::eigenvalues(&a).ok_or("the linearised plant's eigenvalues did not converge")?;
    let worst =
        eig.iter().copied().fold(Complex64::new(f64::NEG_INFINITY, 0.0), |m, l| if l.re > m.re { l } else { m });
    Ok(BusModel {
        states: st.into_iter().map(|(_, s)| s).collect(),
        a,
        eigenvalues: eig.iter().map(|l| [l.re, l.im]).collect(),
        spectral_abscissa: worst.re,
        least_damped_hz: worst.im.abs() / (2.0 * std::f64::consts::PI),
    })
}

/// One axis of a map: a scenario number by its path and the values it takes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Axis {
    pub path: String,
    pub values: Vec<f64>,
}

impl Axis {
    /// `n` values evenly from `lo` to `hi`.
    pub fn linear(path: &str, lo: f64, hi: f64, n: usize) -> Axis {
        let n = n.max(2);
        Axis { path: path.into(), values: (0..n).map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64).collect() }
    }

    /// `n` values evenly from `lo` to `hi` of the number at `path` of `sc`, checked: `n` from 2
    /// to [`MAX_AXIS_VALUES`], `lo` below `hi`, both ends a value the scenario takes there (its
    /// own check, naming the parameter and its range). `which` names the axis in the message.
    pub fn checked(sc: &Scenario, which: &str, path: &str, lo: f64, hi: f64, n: usize) -> Result<Axis, String> {
        // The path as messages show it: escaped and cut (a page may send a megabyte).
        let shown_path = crate::checks::shorten(path);
        if !(2..=MAX_AXIS_VALUES).contains(&n) {
            return Err(format!("{which}: {n} values: from 2 to {MAX_AXIS_VALUES}"));
        }
        if let Some(held) = held_controller(path) {
            return Err(format!(
                "{which}: {shown_path}: the map holds the {held} at its steady output: its settings do not move it; \
                 axes that do: the plant's and the ship's parameters (plant.*, ship.*, e.g. \
                 plant.loads.ship_service_w, plant.loads.filter_capacitance_f), initial.speed_kn and \
                 controllers.field.bus_voltage_ref_v (the operating point)"
            ));
        }
        if path.starts_with("sea.") || path.starts_with("seakeeping.grid.") {
            return Err(format!(
                "{which}: {shown_path}: the map linearises the plant about its calm-water steady state: the sea and the \
                 RAO table's grid do not move it; axes that do: the plant's and the ship's parameters (plant.*, \
                 ship.*), initial.speed_kn and controllers.field.bus_voltage_ref_v"
            ));
        }
        if path.starts_with("stepping.") || path.starts_with("sim.") {
            return Err(format!(
                "{which}: {shown_path}: the map linearises the plant and does not step it in time: the time step and \
                 the run's settings do not move it; axes that do: the plant's and the ship's parameters (plant.*, \
                 ship.*), initial.speed_kn and controllers.field.bus_voltage_ref_v"
            ));
        }
        if !(lo.is_finite() && hi.is_finite() && lo < hi) {
            let shown = |v: f64| {
                if v.is_finite() {
                    crate::checks::num(v)
                } else {
                    "a value that is not a finite number".into()
                }
            };
            return Err(format!(
                "{which}: from {} to {} {shown_path}: two finite numbers, the first below the second",
                shown(lo),
                shown(hi)
            ));
        }
        for v in [lo, hi] {
            set(sc, path, v).map_err(|e| format!("{which}: {e}"))?;
        }
        Ok(Axis::linear(path, lo, hi, n))
    }
}

/// The map: the spectral abscissa over the grid, and the boundary.
#[derive(Debug, Clone, Serialize)]
pub struct StabilityMap {
    pub x: Axis,
    pub y: Axis,
    /// Spectral abscissa \[1/s\] of each cell, a row per y value (None where the steady state or the
    /// model failed, with the reason in `failures`).
    pub abscissa: Vec<Vec<Option<f64>>>,
    /// The frequency \[Hz\] of each cell's least damped mode (the one whose real part is the
    /// abscissa), as `abscissa`.
    pub least_damped_hz: Vec<Vec<Option<f64>>>,
    /// For each y value, the x where the abscissa first crosses zero along the row (bisected
    /// between its cells; None where it does not within the row).
    pub boundary_x: Vec<Option<f64>>,
    pub failures: Vec<String>,
}

/// The controller a `controllers.` path sets, when the map cannot move with it: the linearisation
/// holds every discrete controller at its steady output (`Held`), so only the bus voltage's set
/// point, which moves the operating point, is an axis among them.
fn held_controller(path: &str) -> Option<&'static str> {
    let rest = path.strip_prefix("controllers.")?;
    if rest == "field.bus_voltage_ref_v" {
        return None;
    }
    Some(match rest.split('.').next().unwrap_or("") {
        "governor" => "governor",
        "field" => "exciter (the field controller)",
        "slip" => "motors' slip controller",
        "speed" => "speed controller",
        "autopilot" => "autopilot",
        "lqg_ltr" => "LQG/LTR controller",
        _ => "controllers",
    })
}

/// The scenario with `path` set to `value`.
/// `sc` with `path` set to `value`, on the finest time step: a linearisation does not step in time,
/// so the rules a step must keep (a ship service filter's resonance resolved by it) must not
/// refuse a cell. The step does not enter the linearisation (the same eigenvalues on any step).
fn set(sc: &Scenario, path: &str, value: f64) -> Result<Scenario, String> {
    let finest = crate::checks::num(LINEARISATION_DT_S);
    sc.with_overrides(&[
        (path, &crate::checks::num(value)),
        ("stepping.dt_s", &finest),
        ("stepping.integrator", "rk4"),
        ("stepping.hull_substeps", "1"),
    ])
    .map_err(|e| e.to_string())
}

/// The step the map's scenarios carry \[s\]: the smallest `stepping.dt_s` takes, a whole fraction of
/// every sample period and record interval the presets use.
const LINEARISATION_DT_S: f64 = 1e-5;

/// The spectral abscissa with the two parameters set.
pub fn abscissa_at(sc: &Scenario, x: (&str, f64), y: (&str, f64)) -> Result<f64, String> {
    let s = set(&set(sc, x.0, x.1)?, y.0, y.1)?;
    Ok(linearize(&s)?.spectral_abscissa)
}

/// Checks a map's two axes together: two different parameters, at most [`MAX_CELLS`] cells.
pub fn check_grid(x: &Axis, y: &Axis) -> Result<(), String> {
    if x.path == y.path {
        return Err(format!("both axes are {}: choose two different parameters", x.path));
    }
    let cells = x.values.len() * y.values.len();
    if cells > MAX_CELLS {
        return Err(format!(
            "a map of {} x {} = {cells} cells: at most {MAX_CELLS} (fewer values on an axis)",
            x.values.len(),
            y.values.len()
        ));
    }
    Ok(())
}

/// Most failures a map lists (and a row keeps).
const MAX_FAILURES: usize = 10;

/// The map of `sc` over `x` and `y`: its rows (y values) one after another on the study pipeline
/// ([`StabilityMapStudy`]). Each row is computed alone: the map of a part of `y`'s values is that
/// part of the whole map's rows, bit for bit.
pub fn map(sc: &Scenario, x: &Axis, y: &Axis) -> Result<StabilityMap, String> {
    let spec = StabilityMapSpec { scenario: sc.clone(), x: x.clone(), y: y.clone() };
    crate::studies::study::run_all(&StabilityMapStudy::new(spec)?)
}

/// One row of a map (a y value): its cells, its boundary and its first failures.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MapRow {
    /// The row's index among the y values.
    pub item: u64,
    pub abscissa: Vec<Option<f64>>,
    pub least_damped_hz: Vec<Option<f64>>,
    pub boundary_x: Option<f64>,
    pub failures: Vec<String>,
}

/// Row `j` of the map of `sc` over `x` and `y`.
fn map_row(sc: &Scenario, x: &Axis, y: &Axis, j: usize) -> MapRow {
    let yv = y.values[j];
    let mut failures = Vec::new();
    let models: Vec<Option<BusModel>> = x
        .values
        .iter()
        .map(|&xv| match set(sc, &x.path, xv).and_then(|s| set(&s, &y.path, yv)).and_then(|s| linearize(&s)) {
            Ok(m) => Some(m),
            Err(e) => {
                if failures.len() < MAX_FAILURES {
                    failures.push(format!("{} = {xv}, {} = {yv}: {e}", x.path, y.path));
                }
                None
            }
        })
        .collect();
    let row: Vec<Option<f64>> = models.iter().map(|m| m.as_ref().map(|m| m.spectral_abscissa)).collect();
    let least_damped_hz = models.iter().map(|m| m.as_ref().map(|m| m.least_damped_hz)).collect();
    // The first change of sign along the row, bisected between its two cells (the abscissa
    // is a slow mode's until the unstable one overtakes it: not linear between cells).
    let boundary_x = row.windows(2).zip(x.values.windows(2)).find_map(|(a, xs)| match (a[0], a[1]) {
        (Some(a0), Some(a1)) if (a0 < 0.0) != (a1 < 0.0) => {
            let (lo, hi) = if a0 < 0.0 { (xs[0], xs[1]) } else { (xs[1], xs[0]) };
            bisect_boundary(sc, &x.path, lo, hi, (&y.path, yv), BOUNDARY_HALVINGS).ok()
        }
        _ => None,
    });
    MapRow { item: j as u64, abscissa: row, least_damped_hz, boundary_x, failures }
}

/// The definition of a map: the scenario and its two axes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StabilityMapSpec {
    pub scenario: Scenario,
    pub x: Axis,
    pub y: Axis,
}

/// The stability map on the study pipeline: item j is the row of the j-th y value.
pub struct StabilityMapStudy {
    spec: StabilityMapSpec,
}

impl Study for StabilityMapStudy {
    const KIND: &'static str = "stability-map";
    const ITEM: &'static str = "row";
    type Spec = StabilityMapSpec;
    type Shared = ();
    type Part = Vec<MapRow>;
    type Summary = StabilityMap;

    /// The grid's size checked (the command line checks each axis first with [`Axis::checked`];
    /// a cell the scenario refuses is a failure of the map, as before the pipeline).
    fn new(spec: StabilityMapSpec) -> Result<StabilityMapStudy, String> {
        check_grid(&spec.x, &spec.y)?;
        Ok(StabilityMapStudy { spec })
    }
    fn spec(&self) -> &StabilityMapSpec {
        &self.spec
    }
    fn scenario(&self) -> &Scenario {
        &self.spec.scenario
    }
    fn items(&self) -> u64 {
        self.spec.y.values.len() as u64
    }
    /// A row's cells and its boundary's bisection, each a linearisation of [`CELL_WORK`].
    fn item_work(&self) -> Option<f64> {
        Some((self.spec.x.values.len() as f64 + BOUNDARY_HALVINGS as f64) * CELL_WORK)
    }
    /// Linearisations, not runs: no seakeeping table.
    fn needs_rao_table(&self) -> bool {
        false
    }
    fn prepare(&self) -> Result<(), String> {
        Ok(())
    }
    fn run(&self, _: &(), i: u64) -> Result<Vec<MapRow>, String> {
        Ok(vec![map_row(&self.spec.scenario, &self.spec.x, &self.spec.y, i as usize)])
    }
    fn empty(&self) -> Vec<MapRow> {
        Vec::new()
    }
    fn merge(&self, acc: &mut Vec<MapRow>, other: &Vec<MapRow>) -> Result<(), String> {
        merge_records(acc, other, |r| r.item, Self::ITEM)
    }
    /// One row per item of the ranges, each as wide as the x axis.
    fn check_part(&self, part: &Vec<MapRow>, ranges: &[(u64, u64)]) -> Result<(), String> {
        let n = self.spec.x.values.len();
        for (r, i) in records_of(part, ranges, |r| r.item, Self::ITEM)? {
            if r.abscissa.len() != n || r.least_damped_hz.len() != n || r.failures.len() > MAX_FAILURES {
                return Err(format!("row {i}: need {n} cells and at most {MAX_FAILURES} failures"));
            }
        }
        Ok(())
    }
    /// The rows merged so far (a map lacking rows lacks them in its y axis too), the first
    /// failures in row order.
    fn summary(&self, part: &Vec<MapRow>, _: &[(u64, u64)]) -> Result<StabilityMap, String> {
        let y = &self.spec.y;
        let mut m = StabilityMap {
            x: self.spec.x.clone(),
            y: Axis { path: y.path.clone(), values: part.iter().map(|r| y.values[r.item as usize]).collect() },
            abscissa: Vec::new(),
            least_damped_hz: Vec::new(),
            boundary_x: Vec::new(),
            failures: Vec::new(),
        };
        for r in part {
            m.abscissa.push(r.abscissa.clone());
            m.least_damped_hz.push(r.least_damped_hz.clone());
            m.boundary_x.push(r.boundary_x);
            m.failures.extend(r.failures.iter().cloned());
        }
        m.failures.truncate(MAX_FAILURES);
        Ok(m)
    }
}

/// The x of the boundary at `y` between `lo` (stable) and `hi` (unstable), by bisection on the
/// spectral abscissa's sign (60 halvings: to 1e-18 of the bracket).
pub fn boundary(sc: &Scenario, x_path: &str, lo: f64, hi: f64, y: (&str, f64)) -> Result<f64, String> {
    let (a_lo, a_hi) = (abscissa_at(sc, (x_path, lo), y)?, abscissa_at(sc, (x_path, hi), y)?);
    if !(a_lo < 0.0 && a_hi > 0.0) {
        return Err(format!(
            "{x_path}: the bracket {lo} to {hi} does not straddle the boundary (abscissae {a_lo:.3e}, {a_hi:.3e} 1/s)"
        ));
    }
    bisect_boundary(sc, x_path, lo, hi, y, 60)
}

/// Bisection between a stable `lo` and an unstable `hi` (either order on the axis).
fn bisect_boundary(
    sc: &Scenario,
    x_path: &str,
    lo: f64,
    hi: f64,
    y: (&str, f64),
    halvings: u32,
) -> Result<f64, String> {
    let (mut a, mut b) = (lo, hi);
    for _ in 0..halvings {
        let m = 0.5 * (a + b);
        if abscissa_at(sc, (x_path, m), y)? < 0.0 {
            a = m;
        } else {
            b = m;
        }
    }
    Ok(0.5 * (a + b))
}

/// Filter capacitances of the closed-form check \[F\].
pub const STIFF_BUS_FILTERS_F: [f64; 3] = [0.01, 0.02, 0.04];

/// The map's simple case, checked against a closed form (the test and the validation report
/// share it): the plant at 20 kn with a stiff bus (100 F, the range's top) feeding the ship
/// service load through the default filter with capacitance `c_f` \[F\]. Returns the closed form
/// R_f C_f v_f^2 / L_f and the boundary in ship service power bisected between half and 1.5 times
/// it, as the map does between its cells \[W\].
pub fn stiff_bus_check(c_f: f64) -> Result<(f64, f64), String> {
    let mut sc = crate::scenario::presets::acceleration(false);
    sc.initial.speed_kn = 20.0;
    sc.commands[0].speed_kn = Some(20.0);
    sc.plant.loads.ship_service_w = 1.0e6;
    sc.plant.dc_link.capacitance_f = 100.0;
    let l = &sc.plant.loads;
    let f = crate::plant::bus_loads::ShipService {
        l_h: l.filter_inductance_h,
        r_ohm: l.filter_resistance_ohm,
        c_f,
        v_min: 0.0,
    };
    let closed = f.critical_power_w(sc.bus_voltage_ref_v());
    let b = boundary(
        &sc,
        "plant.loads.ship_service_w",
        0.5 * closed,
        1.5 * closed,
        ("plant.loads.filter_capacitance_f", c_f),
    )?;
    Ok((closed, b))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 57: the linearisation does not read the sea. In SS6 head seas on an RAO grid of its
    /// own, linearising builds no table (it built one a cell: about 2 s each over a hull or grid
    /// axis), and gives the eigenvalues of the same plant in calm water, bit for bit. A map over
    /// the sea or the table's grid, which cannot move, is refused by name; over a hull parameter,
    /// every cell is made and no table built.
    #[test]
    fn the_linearisation_builds_no_rao_table() {
        let mut sc = crate::scenario::presets::preset("head-seas-ss6").unwrap();
        sc.seakeeping.grid.n_omega = 37;
        sc.seakeeping.grid.omega_max = 1.913;
        assert!(!sc.rao_table_is_cached());
        let m = linearize(&sc).unwrap();
        assert!(!sc.rao_table_is_cached(), "the linearisation built the RAO table");
        let mut calm = sc.clone();
        calm.sea.kind = crate::scenario::SeaKind::Calm;
        assert_eq!(m.eigenvalues, linearize(&calm).unwrap().eigenvalues);
        for path in ["seakeeping.grid.omega_max", "sea.h_sig_m"] {
            let e = Axis::checked(&sc, "--x", path, 1.0, 2.0, 3).unwrap_err();
            assert!(e.contains(path) && e.contains("do not move it"), "{e}");
        }
        let x = Axis::checked(&sc, "--x", "ship.hull.kxx_m", 4.0, 5.0, 2).unwrap();
        let y = Axis::checked(&sc, "--y", "plant.loads.filter_capacitance_f", 0.01, 0.04, 2).unwrap();
        let map = map(&sc, &x, &y).unwrap();
        assert!(map.abscissa.iter().flatten().all(|a| a.is_some()), "{:?}", map.failures);
        for kxx in [4.0, 5.0] {
            let mut cell = sc.clone();
            cell.ship.hull.kxx_m = Some(kxx);
            assert!(!cell.rao_table_is_cached(), "kxx {kxx}: a table was built");
        }
    }

    /// Issue 55: a governor or exciter gain cannot move the map (the controllers are held at their
    /// steady outputs; the map was flat at -3.3e-5 1/s from field K_p 1e-5 to 1 and governor K_p 1
    /// to 1000): such an axis is refused by name with the axes that do move it; a plant axis and
    /// the bus voltage's set point are still taken.
    #[test]
    fn an_axis_the_map_holds_still_is_refused_by_name() {
        let sc = crate::scenario::presets::acceleration(false);
        for (path, held) in [("controllers.governor.kp", "governor"), ("controllers.field.kp", "exciter")] {
            let e = Axis::checked(&sc, "--x", path, 1.0, 10.0, 3).unwrap_err();
            assert!(e.contains(path) && e.contains(held) && e.contains("do not move it"), "{e}");
            assert!(e.contains("plant.loads.ship_service_w"), "{e}");
        }
        assert!(Axis::checked(&sc, "--x", "plant.loads.ship_service_w", 1e6, 2e7, 3).is_ok());
        assert!(Axis::checked(&sc, "--y", "controllers.field.bus_voltage_ref_v", 5000.0, 6000.0, 3).is_ok());
        let e = Axis::checked(&sc, "--x", "stepping.dt_s", 1e-4, 1e-3, 3).unwrap_err();
        assert!(e.contains("does not step it in time"), "{e}");
    }

    /// The time step's rules do not refuse a cell: head seas at 5 ms cannot resolve a ship service
    /// filter (the step must be at most 1.26 ms for its 25.2 Hz), yet the map of its ship service
    /// load and filter has every cell, and a cell's eigenvalues are those of the same scenario
    /// on a 1 ms step, bit for bit (the step does not enter the linearisation).
    #[test]
    fn a_linearisation_does_not_apply_the_time_steps_rules() {
        let sc = crate::scenario::presets::preset("head-seas-ss6").unwrap();
        assert!(sc.with_override("plant.loads.ship_service_w", "2e6").is_err(), "the step rule holds for a run");
        let x = Axis::checked(&sc, "--x", "plant.loads.ship_service_w", 1e6, 4e6, 2).unwrap();
        let y = Axis::checked(&sc, "--y", "plant.loads.filter_capacitance_f", 0.01, 0.04, 2).unwrap();
        let m = map(&sc, &x, &y).unwrap();
        assert!(m.failures.is_empty(), "{:?}", m.failures);
        assert!(m.abscissa.iter().flatten().all(|a| a.is_some()), "{:?}", m.abscissa);
        let run = sc
            .with_overrides(&[
                ("stepping.dt_s", "0.001"),
                ("stepping.integrator", "rk4"),
                ("stepping.hull_substeps", "1"),
                ("plant.loads.ship_service_w", "1000000"),
                ("plant.loads.filter_capacitance_f", "0.01"),
            ])
            .unwrap();
        assert_eq!(Some(linearize(&run).unwrap().spectral_abscissa), m.abscissa[0][0]);
    }

    /// At 20 knots in calm water with a 2 MW ship service load on each bus (well inside its
    /// 4.7 MW limit) every mode decays; the filter's resonance (25.2 Hz alone) is there at 26.2 Hz,
    /// damped at -15.1 1/s (the bus's impedance adds to R_f's -7.5 1/s).
    #[test]
    fn the_plant_with_a_ship_service_load_is_stable() {
        let mut sc = crate::scenario::presets::acceleration(false);
        sc.initial.speed_kn = 20.0;
        sc.commands[0].speed_kn = Some(20.0);
        sc.plant.loads.ship_service_w = 2.0e6;
        let m = linearize(&sc).unwrap();
        assert!(m.spectral_abscissa < 0.0, "{m:?}");
        let ring = m.eigenvalues.iter().find(|l| (l[1].abs() / (2.0 * std::f64::consts::PI) - 25.2).abs() < 2.0);
        assert!(ring.is_some_and(|l| l[0] < 0.0), "{:?}", m.eigenvalues);
    }
}
