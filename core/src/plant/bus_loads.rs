//! The other loads on each MVDC bus (thesis ch. 6.1: "other ship loads, converters, and
//! distribution branches ... off of the main power bus"): the ship service load behind its
//! regulated converter, and a pulsed load (radar or weapon duty).
//!
//! Ship service: a tightly regulated converter holds its output power whatever its input voltage,
//! so it draws i = P / v_f from its input filter capacitor: a constant-power load (CPL), whose
//! small-signal input resistance -v_f^2 / P is negative. Its input filter is a series L_f, R_f
//! from the bus to the capacitor C_f:
//!
//!   L_f di_L/dt = v_bus - R_f i_L - v_f,     C_f dv_f/dt = i_L - P / v_f.
//!
//! Linearised about v_f0 the pair is stable while the filter's damping beats the load's negative
//! resistance (trace and determinant of its Jacobian; Middlebrook's criterion for a stiff
//! source): P < R_f C_f v_f0^2 / L_f and P < v_f0^2 / R_f ([`ShipService::critical_power_w`]).
//!
//! The converter cannot draw an unbounded current: below [`CPL_MIN_VOLTAGE_PU`] of the bus set
//! point it draws the current of full power at that voltage (an undervoltage current limit), so an
//! unstable filter oscillates in a bounded limit cycle instead of collapsing.
//!
//! Pulsed load: a constant-power load on the bus itself (its own converter and storage are
//! outside the model), a trapezoid of `pulse_power_w` every `pulse_period_s`, `pulse_length_s`
//! long at full power, with ramps of `pulse_ramp_s` on each side.

use crate::checks::Validator;
use serde::{Deserialize, Serialize};

pub use crate::plant::bus_part::Demand;
use crate::plant::bus_part::{Account, Book, BusFlow, BusNode, BusPart, CheckInfo, Column};
use crate::signals::Signal;

/// The ship service filter's states in its block of each bus: inductor current i_L \[A\], capacitor
/// voltage v_f \[V\].
pub const FILTER_CURRENT: usize = 0;
pub const FILTER_VOLTAGE: usize = 1;

/// Oscillation of the ship service filter above which it is unstable rather than following the
/// bus: the largest recorded |v_bus - R_f i_L - v_f| (the inductor's voltage) over the run's
/// second half \[pu of the bus set point\].
pub const FILTER_OSCILLATION_PU: f64 = 0.02;

/// Voltage below which the ship service converter's current stops rising [pu of the bus set
/// point]: its undervoltage current limit.
pub const CPL_MIN_VOLTAGE_PU: f64 = 0.5;

