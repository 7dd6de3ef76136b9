//! The bounds a polar's cell from outside must keep (a shard's check): every value within what
//! the RAO table lets a linear response reach, every limiting height consistent with its value,
//! and the cell's limit, its criterion and the seas passed as the list of limits gives them.

use super::{along_the_list, first_limit, Cell, Judge, PolarSetup};
use crate::checks::num;
use crate::numerics::units::kn_to_m_s;
use crate::sea::operability::Quantity;
use crate::sea::waves::G;
use std::f64::consts::PI;

/// RMS wave amplitude per metre of H_1/3: H_1/3 / 4 (m0 = H^2 / 16 for the whole spectrum, the
/// band summed holds less), times 1.5 of room for the frequency sum's rounding.
const AMPLITUDE_PER_HS: f64 = 0.25 * 1.5;

/// Relative room for rounding where a value is compared with its limit.
const ROUND: f64 = 1e-9;

/// Highest limiting H_1/3 \[m\]: the square root of the largest double, since its square is
/// a finite number (an RMS's limit over its value, or an exceedance law's a / ln(r0 / limit)).
pub const MAX_LIMIT_HS_M: f64 = 1.3407807929942596e154;

/// What a cell of one polar can hold.
pub struct CellLimits {
    /// Largest |RAO| anywhere in the table: sway, heave \[m/m\], roll, pitch, yaw \[rad/m\]
    /// (the sums interpolate between the table's points, never beyond their largest).
    gains: [f64; 5],
    /// Highest wave frequency the sums take \[rad/s\].
    omega_max: f64,
}

impl CellLimits {
    pub fn of(setup: &PolarSetup) -> CellLimits {
        let values = setup.table.values();
        let mut gains = [0.0f64; 5];
        for point in values.chunks_exact(crate::sea::seakeeping::tables::RaoTable::VALUES_PER_POINT) {
            for (k, g) in gains.iter_mut().enumerate() {
                *g = g.max(libm::hypot(point[3 + 2 * k], point[4 + 2 * k]));
            }
        }
        // One node step of room above the band's top (the nodes' last midpoint).
        CellLimits { gains, omega_max: setup.band.1 + super::FREQUENCY_STEP }
    }

    /// Highest encounter frequency at `u` \[m/s\]: a wave of the top frequency met head on.
    fn omega_e_max(&self, u: f64) -> f64 {
        self.omega_max + self.omega_max * self.omega_max * u / G
    }

    /// Largest value criterion `i` can have per metre of H_1/3 (probabilities: in all), and why.
    fn most(&self, judge: &Judge, i: usize, u: f64) -> (f64, bool, &'static str) {
        let [gs, gh, gr, gp, gy] = self.gains;
        let we = self.omega_e_max(u);
        let point = || {
            let p = judge.places.points.get(judge.point_of[i]).copied().unwrap_or_default();
            (p[0].abs(), p[1].abs(), p[2].abs())
        };
        let a = AMPLITUDE_PER_HS;
        let rms = "an RMS under the table's largest RAO times the wave's RMS amplitude, H_1/3 / 4 (1.5 of room)";
        let rate = "a rate per hour at most 3600 times the highest encounter frequency over 2 pi";
        match judge.criteria[i].quantity {
            Quantity::RollRmsDeg => (a * gr.to_degrees(), true, rms),
            Quantity::PitchRmsDeg => (a * gp.to_degrees(), true, rms),
            Quantity::HeaveRmsM => (a * gh, true, rms),
            Quantity::VerticalVelocityRmsMS => {
                let (x, y, _) = point();
                (a * we * (gh + y * gr + x * gp), true, rms)
            }
            Quantity::VerticalAccelerationRmsG => {
                let (x, y, _) = point();
                (a * we * we * (gh + y * gr + x * gp) / G, true, rms)
            }
            Quantity::LateralAccelerationRmsG => {
                let (x, _, z) = point();
                (a * (we * we * (gs + z * gr + x * gy) + G * gr) / G, true, rms)
            }
            Quantity::SlammingProbability | Quantity::DeckWetnessProbability => {
                (1.0, false, "a chance per encounter, at most 1")
            }
            Quantity::SlamsPerHour
            | Quantity::DeckWetnessPerHour
            | Quantity::VentilationPerHour
            | Quantity::EmergencePerHour => (3600.0 * we / (2.0 * PI), false, rate),
        }
    }

