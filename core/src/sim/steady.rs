//! The calm-water steady state a run starts from (`initial.speed_kn`): the shaft speed at which
//! the propellers carry the hull's resistance, the motor slip that gives their torque, the
//! rectifier current, field current and throttle that hold the bus and the turbines there.

use super::plant::{Plant, N_SETS, N_SHAFTS, SETS_PER_SHAFT};
use super::SimError;
use crate::numerics::units::{kn_to_m_s, rad_s_to_rpm};
use crate::scenario::Scenario;

/// Relative mismatch of motor and propeller torque above which the motor cannot carry the load.
const TORQUE_MATCH: f64 = 1e-6;

/// One consistent operating point of the whole plant (the same for every set and shaft).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyState {
    /// Ship speed [m/s] and shaft speed [rad/s].
    pub ship_speed: f64,
    pub shaft_speed: f64,
    /// Motor slip [rad/s] and its peak-torque slip (warm start of the controller's solver).
    pub slip: f64,
    pub peak_slip: f64,
    /// Bus voltage [V].
    pub bus_voltage: f64,
    /// Turbine speed [rad/s], throttle [-], field current [A] and voltage [V] of each set.
    pub turbine_speed: f64,
    pub throttle: f64,
    pub field_current: f64,
    pub field_voltage: f64,
}

/// The steady state at the scenario's initial speed; at rest (0 knots) the idle plant: turbines at
/// the set point on idle fuel, shafts stopped, the bus floating at the bridge voltage.
pub fn calm_water(p: &Plant, sc: &Scenario) -> Result<SteadyState, SimError> {
    let w_t = p.turbine.rated_speed;
    let v_ref = sc.bus_voltage_ref_v();
    let u0 = kn_to_m_s(sc.initial.speed_kn);
    // Shaft speed at which the propellers balance the resistance at u0 (with the run's beta_T).
    let (w_rm0, p_inv_shaft, slip0, peak) = if u0 > 0.0 {
        let w = p.equilibrium_shaft_speed(u0);
        let q_p = p.propeller_load(w, u0).torque_nm;
        let v_max = p.dc_link.max_phase_voltage(v_ref);
        let peak = p.motor.peak_torque_slip(w, v_max, 0.0);
        let ws = p.motor.slip_for_torque(w, v_max, peak, q_p);
        let mp = p.motor.operate_vhz(w, ws, v_max);
        if (mp.torque - q_p).abs() > TORQUE_MATCH * q_p.abs().max(1.0) {
            // The volts-per-hertz law sets the flux from the rated voltage and frequency, so those
            // (and the circuit) limit the torque; the inverter caps the voltage.
            let m = &sc.plant.motor;
            // A motor switch of the as_printed section is the likelier cause: name it first.
            let ap = &sc.as_printed;
            let switch = match (ap.motor_p_is_poles, ap.eq_2_5_copper_loss) {
                (true, true) => "as_printed.motor_p_is_poles and as_printed.eq_2_5_copper_loss are on (the motor as \
                                 printed); "
                    .to_string(),
                (true, false) => "as_printed.motor_p_is_poles is on (6 pole pairs, as printed); ".to_string(),
                (false, true) => "as_printed.eq_2_5_copper_loss is on (eq. 2.5's torque, as printed); ".to_string(),
                (false, false) => String::new(),
            };
            return Err(SimError::Setup(format!(
                "{switch}plant.motor.rated_voltage_ll_v = {} (at {} Hz): the motor cannot carry the propeller \
                 torque {:.0} kN m at {:.0} rpm that initial.speed_kn = {} needs; with this volts-per-hertz ratio \
                 and circuit its peak torque is {:.0} kN m at the inverter's {:.0} V (raise the rated voltage, \
                 check the circuit of plant.motor and plant.dc_link.inverter_voltage_ratio, or start slower)",
                m.rated_voltage_ll_v,
                m.rated_frequency_hz,
                q_p / 1e3,
                rad_s_to_rpm(w),
                sc.initial.speed_kn,
                p.motor.operate_vhz(w, peak, v_max).torque / 1e3,
                v_max
            )));
        }
        (w, mp.p_in, ws, peak)
    } else {
        (0.0, 0.0, 0.0, 0.0)
    };
    // Each set carries half its shaft's inverter power at the bus set point, and half of the
    // bus's other loads (their filter's input at t = 0); with fewer online (the buses tied) each
    // online set an equal share of both shafts'.
    let p_bus = p.bus.steady_load_w(v_ref, p_inv_shaft).map_err(SimError::Setup)?;
    let online = crate::plant::online::mask(&sc.plant.online.sets).iter().filter(|&&o| o).count();
    let i_dc = if online == N_SETS {
        p_bus / (SETS_PER_SHAFT as f64 * v_ref)
    } else {
        p_bus * N_SHAFTS as f64 / (online.max(1) as f64 * v_ref)
    };
    let w_e = p.generator.electrical_speed(w_t);
    let r_total = p.dc_link.total_resistance(w_e);
    let e_a = (v_ref + r_total * i_dc) / crate::plant::dc_link::BRIDGE_VOLTAGE_RATIO;
    let i_f = p.generator.field_current_for(e_a, w_t);
    let flow = p.dc_link.rectify(e_a, w_e, v_ref, false);
    let q_load = p.generator.friction_torque(w_t) + flow.p_generator / w_t;
    let throttle = p.turbine.throttle_for(q_load, w_t);
    if !(0.0..=1.0).contains(&throttle) {
        return Err(SimError::Setup(format!(
            "initial.speed_kn = {}: the turbines would need throttle {throttle:.2} (more than full; see plant.turbine)",
            sc.initial.speed_kn
        )));
    }
    Ok(SteadyState {
        ship_speed: u0,
        shaft_speed: w_rm0,
        slip: slip0,
        peak_slip: peak,
        // A shaft at rest with no load draws nothing: the bus floats at the bridge voltage.
        bus_voltage: if u0 > 0.0 || p.bus.draws() { v_ref } else { flow.v_bridge },
        turbine_speed: w_t,
        throttle,
        field_current: i_f,
        field_voltage: p.generator.r_f * i_f,
    })
}
