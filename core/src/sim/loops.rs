//! The discrete control loops of a run, one function a loop, sampled in this order every
//! controller sample (`Simulation::control`): the ship's speed, each set's turbine and field (or
//! its LQG/LTR compensator), the sets' overload watch, each motor's slip, and the heading.

use super::health;
use super::lqg;
use super::plant::{slot, Held, Plant, State, HEADING, N_SETS, N_SHAFTS, SETS_PER_SHAFT, SURGE, YAW_RATE};
use super::speed_through_water;
use crate::control::speed::SpeedController;
use crate::plant::generator::FieldController;
use crate::plant::motor::SlipController;
use crate::plant::prime_mover::Governor;
use crate::ship::rudder::Autopilot;

/// All discrete controllers and their held outputs.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Controllers {
    pub(crate) governor: [Governor; N_SETS],
    pub(crate) field: [FieldController; N_SETS],
    /// With `controllers.design = "lqg_ltr"`: the design and each set's compensator, which then
    /// run throttles and field voltages instead of `governor` and `field`.
    pub(crate) lqg: Option<(lqg::LqgDesign, Vec<lqg::LqgSet>)>,
    pub(crate) slip: [SlipController; N_SHAFTS],
    /// Last peak-torque slip of each motor (warm start of the inline solver) \[rad/s\].
    pub(crate) peak_slip: [f64; N_SHAFTS],
    /// Ship speed loop (calm-water map, PI trim, ramp-limited shaft reference).
    pub(crate) speed: SpeedController,
    /// Whether the slip may go negative (AC braking).
    pub(crate) allow_braking: bool,
    /// Last peak braking slip (warm start) \[rad/s\].
    pub(crate) peak_brake_slip: [f64; N_SHAFTS],
    /// Heading: reference \[rad\] moving to the target at `heading_rate` \[rad/s\] (0: a step).
    pub(crate) psi_ref: f64,
    pub(crate) psi_target: f64,
    pub(crate) heading_rate: f64,
    pub(crate) autopilot: Autopilot,
    pub(crate) held: Held,
    /// What the health checks need that the trace does not show (the motors at their slip limit).
    pub(crate) tracked: health::Tracked,
}

impl Controllers {
    /// Ship speed: calm-water map plus PI trim, then the ramp-limited shaft reference \[rad/s\].
    /// Signed by the surge: a ship the waves carry astern is slower than any order ahead, and
    /// the loop drives ahead against it (with |U| it read as too fast and stopped the shafts).
    pub(crate) fn speed_loop(&mut self, x: &State, speed_cmd: f64, ts: f64) -> f64 {
        let signed_speed = if x[SURGE] < 0.0 { -speed_through_water(x) } else { speed_through_water(x) };
        self.speed.update(speed_cmd, signed_speed, ts)
    }

    /// Each online set's throttle and field voltage: its governor and field PIs, or its LQG/LTR
    /// compensator. An offline set's controllers rest with it.
    pub(crate) fn set_loops(&mut self, p: &Plant, x: &State, ts: f64) {
        let c = self;
        match &mut c.lqg {
            Some((d, sets)) => {
                for (k, set) in sets.iter_mut().enumerate().filter(|(k, _)| c.held.online[*k]) {
                    let (th, v_f) =
                        set.update(d, x[slot::turbine_speed(k)], x[slot::bus_voltage(k / SETS_PER_SHAFT)], ts);
                    c.held.throttle[k] = th;
                    c.held.field_voltage[k] = v_f;
                }
            }
            None => {
                // An offline set's controllers rest with it.
                for k in (0..N_SETS).filter(|&k| c.held.online[k]) {
                    let err = (p.turbine.rated_speed - x[slot::turbine_speed(k)]) / p.turbine.rated_speed;
                    c.held.throttle[k] = c.governor[k].update(err, ts);
                    let s = k / SETS_PER_SHAFT;
                    c.held.field_voltage[k] = c.field[k].update(x[slot::bus_voltage(s)], ts);
                }
            }
        }
    }

    /// The sets' overload watch (the health checks' record of a set beyond its rating).
    pub(crate) fn track_overload(&mut self, p: &Plant, x: &State, t_now: f64, ts: f64) {
        let c = self;
        for k in 0..N_SETS {
            let w = x[slot::turbine_speed(k)];
            let over = c.held.online[k] && health::set_overloaded(p.turbine.torque(c.held.throttle[k], w) * w, w, p);
            c.tracked.overload[k].sample(over, t_now, ts);
        }
    }

