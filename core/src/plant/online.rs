//! Which turbine-generator sets run: the online set, starting and stopping a set in time, and the
//! rules a running set obeys (the thesis' ch. 6.1 asks for "a more intelligent operating schedule
//! ... for the four prime mover power source"; ch. 2 runs all four).
//!
//! A set is offline (its breaker open, turbine not burning: it gives nothing and its states rest),
//! starting (ordered on, delivering nothing until its start-up time has passed) or online (breaker
//! closed, sharing the load with the other online sets). With all four online the plant is the
//! thesis' split plant: sets 1 and 2 feed shaft 1's bus, sets 3 and 4 shaft 2's. With any set
//! offline the two buses are cross-connected by a bus tie, so that every online set shares the
//! whole propulsion load (one set can drive both shafts, as a crew runs one at cruise).

use crate::checks::Validator;
use serde::{Deserialize, Serialize};

/// Turbine-generator sets in the plant (two per shaft, thesis Fig. 2-1).
pub const SETS: usize = 4;

crate::params! {
    /// The online set and the rules of starting and stopping a set.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct OnlineParams {
        /// Sets 1 and 2 feed shaft 1's bus, 3 and 4 shaft 2's; with fewer than four the buses
        /// are tied.
        pub sets: Vec<u32> = vec![1, 2, 3, 4] => {
            label: "Online sets", unit: "-", range: 1.0..=4.0, source: "ch. 2: all four LM2500 sets run",
            help: "Turbine-generator sets running from the start, by number (1, 2 on shaft 1; 3, 4 on shaft 2); with fewer than four the buses are tied.",
        },
        /// An aeroderivative gas turbine set is started, run up, synchronised and loaded in a
        /// minute or two; the thesis gives no figure.
        pub startup_time_s: f64 = 120.0 => {
            label: "Start-up time", unit: "s", range: 0.0..=3600.0,
            source: "our choice: two minutes from the order to the breaker closing (the thesis gives none)",
            help: "Time from an order that starts a set until it delivers power.",
        },
        /// The generic part-load curve (core/data/gas_turbine_part_load.csv) has data from 30 %
        /// load up; below it the fuel is extrapolated.
        pub min_load_pu: f64 = 0.3 => {
            label: "Minimum load", unit: "pu", range: 0.0..=1.0,
            source: "our choice: 30 % of rating, where the part-load efficiency data begin",
            help: "Least load an online set should carry; the schedule runs no more sets than keep each above it.",
        },
        pub min_running_time_s: f64 = 600.0 => {
            label: "Minimum running time", unit: "s", range: 0.0..=86400.0,
            source: "our choice: ten minutes, so that a set is not cycled on every swing",
            help: "A set stays online at least this long after it came online; an earlier stop order waits.",
        },
        /// The schedule's reserve: the chance that the sea's power swings exceed the online
        /// sets' rating within `reserve_window_s` stays below this (`aes-sim schedule`).
        pub reserve_probability: f64 = 1.0e-3 => {
            label: "Reserve: overload chance", unit: "-", range: 1.0e-9..=0.5,
            source: "our choice: one watch in a thousand overloads the online sets",
            help: "Largest chance that the sea's power swings exceed the online sets' rating within the reserve window.",
        },
        pub reserve_window_s: f64 = 3600.0 => {
            label: "Reserve window", unit: "s", range: 1.0..=86400.0, source: "our choice: one hour",
            help: "The time over which the reserve's overload chance is counted.",
        },
        pub schedule_step_kn: f64 = 1.0 => {
            label: "Schedule speed step", unit: "kn", range: 0.25..=10.0, source: "our choice",
            help: "Step of the schedule's speeds from 0 to its top speed.",
        },
        pub schedule_top_speed_kn: f64 = 30.0 => {
            label: "Schedule top speed", unit: "kn", range: 1.0..=40.0, source: "our choice: about a destroyer's full speed",
            help: "Fastest speed of the schedule (speeds the four sets cannot drive are marked beyond the plant).",
        },
    }
}

impl crate::params::CrossCheck for OnlineParams {
    fn cross_check(&self, v: &mut Validator) {
        check_set_list(&self.sets, "sets", v);
    }
}

/// A list of set numbers: at least one, each from 1 to [`SETS`], none twice.
pub fn check_set_list(sets: &[u32], field: &str, v: &mut Validator) {
    if sets.is_empty() {
        v.fail(field, "[]", format!("at least one set must be online (set numbers 1 to {SETS})"));
    } else if sets.len() > SETS {
        v.fail(field, sets.len(), format!("at most {SETS} sets"));
    }
    for (i, &s) in sets.iter().enumerate().take(SETS + 1) {
        if sets[..i].contains(&s) {
            v.fail(&format!("{field}.{i}"), s, format!("set {s} is listed twice"));
        }
    }
}

/// The sets of a list as a mask (set k+1 at index k); numbers outside 1 to [`SETS`] are ignored
/// (the checks refuse them first).
pub fn mask(sets: &[u32]) -> [bool; SETS] {
    let mut m = [false; SETS];
    for &s in sets {
        if (1..=SETS as u32).contains(&s) {
            m[s as usize - 1] = true;
        }
    }
    m
}

/// The set numbers of a mask, e.g. "1+3".
pub fn label(m: &[bool; SETS]) -> String {
    let v: Vec<String> = (0..SETS).filter(|&k| m[k]).map(|k| (k + 1).to_string()).collect();
    v.join("+")
}

