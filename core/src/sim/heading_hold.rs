//! Why the heading got away with the rudder hard over: an ordered turn faster than full rudder
//! gives, or waves whose yaw moment (M_add of eq. 2.24) the rudders cannot hold.
//!
//! The autopilot's samples are sorted into two kinds. A turn lasts from the first sample whose
//! heading reference moves until the rudder first comes off its limit after the reference stops
//! (the ship has caught up). Every other sample is a hold: the order is a fixed heading. A lag
//! with the rudder at its limit in a hold is not the order's fault; with a sea it is the waves',
//! and so it is in a turn when the waves' mean yaw moment against the rudder was larger than the
//! rudders' whole moment.

use super::plant::{HullModel, Plant};
use super::{State, SURGE};
use crate::numerics::units::{m_s_to_kn, rad_to_deg};
use crate::ship::rudder::{rudder_force, stern_inflow};

/// Heading error with the rudder at its limit above which a run warns \[rad\] (15 degrees).
pub const LAG_WARN_RAD: f64 = 15.0 * core::f64::consts::PI / 180.0;

/// The yaw moments over the samples of one kind with the rudder at its limit.
#[derive(Debug, Clone, Copy, Default)]
struct Moments {
    /// Largest heading error \[rad\].
    lag: f64,
    samples: u64,
    /// Sums of the waves' yaw moment against the rudder \[N m\], the rudders' moment at their
    /// limit in straight flow \[N m\] and the speed through the water \[m/s\].
    wave_sum: f64,
    rudder_sum: f64,
    speed_sum: f64,
    /// Largest wave yaw moment against the rudder \[N m\].
    wave_max: f64,
}

impl Moments {
    fn add(&mut self, s: &Sample) {
        self.lag = self.lag.max(s.err.abs());
        self.samples += 1;
        self.wave_sum += s.wave_against;
        self.rudder_sum += s.rudder_max;
        self.speed_sum += s.speed;
        self.wave_max = self.wave_max.max(s.wave_against);
    }

    fn mean(&self, sum: f64) -> f64 {
        sum / self.samples.max(1) as f64
    }

    /// The waves' mean yaw moment against the rudder is more than the rudders' whole moment.
    fn waves_win(&self) -> bool {
        self.samples > 0 && self.wave_sum > self.rudder_sum
    }

    /// "(their yaw moment against the rudders averaged 3.4 MN m, up to 15 MN m, against the
    /// rudders' 1.9 MN m at full angle at 2.9 knots)".
    fn words(&self) -> String {
        format!(
            "the waves' yaw moment against the rudders averaged {:.1} MN m (up to {:.1} MN m) while the \
             rudders' full angle gives {:.1} MN m at {:.1} knots",
            self.mean(self.wave_sum) / 1e6,
            self.wave_max / 1e6,
            self.mean(self.rudder_sum) / 1e6,
            m_s_to_kn(self.mean(self.speed_sum))
        )
    }
}

/// The rudders' yaw moment at the limit angle `max_angle` \[rad\] in straight flow at the
/// state's surge speed \[N m\] (eq. 2.24's - x_p F_y; the own hull's rudders in the slipstream
/// of the total thrust `thrust` \[N\]); 0 for the surge model.
pub fn rudder_moment_at_limit(p: &Plant, x: &State, thrust: f64, max_angle: f64) -> f64 {
    let u = x[SURGE];
    match &p.hull_model {
        HullModel::Surge => 0.0,
        HullModel::Maneuvering { rudder, x_p, .. } => {
            let (_, fy) = rudder_force(rudder, p.rho, &stern_inflow(u, 0.0, 0.0, *x_p), max_angle);
            (x_p * fy).abs()
        }
        HullModel::Own { model, .. } => {
            let each = thrust / super::N_SHAFTS as f64;
            let (_, _, n) = model.rudders.forces(p.rho, 0.0, 0.0, p.surge.advance_speed(u), each, max_angle);
            n.abs()
        }
    }
}

/// One autopilot sample as the tracker reads it.
#[derive(Debug, Clone, Copy)]
pub struct Sample {
    /// The heading reference moved at this sample (a turn ordered and under way).
    pub ramping: bool,
    /// The rudder sits at its limit.
    pub saturated: bool,
    /// Heading error psi_ref - psi \[rad\].
    pub err: f64,
    /// The waves' slowly varying yaw moment against the rudder's \[N m\] (positive when it opposes).
    pub wave_against: f64,
    /// The rudders' yaw moment at their limit angle in straight flow at this speed \[N m\], > 0.
    pub rudder_max: f64,
    /// Speed through the water \[m/s\].
    pub speed: f64,
}

