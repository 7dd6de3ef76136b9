//! The coupled drive train: two independent shafts, each with two turbine-generator sets, one DC
//! bus, one motor and one propeller, pushing one hull (thesis Fig. 2-1, split plant).
//!
//! The continuous state is a flat array advanced by RK4; the layout constants below name every
//! slot. Energy accumulators ride along in the same array so that the energy books are integrated
//! with exactly the same scheme as the states they describe.

use crate::dc_link::{DcLink, RectifierFlow};
use crate::generator::SyncGenerator;
use crate::motor::{InductionMotor, MotorPoint};
use crate::prime_mover::GasTurbine;
use crate::propeller::{OpenWater, PropellerLoad};
use crate::scenario::Scenario;
use crate::surge::Surge;
use std::f64::consts::PI;

/// Shafts (independent plants).
pub const N_SHAFTS: usize = 2;
/// Turbine-generator sets per shaft.
pub const SETS_PER_SHAFT: usize = 2;
/// Turbine-generator sets in all.
pub const N_SETS: usize = N_SHAFTS * SETS_PER_SHAFT;

/// Turbine shaft speed of set k [rad/s].
pub const fn omega_t(k: usize) -> usize {
    k
}
/// Field current of set k [A].
pub const fn field_current(k: usize) -> usize {
    N_SETS + k
}
/// Bus voltage of shaft s [V].
pub const fn bus_voltage(s: usize) -> usize {
    2 * N_SETS + s
}
/// Propeller shaft speed of shaft s [rad/s].
pub const fn omega_rm(s: usize) -> usize {
    2 * N_SETS + N_SHAFTS + s
}
/// Ship surge speed u [m/s].
pub const SURGE: usize = 2 * N_SETS + 2 * N_SHAFTS;
/// Distance run x [m].
pub const X_POS: usize = SURGE + 1;
/// First energy accumulator [J]; see [`Energy`].
pub const ENERGY0: usize = X_POS + 1;
/// Number of energy accumulators.
pub const N_ENERGY: usize = 13;
/// Size of the state vector.
pub const NX: usize = ENERGY0 + N_ENERGY;

/// The state vector.
pub type State = [f64; NX];

/// Indices of the energy accumulators (offsets from [`ENERGY0`]); sums over all machines.
#[derive(Debug, Clone, Copy)]
#[repr(usize)]
pub enum Energy {
    /// Turbine shaft work, sum of Q_t omega_t.
    Turbine = 0,
    /// Generator friction, sum of Q_fric omega_t.
    Friction,
    /// Generator electrical output, sum of 3 Re{E_a i_s^*}.
    Generator,
    /// Generator stator copper loss.
    StatorLoss,
    /// Notching resistance loss R_p i^2.
    NotchingLoss,
    /// Inverter output, sum of 3 Re{v_m i_in^*}.
    Inverter,
    /// Motor stator copper loss.
    MotorStatorLoss,
    /// Motor rotor copper loss.
    MotorRotorLoss,
    /// Motor mechanical (eta_m) loss.
    MotorMechLoss,
    /// Motor shaft output, sum of Q_m omega_rm.
    Motor,
    /// Power absorbed by the propellers, sum of Q_p omega_rm.
    Propeller,
    /// Thrust power, sum of T_p u.
    Thrust,
    /// Work against resistance, R_sp u (Table 5.6 "ship").
    Ship,
}

/// Held controller outputs (piecewise constant between controller samples).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Held {
    /// Throttle of each turbine [fraction].
    pub throttle: [f64; N_SETS],
    /// Field voltage of each generator [V].
    pub field_voltage: [f64; N_SETS],
    /// Slip speed of each motor [rad/s electrical].
    pub slip: [f64; N_SHAFTS],
}

/// Everything algebraic at one instant.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Outputs {
    pub turbine_torque: [f64; N_SETS],
    pub friction_torque: [f64; N_SETS],
    pub generator_torque: [f64; N_SETS],
    pub emf: [f64; N_SETS],
    pub rectifier: [RectifierFlow; N_SETS],
    /// Largest motor phase voltage the inverter can make now [V].
    pub motor_v_max: [f64; N_SHAFTS],
    /// Motor phase voltage applied [V].
    pub motor_voltage: [f64; N_SHAFTS],
    pub motor: [MotorPoint; N_SHAFTS],
    pub propeller: [PropellerLoad; N_SHAFTS],
    /// Total thrust [N].
    pub thrust: f64,
    /// Resistance R_sp [N].
    pub resistance: f64,
}