/// Where one set is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SetState {
    /// Breaker open, not burning.
    Offline,
    /// Ordered on: delivers from `ready_at_s` \[s\].
    Starting { ready_at_s: f64 },
    /// Breaker closed since `since_s` \[s\]; a stop order waiting for the minimum running time
    /// stops it at `stop_at_s` \[s\].
    Online { since_s: f64, stop_at_s: Option<f64> },
}

/// The four sets' states and the rules that move them.
#[derive(Debug, Clone, PartialEq)]
pub struct Sets {
    pub state: [SetState; SETS],
    startup_s: f64,
    min_run_s: f64,
}

impl Sets {
    /// The sets at the start of a run: those listed are online (counted as online since long
    /// before, so that a stop order is obeyed at once), the rest offline.
    pub fn new(p: &OnlineParams) -> Sets {
        let m = mask(&p.sets);
        Sets {
            state: std::array::from_fn(|k| {
                if m[k] {
                    SetState::Online { since_s: f64::NEG_INFINITY, stop_at_s: None }
                } else {
                    SetState::Offline
                }
            }),
            startup_s: p.startup_time_s,
            min_run_s: p.min_running_time_s,
        }
    }

    /// Which sets deliver power (breaker closed).
    pub fn online(&self) -> [bool; SETS] {
        std::array::from_fn(|k| matches!(self.state[k], SetState::Online { .. }))
    }

    /// Whether all four are online (the split plant, no bus tie).
    pub fn all_online(&self) -> bool {
        self.online().iter().all(|&o| o)
    }

    /// An order at `t` \[s\] that the sets of `wanted` run: an offline set in it starts (online after
    /// the start-up time), an online set not in it stops (at once, or when its minimum running
    /// time is over). Returns what the order could not do at once, in words.
    pub fn order(&mut self, wanted: &[bool; SETS], t: f64) -> Vec<String> {
        let mut notes = Vec::new();
        for (k, &want) in wanted.iter().enumerate() {
            self.state[k] = match (self.state[k], want) {
                (SetState::Offline, true) => SetState::Starting { ready_at_s: t + self.startup_s },
                (SetState::Starting { .. }, false) => SetState::Offline,
                (SetState::Online { since_s, .. }, false) => {
                    let earliest = since_s + self.min_run_s;
                    if t >= earliest {
                        SetState::Offline
                    } else {
                        notes.push(format!(
                            "set {} was ordered to stop at t = {t:.1} s, {:.0} s after it came online: it runs its \
                             minimum running time (plant.online.min_running_time_s = {}) and stops at t = {earliest:.1} s",
                            k + 1,
                            t - since_s,
                            self.min_run_s
                        ));
                        SetState::Online { since_s, stop_at_s: Some(earliest) }
                    }
                }
                (SetState::Online { since_s, .. }, true) => SetState::Online { since_s, stop_at_s: None },
                (s, _) => s,
            };
        }
        notes
    }

    /// Moves the sets whose time has come at `t` \[s\] (a start-up finished, a waiting stop due);
    /// true when the online set changed.
    pub fn advance(&mut self, t: f64) -> bool {
        let before = self.online();
        for s in self.state.iter_mut() {
            *s = match *s {
                SetState::Starting { ready_at_s } if t >= ready_at_s => {
                    SetState::Online { since_s: ready_at_s, stop_at_s: None }
                }
                SetState::Online { stop_at_s: Some(at), .. } if t >= at => SetState::Offline,
                s => s,
            };
        }
        self.online() != before
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn params(sets: Vec<u32>) -> OnlineParams {
        OnlineParams { sets, startup_time_s: 100.0, min_running_time_s: 600.0, ..OnlineParams::default() }
    }

    /// A started set comes online exactly at its start-up time; a stop order before its minimum
    /// running time waits for it, one after it is obeyed at once.
    #[test]
    fn start_and_stop_follow_their_times() {
        let mut s = Sets::new(&params(vec![1]));
        assert_eq!(s.online(), [true, false, false, false]);
        assert!(s.order(&[true, true, false, false], 10.0).is_empty());
        assert!(!s.advance(109.9));
        assert!(s.advance(110.0));
        assert_eq!(s.online(), [true, true, false, false]);
        // Stop set 2 at 200 s: it came online at 110 s, so it runs until 710 s.
        let notes = s.order(&[true, false, false, false], 200.0);
        assert_eq!(notes.len(), 1);
        assert!(notes[0].contains("stops at t = 710.0 s"), "{}", notes[0]);
        assert!(!s.advance(709.0));
        assert!(s.advance(710.0));
        assert_eq!(s.online(), [true, false, false, false]);
        // Set 1 was online from the start: it stops at once.
        assert!(s.order(&[false, false, true, false], 720.0).is_empty());
        assert_eq!(s.online(), [false, false, false, false]);
        assert!(!s.all_online());
    }

    /// Bad lists are refused with the field named.
    #[test]
    fn set_lists_are_checked() {
        for (sets, what) in [(vec![], "at least one"), (vec![1, 1], "listed twice"), (vec![1, 2, 3, 4, 1], "at most")] {
            let mut v = Validator::new();
            check_set_list(&sets, "sets", &mut v);
            let e = v.finish().unwrap_err();
            assert!(e.to_string().contains(what), "{sets:?}: {e}");
        }
        assert_eq!(label(&mask(&[3, 1])), "1+3");
    }
}
