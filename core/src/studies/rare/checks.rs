//! The bounds a trial's record from outside must keep (a shard's check).

use super::*;

/// What one trial of a study can give, for the checks of a shard from outside: every number of
/// a trial's record within these bounds, or the shard was not made by this study's trials. Each
/// bound says why a trial cannot pass it; they are generous (a real trial stays well inside) but
/// finite, so a tampered shard cannot move a rate, a quantile or a replay's `--set` line.
pub struct TrialLimits {
    seed: u64,
    /// Highest crossing rate of the study's sea \[1/s\].
    max_rate_per_s: f64,
    /// h/R the hub can have at the event: a depth at most [`MAX_HUB_DEPTH_M`] from the surface.
    h_over_r: (f64, f64),
    /// (lowest, highest, unit, why) of each consequence, in the order of [`CONSEQUENCES`].
    values: [(f64, f64, &'static str, &'static str); 5],
    /// Farthest the ship can be from its start at the event \[m\].
    max_reach_m: f64,
    /// The declared ranges of `rare_event.ship_x_m`, `ship_y_m`, `ship_heading_deg` and
    /// `ship_speed_kn`: a trial's place is echoed into its replay's `--set` lines, which must be
    /// accepted.
    place: [(&'static str, f64, f64); 4],
}

/// Farthest the propeller hub is from the still water surface at an event, above or below \[m\]:
/// a hull's hub sits at most a few tens of metres deep, and the highest sea of the scenario's
/// ranges (H_1/3 up to 20 m) with the ship's heave and pitch moves it by tens more.
pub const MAX_HUB_DEPTH_M: f64 = 200.0;

/// Largest motor power drop, in units of both motors' rated power: a motor's torque stays under
/// its pull-out torque (a few times rated at the set point, growing as the square of the bus
/// voltage, which the run's guard keeps under 3 pu) at a shaft speed the guard keeps under 3 times
/// its largest reference: a drop (a mean before minus a lowest after) cannot reach 100 times the
/// rated power of both.
pub const MAX_POWER_DROP_OF_RATED: f64 = 100.0;

impl TrialLimits {
    /// The limits of a trial of the study whose trials run `sc`.
    pub fn of(sc: &Scenario) -> Result<TrialLimits, String> {
        use crate::sim::limits;
        let ev = &sc.rare_event;
        // The crossing rate of a sea is sqrt(m2 / m0) / (2 pi) times a factor at most 1, and
        // sqrt(m2 / m0) is at most the highest encounter frequency of its components: a wave of
        // the sampled band's top frequency met head on at the fastest speed a scenario declares
        // (40 kn). Twice that leaves room for rounding.
        let (_, w_max) = sc.sea.band();
        let u_max = crate::numerics::units::kn_to_m_s(40.0);
        // (Rounded up to a thousandth, as the message prints it.)
        let max_rate_per_s = libm::ceil(
            2.0 * (w_max + w_max * w_max * u_max / crate::sea::waves::G) / (2.0 * std::f64::consts::PI) * 1e3,
        ) / 1e3;
        let radius = 0.5 * sc.propeller.diameter_m;
        let h = MAX_HUB_DEPTH_M / radius;
        // The run stops (diverged) when a bus, a turbine or a shaft leaves these bands, so no
        // recorded row of a finished trial is outside them (the check allows a part in 1e9 for
        // the division by the rated value).
        let (v_lo, v_hi) = limits::BUS_VOLTAGE_PU;
        let (t_lo, t_hi) = limits::TURBINE_SPEED_PU;
        let max_shaft_rpm = limits::SHAFT_SPEED_OF_MAX_REF
            * sc.controllers.speed.max_shaft_rpm.max(crate::numerics::units::rad_s_to_rpm(1.0));
        let p_both_mw = crate::ship::hull::N_SHAFTS as f64 * sc.plant.motor.rated_power_w / 1e6;
        let v_max = v_hi * sc.bus_voltage_ref_v();
        let r_brake = sc.plant.dc_link.brake_resistor_ohm;
        let brake_mj = if r_brake > 0.0 {
            crate::ship::hull::N_SHAFTS as f64 * v_max * v_max / r_brake * (ev.window_s + sc.sim.record_interval_s)
                / 1e6
        } else {
            0.0
        };
        let declared = |name: &'static str| -> Result<(&'static str, f64, f64), String> {
            let m = crate::scenario::registry::find(&format!("rare_event.{name}"))
                .ok_or_else(|| format!("rare_event.{name}: no such parameter"))?;
            Ok((name, m.min.unwrap_or(f64::MIN), m.max.unwrap_or(f64::MAX)))
        };
        Ok(TrialLimits {
            seed: sc.sim.seed,
            max_rate_per_s,
            h_over_r: (-h, h),
            values: [
                (v_lo, v_hi, " pu", "the run stops when a bus leaves this band of its set point"),
                (t_lo, t_hi, " pu", "the run stops when a turbine leaves this band of its rated speed"),
                (
                    0.0,
                    2.0 * max_shaft_rpm,
                    " rpm",
                    "a highest minus a lowest speed, each within 3 times the largest shaft reference, where the run stops",
                ),
                (
                    -MAX_POWER_DROP_OF_RATED * p_both_mw,
                    MAX_POWER_DROP_OF_RATED * p_both_mw,
                    " MW",
                    "100 times both motors' rated power: beyond the pull-out torque at the highest bus voltage and shaft speed a run allows",
                ),
                (
                    0.0,
                    brake_mj,
                    " MJ",
                    "the brake resistors' power at the highest bus voltage a run allows, over the window; 0 without resistors",
                ),
            ],
            // The ship starts at the origin and the run stops when it surges faster than
            // SURGE_M_S or sways faster than SWAY_M_S (rounded up to a metre, and one more).
            max_reach_m: libm::ceil(libm::hypot(limits::SURGE_M_S, limits::SWAY_M_S) * ev.time_s) + 1.0,
            place: [
                declared("ship_x_m")?,
                declared("ship_y_m")?,
                declared("ship_heading_deg")?,
                declared("ship_speed_kn")?,
            ],
        })
    }

    /// Checks trial `i`'s record; the error names the field, its value and what is allowed.
    pub fn check(&self, t: &TrialRecord, i: u64) -> Result<(), String> {
        use crate::checks::num;
        // A part in 1e9 of room for rounding.
        let slack = |b: f64| 1e-9 * (1.0 + b.abs());
        let range = |field: &str, x: f64, lo: f64, hi: f64, unit: &str, why: &str| {
            if x.is_finite() && x >= lo - slack(lo) && x <= hi + slack(hi) {
                Ok(())
            } else {
                Err(format!("{field} = {}: must be from {} to {}{unit} ({why})", num(x), num(lo), num(hi)))
            }
        };
        let want = trial_seed(self.seed, i);
        if t.seed != want {
            return Err(format!(
                "seed = {}: trial {i}'s seed is {want} (from the study's sim.seed {} and the trial's number)",
                t.seed, self.seed
            ));
        }
        let nu = t.crossing_rate_per_s;
        if !(nu.is_finite() && nu > 0.0 && nu <= self.max_rate_per_s) {
            return Err(format!(
                "crossing_rate_per_s = {}: a trial's weight is its sea's crossing rate, above 0 and at most {} per second \
                 (the highest encounter frequency of the sea's band at 40 kn)",
                num(nu),
                num(self.max_rate_per_s)
            ));
        }
        range(
            "h_over_r_at_event",
            t.h_over_r_at_event,
            self.h_over_r.0,
            self.h_over_r.1,
            "",
            &format!("the hub within {MAX_HUB_DEPTH_M} m of the surface"),
        )?;
        for ((c, &x), &(lo, hi, unit, why)) in CONSEQUENCES.iter().zip(&t.values).zip(&self.values) {
            range(&format!("values.{}", c.name), x, lo, hi, unit, why)?;
        }
        let place = [t.ship_x_m, t.ship_y_m, t.ship_heading_deg, t.ship_speed_kn];
        for (&x, &(name, lo, hi)) in place.iter().zip(&self.place) {
            range(name, x, lo, hi, "", &format!("rare_event.{name}'s range: the trial's replay sets it"))?;
        }
        let reach = libm::hypot(t.ship_x_m, t.ship_y_m);
        if reach > self.max_reach_m {
            return Err(format!(
                "ship_x_m = {}, ship_y_m = {}: {} m from the start, at most {} m (the fastest a run allows for the \
                 event's time)",
                num(t.ship_x_m),
                num(t.ship_y_m),
                num(reach),
                num(self.max_reach_m)
            ));
        }
        Ok(())
    }
}