crate::params! {
    /// The loads on each bus besides the propulsion motor (ch. 6.1); none by default.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct BusLoadParams {
        /// A destroyer's ship service load is a few megawatts (DDG-51: three 2.5 MW ship
        /// service generators); 2 MW a bus in the presets that use it.
        pub ship_service_w: f64 = 0.0 => {
            label: "Ship service load", unit: "W", range: 1.0e3..=1.0e8, empty: "none", group: "plant",
            source: "none by default; 2 MW a bus in the presets (a destroyer's few megawatts of ship service)",
            help: "Power of the ship service converter on each bus at t = 0 (constant power, with its own input filter).",
        },
        /// The profile is the level and one step (a later level at a later time).
        pub ship_service_step_s: f64 = 0.0 => {
            label: "Ship service step time", unit: "s", range: 1.0e-3..=1.0e7, empty: "no step", group: "plant",
            source: "our choice", help: "When the ship service load takes its new level.",
        },
        pub ship_service_step_to_w: f64 = 0.0 => {
            label: "Ship service after the step", unit: "W", range: 0.0..=1.0e8, group: "plant",
            source: "our choice", help: "Ship service power of each bus from the step on.",
        },
        /// With R_f and C_f it sets the filter's resonance (25 Hz) and its stability limit
        /// R_f C_f V^2 / L_f = 4.7 MW at 5618 V.
        pub filter_inductance_h: f64 = 4.0e-3 => {
            label: "Ship service filter L", unit: "H", range: 1.0e-5..=1.0, group: "plant",
            source: "our choice: a 25 Hz filter that a 1 ms step resolves, stable to 4.7 MW",
            help: "Series inductance of the ship service converter's input filter.",
        },
        pub filter_resistance_ohm: f64 = 0.06 => {
            label: "Ship service filter R", unit: "Ω", range: 1.0e-4..=10.0, group: "plant",
            source: "our choice: the filter's damping (4.7 MW stability limit)",
            help: "Series resistance of the input filter: its only damping against the load's negative resistance.",
        },
        pub filter_capacitance_f: f64 = 0.01 => {
            label: "Ship service filter C", unit: "F", range: 1.0e-5..=1.0, group: "plant",
            source: "our choice: a 25 Hz filter with 4 mH",
            help: "Capacitance at the ship service converter's input.",
        },
        pub pulse_power_w: f64 = 0.0 => {
            label: "Pulsed load", unit: "W", range: 1.0e3..=1.0e8, empty: "none", group: "plant",
            source: "none by default (radar or weapon duty)",
            help: "Power of the pulsed load on each bus while a pulse is on.",
        },
        pub pulse_length_s: f64 = 2.0 => {
            label: "Pulse length", unit: "s", range: 1.0e-3..=1.0e5, group: "plant", source: "our choice",
            help: "Time at full power in each pulse (the ramps come on top).",
        },
        pub pulse_period_s: f64 = 10.0 => {
            label: "Pulse period", unit: "s", range: 1.0e-3..=1.0e5, group: "plant", source: "our choice",
            help: "Time from the start of one pulse to the next.",
        },
        pub pulse_ramp_s: f64 = 0.1 => {
            label: "Pulse ramp", unit: "s", range: 0.0..=1.0e3, group: "plant", source: "our choice",
            help: "Rise and fall time of each pulse.",
        },
        pub pulse_start_s: f64 = 0.0 => {
            label: "First pulse", unit: "s", range: 0.0..=1.0e7, group: "plant", source: "our choice",
            help: "When the first pulse starts to rise.",
        },
    }
}

impl crate::params::CrossCheck for BusLoadParams {
    fn cross_check(&self, v: &mut Validator) {
        if self.pulse_power_w > 0.0 && self.pulse_length_s + 2.0 * self.pulse_ramp_s > self.pulse_period_s {
            v.fail(
                "pulse_length_s",
                crate::checks::num(self.pulse_length_s),
                format!(
                    "with its two ramps of {} s must fit in pulse_period_s = {} s (a pulse longer than its period)",
                    self.pulse_ramp_s, self.pulse_period_s
                ),
            );
        }
    }
}

impl BusLoadParams {
    /// Whether any load is on the buses (the filter states then take part).
    pub fn any(&self) -> bool {
        self.has_ship_service() || self.pulse_power_w > 0.0
    }

    /// Whether the ship service converter and its filter are present.
    pub fn has_ship_service(&self) -> bool {
        self.ship_service_w > 0.0 || (self.ship_service_step_s > 0.0 && self.ship_service_step_to_w > 0.0)
    }

    /// The largest power the loads of one bus draw at once \[W\].
    pub fn peak_w(&self) -> f64 {
        let service = if self.ship_service_step_s > 0.0 {
            self.ship_service_w.max(self.ship_service_step_to_w)
        } else {
            self.ship_service_w
        };
        service + self.pulse_power_w
    }
}

/// The ship service converter with its input filter, and the pulsed load, of one bus.
#[derive(Debug, Clone, PartialEq)]
pub struct BusLoads {
    pub ship_service: Option<ShipService>,
    pub params: BusLoadParams,
    /// Voltage below which the loads' currents stop rising \[V\] ([`CPL_MIN_VOLTAGE_PU`]).
    pub v_min: f64,
}

/// The ship service converter's input filter and its constant-power load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShipService {
    pub l_h: f64,
    pub r_ohm: f64,
    pub c_f: f64,
    /// Voltage below which its current stops rising \[V\] ([`CPL_MIN_VOLTAGE_PU`]).
    pub v_min: f64,
}

/// The ship service filter's rates and flows at one instant.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct FilterFlow {
    /// di_L/dt \[A/s\], dv_f/dt \[V/s\].
    pub di_l: f64,
    pub dv_f: f64,
    /// Current the converter draws from the filter capacitor \[A\].
    pub i_load: f64,
    /// Power the converter takes (its output: constant power above its current limit) \[W\].
    pub p_load: f64,
    /// Filter resistance loss R_f i_L^2 \[W\].
    pub p_loss: f64,
}

