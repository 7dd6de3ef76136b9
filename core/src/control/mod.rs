//! The discrete PI controller every loop of the ship uses (governor, field, slip, autopilot,
//! ship speed): one type, one anti-windup rule. Beside it: the speed loop (`speed`), the LQG/LTR
//! design of ch. 3.1 (`design`) and the linear-systems toolkit it shares with the IPS study of
//! ch. 4 (`linear`).

pub mod design;
pub mod linear;
pub mod speed;

/// A discrete PI: output `kp e + integral`, clamped to [lo, hi]; the integral advances by
/// `ki e Ts` per sample unless that would push an output sitting at a limit further into it
/// (conditional integration).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DiscretePi {
    pub kp: f64,
    pub ki: f64,
    /// Integrator, in the output's unit (it carries the steady output).
    pub integral: f64,
}

impl DiscretePi {
    pub fn new(kp: f64, ki: f64, integral: f64) -> DiscretePi {
        DiscretePi { kp, ki, integral }
    }

    /// The unsaturated output `kp e + integral` (a caller may add further terms before
    /// [`DiscretePi::saturate`]).
    pub fn unsaturated(&self, err: f64) -> f64 {
        self.kp * err + self.integral
    }

    /// Clamps `unsat` to [`lo`, `hi`] and integrates `err` over `ts` \[s\] under the anti-windup
    /// rule; returns the clamped output.
    pub fn saturate(&mut self, unsat: f64, err: f64, lo: f64, hi: f64, ts: f64) -> f64 {
        if may_integrate(unsat, lo, hi, err) {
            self.integral += self.ki * err * ts;
        }
        unsat.clamp(lo, hi)
    }

    /// One sample: error `err`, output limits [`lo`, `hi`], sample period `ts` \[s\].
    pub fn update(&mut self, err: f64, lo: f64, hi: f64, ts: f64) -> f64 {
        let unsat = self.unsaturated(err);
        self.saturate(unsat, err, lo, hi, ts)
    }
}

/// The anti-windup rule: integrate `err` unless the unsaturated output `unsat`, clamped to
/// [`lo`, `hi`], already sits at the limit that `err` pushes towards.
pub fn may_integrate(unsat: f64, lo: f64, hi: f64, err: f64) -> bool {
    (unsat < hi || err < 0.0) && (unsat > lo || err > 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn anti_windup_rule() {
        assert!(may_integrate(0.5, 0.0, 1.0, 1.0));
        assert!(!may_integrate(1.2, 0.0, 1.0, 1.0));
        assert!(may_integrate(1.2, 0.0, 1.0, -1.0));
        assert!(!may_integrate(-0.1, 0.0, 1.0, -1.0));
    }

    /// A PI on a first-order plant x' = u - x settles at the set point with no steady error, and
    /// held at a limit its integrator does not wind up.
    #[test]
    fn tracks_and_does_not_wind_up() {
        let (mut pi, mut x, ts) = (DiscretePi::new(2.0, 1.0, 0.0), 0.0, 0.01);
        // Closed loop s^2 + 3 s + 1: slowest mode e^(-0.38 t), 80 s leave about 1e-13.
        for _ in 0..8000 {
            let u = pi.update(0.5 - x, -10.0, 10.0, ts);
            x += (u - x) * ts;
        }
        assert!((x - 0.5).abs() < 1e-9, "{x}");
        let mut sat = DiscretePi::new(1.0, 1.0, 0.0);
        for _ in 0..1000 {
            assert_eq!(sat.update(5.0, 0.0, 1.0, ts), 1.0);
        }
        // It integrated only until the output reached the limit.
        assert!(sat.integral < 1.0, "{}", sat.integral);
    }
}