/// The run's account of headings lost with the rudder hard over.
#[derive(Debug, Clone, Copy, Default)]
pub struct HeadingHold {
    turning: bool,
    turn: Moments,
    hold: Moments,
}

impl HeadingHold {
    /// Books one autopilot sample.
    pub fn observe(&mut self, s: &Sample) {
        if s.ramping {
            self.turning = true;
        } else if !s.saturated {
            self.turning = false;
        }
        if s.saturated {
            if self.turning {
                self.turn.add(s)
            } else {
                self.hold.add(s)
            }
        }
    }

    /// The warnings for the run (`sea`: the run had waves).
    pub fn warnings(&self, sea: bool) -> Vec<String> {
        let mut w = Vec::new();
        let (turn, hold) = (&self.turn, &self.hold);
        if turn.lag > LAG_WARN_RAD {
            if sea && turn.waves_win() {
                w.push(format!(
                    "the heading fell up to {:.0} degrees behind an ordered turn with the rudder hard over: the \
                     rudders cannot hold the heading against the waves ({})",
                    rad_to_deg(turn.lag),
                    turn.words()
                ));
            } else {
                w.push(format!(
                    "the heading reference ran up to {:.0} degrees ahead of the ship with the rudder hard over: \
                     the ordered turn is faster than full rudder can give at this speed",
                    rad_to_deg(turn.lag)
                ));
            }
        }
        if hold.lag > LAG_WARN_RAD {
            let head = format!(
                "the heading drifted up to {:.0} degrees off its order with the rudder hard over and no turn ordered",
                rad_to_deg(hold.lag)
            );
            w.push(if sea {
                let beaten =
                    if hold.waves_win() { "" } else { ", with the hull's own yaw moment as it swung across the sea" };
                format!("{head}: the rudders cannot hold the heading against the waves ({}{beaten})", hold.words())
            } else {
                format!("{head}: the rudders cannot hold the heading at this speed")
            });
        }
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(ramping: bool, saturated: bool, err_deg: f64, wave: f64) -> Sample {
        Sample { ramping, saturated, err: err_deg.to_radians(), wave_against: wave, rudder_max: 2e6, speed: 1.5 }
    }

    /// A turn the rudder cannot follow in calm water blames the order; the same lag with the
    /// reference still blames the waves, with their moments in MN m. Tolerance: exact words.
    #[test]
    fn a_lag_is_blamed_on_its_cause() {
        let mut turn = HeadingHold::default();
        turn.observe(&sample(true, true, 20.0, 0.0));
        // After the reference stops, the lag while the rudder stays hard over is still the turn's.
        turn.observe(&sample(false, true, 30.0, 0.0));
        let w = turn.warnings(false);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].contains("ordered turn is faster") && w[0].contains("30 degrees"), "{w:?}");

        let mut hold = HeadingHold::default();
        hold.observe(&sample(false, false, 1.0, 1e6));
        hold.observe(&sample(false, true, 10.0, 3e6));
        hold.observe(&sample(false, true, 40.0, 5e6));
        let w = hold.warnings(true);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].contains("no turn ordered") && w[0].contains("against the waves"), "{w:?}");
        assert!(
            w[0].contains("averaged 4.0 MN m (up to 5.0 MN m)") && w[0].contains("gives 2.0 MN m at 2.9 knots"),
            "{w:?}"
        );
        assert!(!w[0].contains("hull's own"), "{w:?}");
    }

    /// A turn ends when the rudder comes off its limit after the reference stops: a later drift
    /// is a hold's.
    #[test]
    fn a_turn_ends_when_the_rudder_comes_off_its_limit() {
        let mut h = HeadingHold::default();
        h.observe(&sample(true, true, 5.0, 0.0));
        h.observe(&sample(false, false, 1.0, 0.0));
        h.observe(&sample(false, true, 20.0, 1e6));
        let w = h.warnings(true);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].contains("no turn ordered") && w[0].contains("hull's own"), "{w:?}");
        // In a turn, waves stronger than the rudders are named too.
        let mut t = HeadingHold::default();
        t.observe(&sample(true, true, 20.0, 3e6));
        let w = t.warnings(true);
        assert!(w[0].contains("behind an ordered turn") && w[0].contains("against the waves"), "{w:?}");
    }
}