impl ShipService {
    /// The filter's rates with the bus at `v_bus`, the filter at (`i_l`, `v_f`) and the converter
    /// asking for `p` \[W\].
    pub fn flow(&self, v_bus: f64, i_l: f64, v_f: f64, p: f64) -> FilterFlow {
        let i_load = p / v_f.max(self.v_min);
        FilterFlow {
            di_l: (v_bus - self.r_ohm * i_l - v_f) / self.l_h,
            dv_f: (i_l - i_load) / self.c_f,
            i_load,
            p_load: v_f * i_load,
            p_loss: self.r_ohm * i_l * i_l,
        }
    }

    /// The filter's steady state (i_L, v_f) with the bus at `v_bus` and the load at `p`: the upper
    /// root of v_f^2 - v_bus v_f + R_f p = 0 (None when the load is beyond what the filter's
    /// resistance passes, p > v_bus^2 / (4 R_f)).
    pub fn steady(&self, v_bus: f64, p: f64) -> Option<(f64, f64)> {
        let disc = v_bus * v_bus - 4.0 * self.r_ohm * p;
        if disc < 0.0 {
            return None;
        }
        let v_f = 0.5 * (v_bus + libm::sqrt(disc));
        Some((p / v_f, v_f))
    }

    /// The largest constant power the filter feeds stably from a stiff bus at `v_bus` \[W\]: the
    /// smaller of the trace condition P < R_f C_f v_f^2 / L_f (damping against the load's
    /// negative resistance) and the determinant's P < v_f^2 / R_f, solved with v_f at its steady
    /// value for that P (bisection on the power).
    pub fn critical_power_w(&self, v_bus: f64) -> f64 {
        let margin = |p: f64| -> f64 {
            match self.steady(v_bus, p) {
                Some((_, v_f)) => {
                    let v2 = v_f * v_f;
                    (self.r_ohm * self.c_f * v2 / self.l_h).min(v2 / self.r_ohm) - p
                }
                None => -1.0,
            }
        };
        let hi = v_bus * v_bus / (4.0 * self.r_ohm);
        if margin(hi) > 0.0 {
            return hi;
        }
        crate::numerics::bisect(margin, 0.0, hi, 200)
    }

    /// The filter's resonance 1 / sqrt(L_f C_f) \[rad/s\].
    pub fn resonance_rad_s(&self) -> f64 {
        1.0 / libm::sqrt(self.l_h * self.c_f)
    }
}

impl BusLoads {
    /// The loads of `p`, with the bus set point `v_ref` \[V\]; None without any load.
    pub fn new(p: &BusLoadParams, v_ref: f64) -> Option<BusLoads> {
        if !p.any() {
            return None;
        }
        Some(BusLoads {
            ship_service: p.has_ship_service().then_some(ShipService {
                l_h: p.filter_inductance_h,
                r_ohm: p.filter_resistance_ohm,
                c_f: p.filter_capacitance_f,
                v_min: CPL_MIN_VOLTAGE_PU * v_ref,
            }),
            params: p.clone(),
            v_min: CPL_MIN_VOLTAGE_PU * v_ref,
        })
    }

    /// The ship service level at time `t` \[s\]: after the step (if any) its new level.
    pub fn ship_service_at(&self, t: f64) -> f64 {
        let p = &self.params;
        if p.ship_service_step_s > 0.0 && t >= p.ship_service_step_s {
            p.ship_service_step_to_w
        } else {
            p.ship_service_w
        }
    }

    /// The pulsed load at time `t` \[s\]: a trapezoid every period.
    pub fn pulse_at(&self, t: f64) -> f64 {
        let p = &self.params;
        if p.pulse_power_w <= 0.0 || t < p.pulse_start_s {
            return 0.0;
        }
        let tau = (t - p.pulse_start_s) % p.pulse_period_s;
        let r = p.pulse_ramp_s;
        let shape = if tau < r {
            tau / r
        } else if tau < r + p.pulse_length_s {
            1.0
        } else if tau < 2.0 * r + p.pulse_length_s {
            (2.0 * r + p.pulse_length_s - tau) / r
        } else {
            0.0
        };
        p.pulse_power_w * shape
    }