    /// Checks one cell of the seas `hs` \[m\]; the error names the field, its value and the bound.
    pub fn check(&self, judge: &Judge, cell: &Cell, hs: &[f64]) -> Result<(), String> {
        let u = kn_to_m_s(cell.speed_kn);
        for (s, (values, limits)) in cell.values.iter().zip(&cell.limit_hs_m).enumerate() {
            for (i, (v, l)) in values.iter().zip(limits).enumerate() {
                let c = &judge.criteria[i];
                let field = |f: &str| format!("{f}.{s}.{i}");
                if let Some(l) = *l {
                    if !(0.0..=MAX_LIMIT_HS_M).contains(&l) {
                        return Err(format!(
                            "{} = {}: a limiting H_1/3 is from 0 to {} m (the root of a finite a / ln(r0 / limit))",
                            field("limit_hs_m"),
                            num(l),
                            num(MAX_LIMIT_HS_M)
                        ));
                    }
                }
                let Some(v) = *v else {
                    // Only a propeller in the air in calm water has no finite value.
                    if matches!(c.quantity, Quantity::VentilationPerHour | Quantity::EmergencePerHour) {
                        continue;
                    }
                    return Err(format!(
                        "{} = null: only a ventilation or emergence rate may be unbounded",
                        field("values")
                    ));
                };
                let (per, scales, why) = self.most(judge, i, u);
                let top = if scales { per * hs[s] } else { per };
                if !(v.is_finite() && v >= 0.0 && v <= top * (1.0 + ROUND)) {
                    return Err(format!("{} = {}: must be from 0 to {} ({why})", field("values"), num(v), num(top)));
                }
                let (lim, h) = (c.limit, hs[s]);
                let bad = |why: &str| {
                    Err(format!(
                        "{} = {}, {} = {}: {why} (limit {}, H_1/3 {} m)",
                        field("values"),
                        num(v),
                        field("limit_hs_m"),
                        l.map_or("null".into(), num),
                        num(lim),
                        num(h)
                    ))
                };
                // An RMS grows as H_1/3, so value x limiting height = limit x H_1/3.
                if scales {
                    match l {
                        Some(l) if (v * l - lim * h).abs() <= ROUND * lim * h => {}
                        None if v == 0.0 => {}
                        _ => return bad("an RMS value times its limiting H_1/3 is the limit times the sea's H_1/3"),
                    }
                }
                // A chance per encounter is exp(-a / H^2) and its limit's height solves it at the
                // limit: ln(value) = -(limiting H / H)^2 ln(1 / limit) (0 once that passes
                // exp's underflow; no limiting height when the chance is 0 at every height).
                if matches!(c.quantity, Quantity::SlammingProbability | Quantity::DeckWetnessProbability) && h > 0.0 {
                    let fits = match l {
                        Some(l) => {
                            let ln_v = -(l / h) * (l / h) * libm::log(1.0 / lim);
                            // Near exp's underflow (about e^-708) the value keeps few digits:
                            // there both need only be tiny.
                            if v < 1e-295 {
                                ln_v < -670.0
                            } else if ln_v < -680.0 {
                                v < 1e-290
                            } else {
                                (libm::log(v) - ln_v).abs() <= 1e-6 * (1.0 + ln_v.abs())
                            }
                        }
                        None => v == 0.0 || lim >= 1.0,
                    };
                    if !fits {
                        return bad("a chance per encounter is the limit raised to (limiting H_1/3 / H_1/3)^2");
                    }
                }
                // Every value grows with H_1/3: below its limiting height it is under the limit,
                // above it over; with no limiting height it never reaches the limit.
                let under = v <= lim * (1.0 + ROUND);
                let over = v >= lim * (1.0 - ROUND);
                let ok = match l {
                    None => under,
                    Some(l) if h < l * (1.0 - ROUND) => under,
                    Some(l) if h > l * (1.0 + ROUND) => over,
                    Some(_) => true,
                };
                if !ok {
                    return bad("the value passes its limit where the sea passes its limiting H_1/3, and only there");
                }
            }
        }
        // The cell's limit, criterion and seas passed follow from the limits listed.
        let cell_limit: Vec<Option<(f64, usize)>> = cell.limit_hs_m.iter().map(|l| first_limit(l)).collect();
        let mins: Vec<Option<f64>> = cell_limit.iter().map(|c| c.map(|(v, _)| v)).collect();
        let (limiting, beyond, passed) = along_the_list(hs, &mins);
        let criterion = cell_limit[passed.min(hs.len() - 1)].map(|(_, i)| i);
        if cell.limiting_hs_m != limiting
            || cell.beyond_listed != beyond
            || cell.seas_passed != passed
            || cell.limiting_criterion != criterion
        {
            return Err(format!(
                "limiting_hs_m = {}, limiting_criterion = {:?}, beyond_listed = {}, seas_passed = {}: the seas' \
                 limits give {}, {criterion:?}, {beyond}, {passed}",
                cell.limiting_hs_m.map_or("null".into(), num),
                cell.limiting_criterion,
                cell.beyond_listed,
                cell.seas_passed,
                limiting.map_or("null".into(), num),
            ));
        }
        Ok(())
    }
}