    /// Each motor's slip toward the shaft reference `shaft_ref` \[rad/s\], within its torque,
    /// power and (braking) limits.
    pub(crate) fn slip_loops(&mut self, p: &Plant, x: &State, shaft_ref: f64, t_now: f64, ts: f64) {
        let c = self;
        // Runs that go astern take the motors through zero shaft speed: their peak slips come
        // from the global search (`peak_slip_scan`).
        let astern = c.speed.astern();
        for s in 0..N_SHAFTS {
            let w_rm = x[slot::shaft_speed(s)];
            let v_max = p.dc_link.max_phase_voltage(x[slot::bus_voltage(s)]);
            let err = p.motor.pole_pairs * (shaft_ref - w_rm);
            if w_rm < 0.0 && c.allow_braking {
                let (slip, at_limit) = c.slip_astern(p, s, w_rm, v_max, err, ts);
                c.held.slip[s] = slip;
                c.tracked.slip_limit[s].sample(at_limit, t_now, ts);
                continue;
            }
            // The upper slip limit (power-limited slip below the peak-torque slip) takes two
            // iterative solves; it changes nothing unless the PI's output or integrator would
            // reach it. Both are below it when the torque there still rises with slip (below the
            // peak) and gives less than rated power, which two circuit evaluations show.
            let reach = c.slip[s].pi.unsaturated(err).max(c.slip[s].pi.integral + c.slip[s].pi.ki * err * ts);
            // (With a zero-slip offset the output may jump to the offset: it must lie below too.)
            let reach = reach.max(c.slip[s].offset);
            let limit = if p.motor.below_slip_limits(w_rm, v_max, reach, p.motor.p_rated) {
                f64::INFINITY
            } else {
                let peak = if astern {
                    p.motor.peak_slip_scan(w_rm, v_max, 1.0)
                } else {
                    p.motor.peak_torque_slip(w_rm, v_max, c.peak_slip[s])
                };
                c.peak_slip[s] = peak;
                p.motor.power_limited_slip(w_rm, v_max, peak, p.motor.p_rated)
            };
            let lower = if c.allow_braking {
                let peak_b = if astern {
                    p.motor.peak_slip_scan(w_rm, v_max, -1.0)
                } else {
                    p.motor.peak_braking_slip(w_rm, v_max, c.peak_brake_slip[s])
                };
                c.peak_brake_slip[s] = peak_b;
                p.motor.power_limited_braking_slip(w_rm, v_max, peak_b, p.motor.p_rated)
            } else {
                0.0
            };
            c.held.slip[s] = c.slip[s].update(err, lower, limit, ts);
            c.tracked.slip_limit[s].sample(c.held.slip[s] >= limit, t_now, ts);
        }
    }

    /// Motor `s`'s slip with its shaft turning astern (`w_rm` < 0 \[rad/s\]): the circuit is its own
    /// mirror image, Q(-omega_rm, -omega_s) = -Q(omega_rm, omega_s) (the volts-per-hertz law takes
    /// |omega_e|), so motoring astern is negative slip within the ahead motoring limits at
    /// |omega_rm| (peak torque and rated power), and braking an astern shaft positive slip within
    /// the braking limits there. Only runs that may brake come here (astern orders need it).
    /// Returns the slip [rad/s] and whether it is at the motoring limit.
    fn slip_astern(&mut self, p: &Plant, s: usize, w_rm: f64, v_max: f64, err: f64, ts: f64) -> (f64, bool) {
        let w = -w_rm;
        let peak = p.motor.peak_slip_scan(w, v_max, 1.0);
        let motoring = p.motor.power_limited_slip(w, v_max, peak, p.motor.p_rated);
        let peak_b = p.motor.peak_slip_scan(w, v_max, -1.0);
        let braking = p.motor.power_limited_braking_slip(w, v_max, peak_b, p.motor.p_rated);
        let slip = self.slip[s].update(err, motoring, braking, ts);
        (slip, slip <= -motoring)
    }

    /// Heading: the reference ramps to the target at most at `max_turn_rate` \[rad/s\]; the
    /// autopilot steers the rudder. Returns the heading error \[rad\] when the rudder is hard over.
    pub(crate) fn heading_loop(&mut self, x: &State, max_turn_rate: f64, ts: f64) -> Option<f64> {
        let c = self;
        let gap = c.psi_target - c.psi_ref;
        let rate = c.heading_rate.min(max_turn_rate);
        let r_ref = if rate > 0.0 && gap.abs() > rate * ts {
            c.psi_ref += gap.signum() * rate * ts;
            gap.signum() * rate
        } else {
            c.psi_ref = c.psi_target;
            0.0
        };
        let err = c.psi_ref - x[HEADING];
        // Going astern the water meets the rudders from behind and their side force reverses: the
        // autopilot steers with its errors negated, or it would turn the ship away from its course.
        let sign = if x[SURGE] < 0.0 { -1.0 } else { 1.0 };
        c.held.rudder = c.autopilot.update(sign * err, sign * (r_ref - x[YAW_RATE]), ts);
        (c.held.rudder.abs() >= c.autopilot.max_angle - 1e-9).then_some(err.abs())
    }
}