    /// What the loads demand at time `t` \[s\].
    pub fn demand(&self, t: f64) -> Demand {
        Demand { ship_service_w: self.ship_service_at(t), pulse_w: self.pulse_at(t) }
    }
}

impl BusPart for BusLoads {
    type Params = BusLoadParams;
    const STATES: &'static [&'static str] = &["filter_current", "filter_voltage"];
    const ACCOUNTS: &'static [Account] = &[
        Account { name: "ship_service", book: Book::Load },
        Account { name: "pulsed", book: Book::Load },
        Account { name: "filter_loss", book: Book::Loss },
    ];
    const DRAWS: bool = true;

    fn build(p: &BusLoadParams, v_ref: f64) -> Option<BusLoads> {
        BusLoads::new(p, v_ref)
    }
    fn present(p: &BusLoadParams) -> bool {
        p.any()
    }
    /// Only the ship service's filter has states.
    fn linearized(p: &BusLoadParams) -> bool {
        p.has_ship_service()
    }

    /// The ship service filter's input at its steady state and the pulsed load.
    fn steady_input_w(&self, v_bus: f64) -> Result<f64, String> {
        let d = self.demand(0.0);
        let service = match &self.ship_service {
            Some(f) => {
                let (i_l, _) = f.steady(v_bus, d.ship_service_w).ok_or_else(|| {
                    format!(
                        "plant.loads.ship_service_w = {}: more than the filter's resistance passes from the bus \
                         (at most v^2 / (4 R_f) = {:.1} MW)",
                        d.ship_service_w,
                        v_bus * v_bus / (4.0 * f.r_ohm) / 1e6
                    )
                })?;
                v_bus * i_l
            }
            None => 0.0,
        };
        Ok(service + d.pulse_w)
    }

    /// The filter at rest (none: 0).
    fn start(&self, v_bus: f64, _p_load: f64, x: &mut [f64]) {
        let (i, v) = match &self.ship_service {
            Some(f) => f.steady(v_bus, self.demand(0.0).ship_service_w).unwrap_or((0.0, v_bus)),
            None => (0.0, 0.0),
        };
        x[FILTER_CURRENT] = i;
        x[FILTER_VOLTAGE] = v;
    }

    /// The filter's rates and the pulsed load: constant power on the bus, current-limited like
    /// the converter.
    #[inline(always)]
    fn derivatives(&self, x: &[f64], node: &mut BusNode, dx: &mut [f64], e: &mut [f64], flow: &mut BusFlow) {
        let v_c = node.v;
        dx[FILTER_CURRENT] = 0.0;
        dx[FILTER_VOLTAGE] = 0.0;
        if let Some(service) = &self.ship_service {
            let (i_l, v_f) = (x[FILTER_CURRENT], x[FILTER_VOLTAGE]);
            let f = service.flow(v_c, i_l, v_f, node.demand.ship_service_w);
            dx[FILTER_CURRENT] = f.di_l;
            dx[FILTER_VOLTAGE] = f.dv_f;
            node.i_draw += i_l;
            node.p_load += v_c * i_l;
            e[0] += f.p_load;
            e[2] += f.p_loss;
            flow.ship_service_w = f.p_load;
            flow.ship_service_in_w = v_c * i_l;
            flow.filter_voltage_v = v_f;
        }
        let i_p = node.demand.pulse_w / v_c.max(self.v_min);
        node.i_draw += i_p;
        node.p_load += v_c * i_p;
        e[1] += v_c * i_p;
        flow.pulse_w = v_c * i_p;
    }

    /// The filter's inductor and capacitor.
    fn add_stored_energy(&self, x: &[f64], e: &mut f64) {
        if let Some(service) = &self.ship_service {
            *e += 0.5 * service.l_h * x[FILTER_CURRENT] * x[FILTER_CURRENT];
            *e += 0.5 * service.c_f * x[FILTER_VOLTAGE] * x[FILTER_VOLTAGE];
        }
    }

    fn checks() -> Vec<CheckInfo> {
        vec![
            CheckInfo {
                name: "ship service filter oscillating",
                threshold: format!(
                    "the ship service filter's inductor voltage (the magnitude of v_bus - R_f i_L - v_f) above {FILTER_OSCILLATION_PU} pu \
                     at a recorded time in the run's second half"
                ),
                reason: "a constant-power load's negative input resistance -v^2/P beats its input filter's damping \
                         (on a stiff bus P above R_f C_f v^2 / L_f; `aes-sim stability-map` finds a plant's boundary): the \
                         filter rings at its resonance and grows \
                         until the converter's current limit holds it in a limit cycle",
            },
        ]
    }

    /// The ship service filter's oscillation.
    fn assess(l: &BusLoadParams, t: &[f64], column: Column<'_>, out: &mut Vec<String>) {
        if !l.has_ship_service() {
            return;
        }
        let ripple = column(Signal::FilterRipplePu);
        let half = ripple.len() / 2;
        let (i, top) = ripple[half..].iter().enumerate().fold((0, 0.0), |m, (i, &v)| if v > m.1 { (i, v) } else { m });
        if top > FILTER_OSCILLATION_PU {
            let f_hz = 1.0 / (2.0 * std::f64::consts::PI * (l.filter_inductance_h * l.filter_capacitance_f).sqrt());
            out.push(format!(
                "ship service filter oscillating: its inductor voltage reaches {top:.3} pu at t = {:.1} s, above \
                 {FILTER_OSCILLATION_PU} pu: the {:.1} MW constant-power load's negative resistance beats the filter's \
                 damping and it rings near its {f_hz:.1} Hz resonance (on a stiff bus stable below R_f C_f v^2 / L_f; \
                 `aes-sim stability-map` finds this plant's boundary)",
                t[half + i],
                l.ship_service_w.max(l.ship_service_step_to_w) / 1e6
            ));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn filter() -> ShipService {
        let p = BusLoadParams::default();
        ShipService {
            l_h: p.filter_inductance_h,
            r_ohm: p.filter_resistance_ohm,
            c_f: p.filter_capacitance_f,
            v_min: 0.0,
        }
    }

    /// The steady state draws what the load takes plus the filter's loss, and its rates vanish
    /// (measured residuals 1e-13 A/s and 0 V/s).
    #[test]
    fn steady_filter_is_at_rest() {
        let f = filter();
        let (i, v) = f.steady(5618.0, 2.0e6).unwrap();
        let fl = f.flow(5618.0, i, v, 2.0e6);
        assert!(fl.di_l.abs() < 1e-6 && fl.dv_f.abs() < 1e-6, "{fl:?}");
        assert!((5618.0 * i - 2.0e6 - fl.p_loss).abs() < 1e-6 * 2.0e6);
    }

    /// The default filter's limit is R C V^2 / L at the filter's steady voltage: 4.72 MW at
    /// 5618 V (the trace condition; the determinant's v^2 / R is 500 MW).
    #[test]
    fn critical_power_is_the_trace_condition() {
        let f = filter();
        let p = f.critical_power_w(5618.0);
        let (_, v_f) = f.steady(5618.0, p).unwrap();
        let closed = f.r_ohm * f.c_f * v_f * v_f / f.l_h;
        assert!((p - closed).abs() < 1e-6 * closed, "{p} {closed}");
        assert!(p > 4.6e6 && p < 4.8e6, "{p}");
    }

    /// A pulse rises, holds and falls within its period; steps take effect at their time.
    #[test]
    fn profiles() {
        let p = BusLoadParams {
            ship_service_w: 1.0e6,
            ship_service_step_s: 5.0,
            ship_service_step_to_w: 3.0e6,
            pulse_power_w: 4.0e6,
            pulse_length_s: 1.0,
            pulse_period_s: 4.0,
            pulse_ramp_s: 0.5,
            pulse_start_s: 1.0,
            ..Default::default()
        };
        let l = BusLoads::new(&p, 5618.0).unwrap();
        assert_eq!(l.ship_service_at(4.9), 1.0e6);
        assert_eq!(l.ship_service_at(5.0), 3.0e6);
        assert_eq!(l.pulse_at(0.5), 0.0);
        assert!((l.pulse_at(1.25) - 2.0e6).abs() < 1e-6);
        assert_eq!(l.pulse_at(2.0), 4.0e6);
        assert!((l.pulse_at(2.75) - 2.0e6).abs() < 1e-6);
        assert_eq!(l.pulse_at(4.0), 0.0);
        assert_eq!(l.pulse_at(5.5), 4.0e6);
    }
}