/// Model constants of the whole drive train.
#[derive(Debug, Clone, PartialEq)]
pub struct Plant {
    pub turbine: GasTurbine,
    pub generator: SyncGenerator,
    pub dc_link: DcLink,
    pub motor: InductionMotor,
    pub open_water: OpenWater,
    pub surge: Surge,
    pub prop_diameter: f64,
    pub rho: f64,
    pub rotative_efficiency: f64,
    pub shaft_inertia: f64,
    pub beta_t: f64,
    pub beta_q: f64,
}

impl Plant {
    pub fn new(sc: &Scenario) -> Result<Plant, String> {
        let turbine = GasTurbine::new(&sc.plant.turbine);
        let generator = SyncGenerator::new(&sc.plant.generator, turbine.rated_speed);
        let dc_link = DcLink {
            capacitance: sc.plant.dc_link.capacitance_f,
            r_p: sc.plant.dc_link.notching_resistance_ohm,
            l_commutation: sc.plant.generator.stator_inductance_h,
            r_stator_dc: 18.0 / (PI * PI) * sc.plant.generator.stator_resistance_ohm,
            inverter_voltage_ratio: sc.plant.dc_link.inverter_voltage_ratio,
        };
        Ok(Plant {
            turbine,
            generator,
            dc_link,
            motor: InductionMotor::new(&sc.plant.motor),
            open_water: OpenWater::from_params(&sc.propeller)?,
            surge: Surge::new(&sc.ship),
            prop_diameter: sc.propeller.diameter_m,
            rho: sc.ship.water_density_kg_m3,
            rotative_efficiency: sc.propeller.rotative_efficiency,
            shaft_inertia: sc.propeller.shaft_inertia_kg_m2,
            beta_t: sc.propeller.beta_t,
            beta_q: sc.propeller.beta_q,
        })
    }

    /// Propeller thrust and torque at shaft speed `omega` [rad/s] and ship speed `u` [m/s].
    pub fn propeller_load(&self, omega: f64, u: f64) -> PropellerLoad {
        self.open_water.load(
            omega / (2.0 * PI),
            self.surge.advance_speed(u),
            self.prop_diameter,
            self.rho,
            self.rotative_efficiency,
            self.beta_t,
            self.beta_q,
        )
    }

