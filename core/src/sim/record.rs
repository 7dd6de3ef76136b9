//! Recording: the row of every signal of [`crate::signals`], computed from the simulator's state by
//! the expressions of the one signal table (`for_each_signal!`).

use super::plant::{slot, Outputs, Plant, State};
use super::plant::{HEADING, N_SETS, N_SHAFTS, SURGE, SWAY, X_POS, YAW_RATE, Y_POS};
use super::seaway::SeaSample;
use super::Controllers;
use crate::numerics::units::{m_s_to_kn, rad_s_to_rpm};
use crate::signals::N_SIGNALS;

/// The ship service filter's slots on each bus.
const FILTER_CURRENT: [usize; N_SHAFTS] = filter_slots("filter_current");
const FILTER_VOLTAGE: [usize; N_SHAFTS] = filter_slots("filter_voltage");

const fn filter_slots(name: &str) -> [usize; N_SHAFTS] {
    let mut out = [0; N_SHAFTS];
    let mut s = 0;
    while s < N_SHAFTS {
        out[s] = match super::plant::part_slot(name, s) {
            Some(i) => i,
            None => panic!("no such bus part state"),
        };
        s += 1;
    }
    out
}

/// Everything a row is computed from, with the sums that several signals share done once.
pub(super) struct Recording<'a> {
    pub t: f64,
    pub plant: &'a Plant,
    pub x: &'a State,
    pub out: &'a Outputs,
    pub ctl: &'a Controllers,
    /// Ordered ship speed [m/s].
    pub speed_cmd: f64,
    /// Bus voltage set point [V].
    pub v_ref: f64,
    /// The seaway's last sample with the hub depth carried to `t`.
    pub sea: SeaSample,
    /// Each hub's depth over the propeller radius at `t` (`sea.hub` over the radius) [-].
    pub h_over_r: [f64; N_SHAFTS],
    /// Sums over machines [W].
    pub p_turbine: f64,
    pub p_motor: f64,
    pub fuel: f64,
}

impl Recording<'_> {
    pub fn mean_shaft(&self, f: impl Fn(usize) -> f64) -> f64 {
        (0..N_SHAFTS).map(f).sum::<f64>() / N_SHAFTS as f64
    }
    pub fn mean_set(&self, f: impl Fn(usize) -> f64) -> f64 {
        (0..N_SETS).map(f).sum::<f64>() / N_SETS as f64
    }
    pub fn rad_to_deg(&self, a: f64) -> f64 {
        crate::numerics::units::rad_to_deg(a)
    }
    pub fn ship_speed_kn(&self) -> f64 {
        m_s_to_kn(super::speed_through_water(self.x))
    }
    pub fn speed_cmd_kn(&self) -> f64 {
        m_s_to_kn(self.speed_cmd)
    }
    pub fn shaft_rpm(&self, s: usize) -> f64 {
        rad_s_to_rpm(self.x[slot::shaft_speed(s)])
    }
    pub fn shaft_ref_rpm(&self) -> f64 {
        rad_s_to_rpm(self.ctl.speed.shaft_ref)
    }
    pub fn turbine_speed_pu(&self, k: usize) -> f64 {
        self.x[slot::turbine_speed(k)] / self.plant.turbine.rated_speed
    }
    pub fn throttle(&self, k: usize) -> f64 {
        self.ctl.held.throttle[k]
    }
    pub fn field_current(&self, k: usize) -> f64 {
        self.x[slot::field_current(k)]
    }
    pub fn bus_voltage(&self, s: usize) -> f64 {
        self.x[slot::bus_voltage(s)]
    }
    pub fn bus_voltage_pu(&self, s: usize) -> f64 {
        self.x[slot::bus_voltage(s)] / self.v_ref
    }
    pub fn motor_voltage_pu(&self, s: usize) -> f64 {
        self.out.motor_voltage[s] / self.plant.motor.v_rated
    }
    pub fn slip(&self, s: usize) -> f64 {
        self.ctl.held.slip[s]
    }
    pub fn filter_ripple_pu(&self) -> f64 {
        let Some(f) = self.plant.bus.loads.as_ref().and_then(|l| l.ship_service.as_ref()) else { return 0.0 };
        (0..N_SHAFTS)
            .map(|s| {
                let (i_l, v_f) = (self.x[FILTER_CURRENT[s]], self.x[FILTER_VOLTAGE[s]]);
                (self.x[slot::bus_voltage(s)] - f.r_ohm * i_l - v_f).abs() / self.v_ref
            })
            .fold(0.0, f64::max)
    }
    pub fn motor_power_pu(&self) -> f64 {
        self.p_motor / N_SHAFTS as f64 / self.plant.motor.p_rated
    }
    pub fn motor_torque(&self, s: usize) -> f64 {
        self.out.motor[s].torque
    }
    pub fn thrust(&self) -> f64 {
        self.out.thrust
    }
    pub fn advance_ratio(&self, s: usize) -> f64 {
        self.out.propeller[s].advance_ratio
    }
    pub fn open_water_efficiency(&self, s: usize) -> f64 {
        self.plant.open_water_efficiency(self.out.propeller[s].advance_ratio)
    }
    pub fn beta_t(&self) -> f64 {
        self.plant.beta_t * self.mean_shaft(|s| self.ctl.held.sea.beta_t[s])
    }
    pub fn beta_q(&self) -> f64 {
        self.plant.beta_q * self.mean_shaft(|s| self.ctl.held.sea.beta_q[s])
    }
    pub fn x_m(&self) -> f64 {
        self.x[X_POS]
    }
    pub fn y_m(&self) -> f64 {
        self.x[Y_POS]
    }
    pub fn heading_deg(&self) -> f64 {
        self.rad_to_deg(self.x[HEADING])
    }
    pub fn heading_ref_deg(&self) -> f64 {
        self.rad_to_deg(self.ctl.psi_ref)
    }
    pub fn rudder_deg(&self) -> f64 {
        self.rad_to_deg(self.ctl.held.rudder)
    }
    pub fn drift_angle_deg(&self) -> f64 {
        self.rad_to_deg(libm::atan2(self.x[SWAY], self.x[SURGE].abs().max(1e-9)))
    }
    pub fn yaw_rate_deg_s(&self) -> f64 {
        self.rad_to_deg(self.x[YAW_RATE])
    }
    pub fn brake_power(&self) -> f64 {
        self.out.brake_power.iter().sum::<f64>()
    }
    pub fn p_generator(&self) -> f64 {
        self.out.rectifier.iter().map(|r| r.p_generator).sum()
    }
    pub fn p_inverter(&self) -> f64 {
        self.out.motor.iter().map(|m| m.p_in).sum()
    }
    pub fn p_ship(&self) -> f64 {
        self.out.resistance * self.x[SURGE]
    }
    pub fn added_resistance(&self) -> f64 {
        -self.ctl.held.sea.wave_fx
    }
    pub fn drift_force(&self) -> f64 {
        self.ctl.held.sea.wave_fy
    }
}

macro_rules! signal_row {
    ($($variant:ident, $name:literal, $unit:literal, $label:literal, $desc:literal, |$r:ident| $e:expr;)*) => {
        /// The row of every signal, in trace column order.
        pub(super) fn row(rec: &Recording) -> [f64; N_SIGNALS] {
            [$({
                let $r = rec;
                $e
            },)*]
        }
    };
}

crate::for_each_signal!(signal_row);