    /// The algebraic outputs and the state derivative `dx` at state `x` with held controls `h`.
    pub fn evaluate(&self, x: &State, h: &Held, out: &mut Outputs, dx: &mut State) {
        let mut e = [0.0; N_ENERGY];
        let u = x[SURGE];
        let mut thrust = 0.0;
        for s in 0..N_SHAFTS {
            let v_c = x[bus_voltage(s)];
            let mut i_rect = 0.0;
            for k in s * SETS_PER_SHAFT..(s + 1) * SETS_PER_SHAFT {
                let w_t = x[omega_t(k)];
                let i_f = x[field_current(k)];
                let q_t = self.turbine.torque(h.throttle[k], w_t); // eq. 2.1
                let q_fric = self.generator.friction_torque(w_t);
                let e_a = self.generator.emf(w_t, i_f);
                let flow = self
                    .dc_link
                    .rectify(e_a, self.generator.electrical_speed(w_t), v_c); // eqs. 2.8-2.9
                                                                              // Eq. 2.3 with the shaft (not electrical) speed, so that power is conserved for any pole count.
                let q_g = if w_t.abs() > 1e-6 {
                    flow.p_generator / w_t
                } else {
                    0.0
                };
                dx[omega_t(k)] = (q_t - q_fric - q_g) / self.turbine.inertia; // eq. 2.4 in rad/s
                dx[field_current(k)] = self.generator.field_current_rate(h.field_voltage[k], i_f); // eq. 2.2
                i_rect += flow.i_dc;
                e[Energy::Turbine as usize] += q_t * w_t;
                e[Energy::Friction as usize] += q_fric * w_t;
                e[Energy::Generator as usize] += flow.p_generator;
                e[Energy::StatorLoss as usize] += flow.p_stator_loss;
                e[Energy::NotchingLoss as usize] += flow.p_notching_loss;
                out.turbine_torque[k] = q_t;
                out.friction_torque[k] = q_fric;
                out.generator_torque[k] = q_g;
                out.emf[k] = e_a;
                out.rectifier[k] = flow;
            }
            let w_rm = x[omega_rm(s)];
            let v_max = self.dc_link.max_phase_voltage(v_c);
            let omega_e = self.motor.pole_pairs * w_rm + h.slip[s];
            let v_m = self.motor.phase_voltage(omega_e, v_max);
            let mp = self.motor.operate(v_m, omega_e, h.slip[s], w_rm);
            let pl = self.propeller_load(w_rm, u);
            dx[bus_voltage(s)] = self.dc_link.bus_voltage_rate(i_rect, mp.p_in, v_c); // eqs. 2.7, 2.10
            dx[omega_rm(s)] = (mp.torque - pl.torque_nm) / self.shaft_inertia; // eq. 2.6 in rad/s
            thrust += pl.thrust_n;
            e[Energy::Inverter as usize] += mp.p_in;
            e[Energy::MotorStatorLoss as usize] += mp.p_stator_loss;
            e[Energy::MotorRotorLoss as usize] += mp.p_rotor_loss;
            e[Energy::MotorMechLoss as usize] += (mp.torque_em - mp.torque) * w_rm;
            e[Energy::Motor as usize] += mp.torque * w_rm;
            e[Energy::Propeller as usize] += pl.torque_nm * w_rm;
            e[Energy::Thrust as usize] += pl.thrust_n * u;
            out.motor_v_max[s] = v_max;
            out.motor_voltage[s] = v_m;
            out.motor[s] = mp;
            out.propeller[s] = pl;
        }
        let resistance = self.surge.resistance(u);
        dx[SURGE] = self.surge.acceleration(thrust, u); // eq. 2.16
        dx[X_POS] = u;
        e[Energy::Ship as usize] = resistance * u;
        dx[ENERGY0..].copy_from_slice(&e);
        out.thrust = thrust;
        out.resistance = resistance;
    }

    /// Kinetic and electric energy stored in the state [J]: turbine rotors, bus capacitors,
    /// propeller shafts and the ship (with its added mass).
    pub fn stored_energy(&self, x: &State) -> f64 {
        let mut e = 0.0;
        for k in 0..N_SETS {
            e += 0.5 * self.turbine.inertia * x[omega_t(k)] * x[omega_t(k)];
        }
        for s in 0..N_SHAFTS {
            e += 0.5 * self.dc_link.capacitance * x[bus_voltage(s)] * x[bus_voltage(s)];
            e += 0.5 * self.shaft_inertia * x[omega_rm(s)] * x[omega_rm(s)];
        }
        e + 0.5 * self.surge.mass_total * x[SURGE] * x[SURGE]
    }
}

/// One classical fourth-order Runge-Kutta step of `dt` [s] (held controls), with no allocation.
pub fn rk4_step(plant: &Plant, x: &mut State, h: &Held, dt: f64, out: &mut Outputs) {
    let mut k1 = [0.0; NX];
    let mut k2 = [0.0; NX];
    let mut k3 = [0.0; NX];
    let mut k4 = [0.0; NX];
    let mut y = [0.0; NX];
    plant.evaluate(x, h, out, &mut k1);
    for i in 0..NX {
        y[i] = x[i] + 0.5 * dt * k1[i];
    }
    plant.evaluate(&y, h, out, &mut k2);
    for i in 0..NX {
        y[i] = x[i] + 0.5 * dt * k2[i];
    }
    plant.evaluate(&y, h, out, &mut k3);
    for i in 0..NX {
        y[i] = x[i] + dt * k3[i];
    }
    plant.evaluate(&y, h, out, &mut k4);
    for i in 0..NX {
        x[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
}
