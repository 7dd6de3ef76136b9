//! Named scenarios, one per study of thesis ch. 5 as they are implemented.

use crate::scenario::{Command, HullModelKind, PropellerModelKind, RectifierKind, Scenario, SeaKind};

/// Names of all presets, in the order of the thesis.
pub const PRESET_NAMES: &[&str] = &[
    "startup",
    "acceleration",
    "acceleration-high-gains",
    "acceleration-lqg-ltr",
    "ac-braking",
    "ac-braking-unbuffered",
    "crash-stop",
    "crash-stop-storage",
    "turn-45",
    "turn-90",
    "turn-360",
    "quarter-turn-ss3",
    "quarter-turn-ss6",
    "fuel-regular-seas",
    "head-seas-ss6",
    "head-seas-ss6-storage",
    "turn-360-ss6",
    "as-printed",
    "mc-excess-energy",
    "mc-arrival",
    "wigley-head-seas",
    "mc-wigley",
];

/// The preset of that name.
pub fn preset(name: &str) -> Option<Scenario> {
    Some(match name {
        "startup" => startup(),
        "acceleration" => acceleration(false),
        "acceleration-high-gains" => acceleration(true),
        "acceleration-lqg-ltr" => acceleration_lqg_ltr(),
        "ac-braking" => ac_braking(true),
        "ac-braking-unbuffered" => ac_braking(false),
        "crash-stop" => crash_stop(false),
        "crash-stop-storage" => crash_stop(true),
        "turn-45" => turn("turn-45", 45.0, None),
        "turn-90" => turn("turn-90", 90.0, None),
        "turn-360" => turn("turn-360", 360.0, Some(1.0)),
        "quarter-turn-ss3" => quarter_turn(3),
        "quarter-turn-ss6" => quarter_turn(6),
        "fuel-regular-seas" => fuel_regular_seas(),
        "head-seas-ss6" => head_seas_ss6(),
        "head-seas-ss6-storage" => head_seas_ss6_storage(),
        "turn-360-ss6" => turn_360_ss6(),
        "as-printed" => as_printed(),
        "mc-excess-energy" => mc_excess_energy(),
        "mc-arrival" => mc_arrival(),
        "wigley-head-seas" => wigley_head_seas(),
        "mc-wigley" => mc_wigley(),
        _ => return None,
    })
}

fn speed(t_s: f64, kn: f64) -> Command {
    Command {
        t_s,
        speed_kn: Some(kn),
        heading_deg: None,
        heading_rate_deg_s: None,
        online_sets: None,
        crash_stop: false,
    }
}

/// Ch. 5.1: idle to 25 knots in calm water with the surge model (Figs. 5-1, 5-2, Tables 5.6-5.7).
pub fn startup() -> Scenario {
    let mut s = Scenario {
        name: "startup".into(),
        description: "Start-up from idle to 25 knots in calm water (thesis ch. 5.1, Figs. 5-1 and 5-2): \
                      power flows turbine -> generator -> inverter -> motor -> ship, each stage losing a little."
            .into(),
        commands: vec![speed(0.0, 25.0)],
        ..Scenario::default()
    };
    s.sim.duration_s = 400.0;
    s
}

/// The start-up ordered to `speed_kn` and run for `duration_s` (Table 5.7 compares its end at 20,
/// 25 and 30 knots after 400 s: the validation report and tests/startup.rs).
pub fn startup_to(speed_kn: f64, duration_s: f64) -> Scenario {
    let mut s = startup();
    s.commands[0].speed_kn = Some(speed_kn);
    s.sim.duration_s = duration_s;
    s
}

/// The maneuvering model, steady at 25 knots.
fn at_speed_maneuvering(name: &str, description: &str) -> Scenario {
    let mut s = Scenario { name: name.into(), description: description.into(), ..Scenario::default() };
    s.hull.model = HullModelKind::Maneuvering;
    s.initial.speed_kn = 25.0;
    s.commands = vec![speed(0.0, 25.0)];
    s
}

/// Ch. 5.2.1: 25 knots to full ahead by a step command (Figs. 5-3 to 5-5).
pub fn acceleration(high_gains: bool) -> Scenario {
    let (name, gains) = if high_gains {
        ("acceleration-high-gains", "higher field gains Kp,v = 0.0003, Ki,v = 0.001 (Fig. 5-5)")
    } else {
        ("acceleration", "the baseline field gains Kp,v = 0.0001, Ki,v = 0.0005 (Figs. 5-3, 5-4)")
    };
    let mut s = at_speed_maneuvering(
        name,
        &format!(
            "Acceleration from 25 knots to full ahead by a step order (thesis ch. 5.2.1) with {gains}: the motors \
             pull hard, the turbines slow down and the bus voltage sags with them until the throttle catches up."
        ),
    );
    s.commands.push(speed(10.0, 40.0));
    s.controllers.speed.shaft_ramp_rpm_per_s = 0.0;
    if high_gains {
        s.controllers.field.kp = 0.0003;
        s.controllers.field.ki = 0.001;
    }
    s.sim.duration_s = 120.0;
    s
}

/// Ch. 5.2.1 with the LQG/LTR controller of ch. 3.1 (applied to our own plant as ch. 3.1.3 asks)
/// in place of the governor and field PIs.
pub fn acceleration_lqg_ltr() -> Scenario {
    let mut s = acceleration(false);
    s.name = "acceleration-lqg-ltr".into();
    s.description = "The acceleration from 25 knots to full ahead (thesis ch. 5.2.1) with one LQG/LTR controller \
         per turbine-generator set (thesis ch. 3.1, designed on our own drive train at 25 knots) in place of the \
         governor and field PIs, with the turbines' speed weighted 10 times the bus voltage: the step from 0.34 to \
         1 pu of motor power is more than the turbines can follow, and with equal weights the compensator holds the \
         bus by taking the turbines' kinetic energy until they stall (0.14 pu). Weighted, they slow to 0.69 pu and \
         the bus dips 40 %, as with the PIs: no linear design rides out this step. Compare with the \
         \"acceleration\" preset."
        .into();
    s.controllers.design = crate::scenario::ControllerDesign::LqgLtr;
    // Equal weights stall the turbines in this step (tests/controllers.rs).
    s.controllers.lqg_ltr.turbine_speed_weight = 10.0;
    s
}

/// Ch. 5.2.2: AC braking from 25 knots, with a brake resistor (ideal power management, Fig. 5-7)
/// or with the energy flowing back to the turbines (Fig. 5-8).
pub fn ac_braking(ideal: bool) -> Scenario {
    let mut s = if ideal {
        at_speed_maneuvering(
            "ac-braking",
            "AC braking from 25 knots (thesis ch. 5.2.2, Figs. 5-6, 5-7): the motors run as generators with negative \
             slip, the ship's kinetic energy flows back into the DC buses and a brake resistor burns it; the turbines \
             idle.",
        )
    } else {
        at_speed_maneuvering(
            "ac-braking-unbuffered",
            "AC braking from 25 knots without a brake resistor (thesis ch. 5.2.2, Fig. 5-8): the returned energy \
             flows back through reversible rectifiers into the generators and the turbines overspeed with the \
             throttle closed.",
        )
    };
    s.propeller.model = PropellerModelKind::FourQuadrant;
    s.controllers.slip.allow_braking = true;
    if ideal {
        s.plant.dc_link.brake_resistor_ohm = 1.0;
    } else {
        s.plant.dc_link.rectifier = RectifierKind::Reversible;
    }
    s.controllers.speed.shaft_ramp_rpm_per_s = 10.0;
    // Water brakes take over at low speed (ch. 5.2.2): AC braking orders 10 knots.
    s.commands.push(speed(10.0, 10.0));
    s.sim.duration_s = 120.0;
    s
}

/// Energy each bus's storage in `crash-stop-storage` holds \[J\]: the brake resistors of
/// `crash-stop` burn 86 MJ (43 MJ a bus), and a storage charges from its set point (0.55) to its
/// top (0.9), so 43 MJ needs 123 MJ; 150 MJ leaves a margin (tests/astern.rs: the resistors then
/// burn 5.8 MJ).
pub const CRASH_STOP_STORAGE_J: f64 = 150.0e6;

/// The full-astern stopping test (IMO MSC.137(76) 5.3.4) from 25 knots through the whole drive
/// train: a crash-stop order reverses the shafts at once, the windmilling propellers drive the
/// motors as generators (ch. 5.2.2's AC braking), the brake resistors burn what the buses cannot
/// hold, and the ship stops and goes astern. With `storage`, a battery on each bus sized to the
/// brake energy takes it instead.
pub fn crash_stop(storage: bool) -> Scenario {
    let mut s = at_speed_maneuvering(
        if storage { "crash-stop-storage" } else { "crash-stop" },
        if storage {
            "The crash stop from 25 knots (crash-stop) with a 150 MJ, 20 MW battery on each bus behind its DC-DC \
             converter, sized so that its charge from the set point to the top holds what the brake resistors burn \
             without it: the storage takes the regenerated energy, so the resistors burn less and the bus stays \
             lower."
        } else {
            "The crash stop from 25 knots (IMO's full-astern stopping test): full astern at once, the windmilling \
             propellers drive the motors as generators, the brake resistors burn the ship's kinetic energy that \
             the buses cannot take, the turbines unload, and the ship stops dead in the water and goes astern."
        },
    );
    s.propeller.model = PropellerModelKind::FourQuadrant;
    s.controllers.slip.allow_braking = true;
    s.plant.dc_link.brake_resistor_ohm = 1.0;
    s.commands.push(Command { crash_stop: true, ..speed(10.0, 0.0) });
    s.commands[1].speed_kn = None;
    if storage {
        s.plant.storage.energy_j = CRASH_STOP_STORAGE_J;
        s.plant.storage.power_w = 20.0e6;
    }
    // The step from motoring to full braking is the sharpest transient of any preset: at RK4's
    // 1 ms its energy books close to 2.7e-9 of the turbines' work, at 0.5 ms (the error falls as
    // dt^4) to the 1e-9 of the runs ahead.
    s.stepping.dt_s = 0.0005;
    s.sim.duration_s = 300.0;
    s
}

/// Ch. 5.2.3: heading changes at 25 knots (Figs. 5-9, 5-10, 5-16 in calm water).
pub fn turn(name: &str, heading_deg: f64, rate_deg_s: Option<f64>) -> Scenario {
    let what = if heading_deg >= 360.0 {
        "A full turn at 25 knots (thesis Fig. 5-16 in calm water), ordered as a heading ramp of 1 degree per second \
         (r' = 0.19 on this hull): the autopilot holds the ship on the ramp, so the radius is L / r', about 5 ship \
         lengths; the thesis' 3 lengths need a ramp of r' = 1/3"
            .to_string()
    } else {
        format!("A {heading_deg:.0} degree heading change at 25 knots (thesis ch. 5.2.3, Figs. 5-9 and 5-10)")
    };
    let mut s = at_speed_maneuvering(
        name,
        &format!("{what}: the hull turns less streamlined, the propellers see an altered inflow, and the motors need more power to hold speed."),
    );
    s.commands.push(Command {
        t_s: 10.0,
        speed_kn: None,
        heading_deg: Some(heading_deg),
        heading_rate_deg_s: rate_deg_s,
        online_sets: None,
        crash_stop: false,
    });
    s.sim.duration_s = if heading_deg >= 360.0 { 500.0 } else { 300.0 };
    s
}

/// Ch. 5.2.4: a 90 degree turn at 25 knots in a random sea from ahead, sea state 3 or 6 (Fig. 5-11):
/// added resistance slows the ship and the drift force pushes it sideways.
pub fn quarter_turn(sea_state: u32) -> Scenario {
    let mut s = at_speed_maneuvering(
        &format!("quarter-turn-ss{sea_state}"),
        &format!(
            "A 90 degree turn at 25 knots in sea state {sea_state} from ahead (thesis ch. 5.2.4, Fig. 5-11): the \
                waves' second-order forces add resistance and, once the sea is on the beam, push the ship \
                sideways (drift)."
        ),
    );
    s.sea.kind = SeaKind::Random;
    s.sea.sea_state = sea_state;
    s.seakeeping.grid.roll_wave_amplitude_m = 0.5 * s.sea.spectrum().0;
    s.commands.push(Command {
        t_s: 20.0,
        speed_kn: None,
        heading_deg: Some(90.0),
        heading_rate_deg_s: None,
        online_sets: None,
        crash_stop: false,
    });
    s.sim.duration_s = 300.0;
    s.sim.seed = 1;
    sea_step(&mut s);
    s
}

/// Ch. 5.2.4, Fig. 5-12: 25 knots in a regular head sea of 1 ft amplitude at 0.6 rad/s; `aes-sim fuel`
/// sweeps amplitude (1 to 5 ft), frequency and heading (head and bow seas) from this scenario.
pub fn fuel_regular_seas() -> Scenario {
    let mut s = at_speed_maneuvering(
        "fuel-regular-seas",
        "Travel at 25 knots in a regular head sea (thesis ch. 5.2.4, Fig. 5-12): the added resistance raises the \
            power and with it the fuel burnt by each gas turbine. `aes-sim fuel` sweeps 1 to 5 ft waves over \
            frequency for head and bow seas.",
    );
    s.sea.kind = SeaKind::Regular;
    s.sea.amplitude_m = 0.3048;
    s.sea.omega_rad_s = 0.6;
    s.seakeeping.grid.roll_wave_amplitude_m = 0.3048;
    s.sim.duration_s = 120.0;
    sea_step(&mut s);
    s
}

/// Ch. 5.3.1: 25 knots in head seas, sea state 6, 80 s (Figs. 5-13 to 5-15).
pub fn head_seas_ss6() -> Scenario {
    let mut s = head_seas_thesis_depth();
    s.description = "25 knots into head seas of sea state 6 (thesis ch. 5.3.1, Figs. 5-13 to 5-15) with the \
         propeller hub raised to stand for a light (ballast) loading: the 4.5 m propellers turn with their hub \
         only h0 = 3.5 m below the calm surface and their tips 1.25 m below it (the hull keeps the 5415's \
         draft, mass and RAOs; only the hub moves). As the stern rises and falls in the waves \
         the hub depth swings by about 2 m: with the consistent hub depth (the stern follows the long waves) \
         the propellers ventilate six or seven times each in the 80 s (h/R below 1.1; seed 1), the discs reach the \
         surface two to four times, and the motor's power drops to 0.14-0.33 pu in the deepest dips. Fully loaded \
         (h0 = 6 m, the thesis' depth) they stay down; with the hub depth of eq. 2.57 as printed \
         (seakeeping.stern_motion) they ventilate at either depth, far more often."
        .into();
    s.set_hub_depth_m(3.5);
    s
}

/// The storage of the "with storage" preset on each bus (storage sizing's suggested size, docs/studies/storage-sizing.md, for
/// head-seas-ss6 at the ballast hub depth): 200 MJ (56 kWh) at 10 MW, levelling above 0.02 Hz.
pub fn suggested_storage() -> crate::scenario::StorageParams {
    crate::scenario::StorageParams { energy_j: 200.0e6, power_w: 10.0e6, corner_hz: 0.02, ..Default::default() }
}

/// head-seas-ss6 with the suggested storage on each bus: the pair "without storage / with
/// storage" (ch. 5.2.2, 6.1).
pub fn head_seas_ss6_storage() -> Scenario {
    let mut s = head_seas_ss6();
    s.name = "head-seas-ss6-storage".into();
    s.description = "head-seas-ss6 (25 knots into head seas of sea state 6, the hub at the ballast depth h0 = 3.5 m) \
         with a 200 MJ, 10 MW battery on each bus behind its DC-DC converter: it takes the fast part of the \
         propulsion load (above 0.02 Hz) and supports the bus by droop, so the turbines see only the slow part. \
         Compare with head-seas-ss6: the turbines' speed swing and the bus's sags all but vanish while the \
         propellers ventilate just as before; the state of charge drifts down as the mean load climbs."
        .into();
    s.plant.storage = suggested_storage();
    s
}

/// The head-seas run at the thesis' hub depth h0 = 6 m (the base of the Monte Carlo studies, which
/// set their own depth and propeller).
fn head_seas_thesis_depth() -> Scenario {
    let mut s = at_speed_maneuvering("head-seas-ss6", "");
    s.sea.kind = SeaKind::Random;
    s.sea.sea_state = 6;
    s.sim.duration_s = 80.0;
    s.sim.seed = 1;
    sea_step(&mut s);
    s
}

/// The thesis' equations as printed (`core/src/as_printed.rs`): head seas SS6 at 25 knots with the
/// hub at the thesis' h0 = 6 m, every switch of `as_printed` on that lets the run start at 25 kn
/// and eq. 2.57's sign as printed. The two motor switches are off: with either the motor cannot
/// carry the propeller's 944 kN m at 25 kn (peak torque 654 kN m with P read as poles, 61 kN m
/// with eq. 2.5's copper-loss torque) and the set-up refuses the run.
pub fn as_printed() -> Scenario {
    let mut s = head_seas_thesis_depth();
    s.name = "as-printed".into();
    s.description = "The thesis' equations as printed, in its ch. 5.3 run (25 knots into head seas of sea state 6, \
        hub at h0 = 6 m): the Doppler shift counted twice (eqs. 2.55, 2.59), Appendix A's eqs. 5 and 17, eq. 2.47's \
        conjugate, E_a line to line (the bus at 9.7 kV), Tables 5.1/5.5's ship (L 180 m, x_p 75 m, 7000 t) and eq. 2.57's sign. What you see: Appendix A's typo in A35 \
        makes the destroyer heave by about 16 m, so the propellers leave the water again and again (h/R down to -7), \
        the motor power falls to nothing each time, the shaft speed swings between 209 and 263 rpm, the mean \
        second-order force pushes the ship forward, and the turbines overspeed to 1.4 pu and then stall (0.3 pu). The thesis says that only a small fraction of the propeller \
        emerges in this run and that its heave and pitch agree with other programs, so its code did not use \
        Appendix A as printed; eq. 2.57's sign alone (seakeeping.stern_motion) gives its ch. 5.3 \
        picture: ventilation and swings of tens of rpm (201 to 234 rpm). The motor switches (P as poles, eq. 2.5) \
        are off: with either the motor cannot carry the propeller at 25 knots."
        .into();
    s.as_printed = crate::as_printed::AsPrintedParams {
        doppler_twice: true,
        appendix_a_typos: true,
        eq_2_47_conjugate: true,
        ea_line_to_line: true,
        table_5_ship: true,
        ..Default::default()
    };
    s.seakeeping.stern_motion = crate::scenario::SternMotion::ThesisEq257;
    s.hull.forces = crate::ship::maneuvering::ManeuveringForces::Table23;
    s.seakeeping.short_wave_force = crate::sea::seakeeping::reflection::ShortWaveForce::SalvesenF7;
    s
}

/// Ch. 5.3.2: the full turn at 25 knots in sea state 6, starting in head seas (Figs. 5-16 to 5-19).
pub fn turn_360_ss6() -> Scenario {
    let mut s = turn("turn-360-ss6", 360.0, Some(1.0));
    s.description = "A full turn at 25 knots in sea state 6 starting in head seas (thesis ch. 5.3.2, Figs. 5-16 \
        to 5-19): the propellers are excited most in head seas, little in following seas, and the motors need \
        well over their straight-line power to hold speed in the turn."
        .into();
    s.sea.kind = SeaKind::Random;
    s.sea.sea_state = 6;
    s.sim.seed = 1;
    sea_step(&mut s);
    s
}

/// Ch. 5.4.1 (Figs. 5-20 to 5-23): 100 trials of 80 s at 25 knots in head seas SS6 with a 4.8 m
/// propeller at only h0 = 4.0 m: envelopes of motor power, its histogram at 40 s, the excess energy
/// due to surface effects per trial and the periodogram of motor power.
pub fn mc_excess_energy() -> Scenario {
    let mut s = head_seas_thesis_depth();
    s.name = "mc-excess-energy".into();
    s.description = "Monte Carlo, 100 trials of 80 s at 25 knots in head seas SS6 with a 4.8 m propeller only 4 \
        m deep (thesis ch. 5.4.1, Figs. 5-20 to 5-23): the energy one motor draws over the run against the same \
        sea without surface losses and against calm water, and how its power spreads over trials. Run it with `aes-sim mc` or the Monte Carlo tab."
        .into();
    s.propeller.diameter_m = 4.8;
    s.set_hub_depth_m(4.0);
    s.monte_carlo.trials = 100;
    s.monte_carlo.excess_energy = true;
    s
}

/// Ch. 5.4.2 (Table 5.8, Figs. 5-24, 5-25): arrival time of the first surface effect with a 4.8 m
/// propeller at h0 = 6.0 m, 200 trials stopped 12 s after their first event, 90 s cap; compared with
/// Rice's rate. With the consistent hub depth (eq. 2.57 corrected) surface effects at h0 = 6 m are
/// several thousand times rarer (Rice: about 1e-5 per second for either hub against 0.09), so
/// this study uses eq. 2.57 as printed, as the thesis did.
pub fn mc_arrival() -> Scenario {
    let mut s = head_seas_thesis_depth();
    s.name = "mc-arrival".into();
    s.description = "Monte Carlo, 200 trials at 25 knots in head seas SS6 with a 4.8 m propeller 6 m deep, each \
        stopped 12 s after its first surface effect or at 90 s (thesis ch. 5.4.2, Table 5.8, Figs. 5-24 and \
        5-25): the arrival times against Rice's up-crossing rate. Uses the hub depth of eq. 2.57 as printed, as \
        the thesis did; with the corrected sign such events are about seven thousand times rarer."
        .into();
    s.propeller.diameter_m = 4.8;
    s.set_hub_depth_m(6.0);
    s.seakeeping.stern_motion = crate::scenario::SternMotion::ThesisEq257;
    s.sim.duration_s = 90.0;
    s.monte_carlo.trials = 200;
    s.monte_carlo.stop_at_first_event = true;
    s.monte_carlo.envelope_signals = vec!["im_power_pu".into(), "h_over_r".into()];
    s
}

/// Any hull end to end (issue 15): the same plant on the Wigley hull (L 100 m, B 10 m, T 6.25 m,
/// `ship_hull`) at 20 knots (Fn 0.33) in head seas of sea state 5: its heave and pitch resonance
/// lies near this encounter frequency, where strip theory gives its largest motions.
pub fn wigley_head_seas() -> Scenario {
    let mut s = at_speed_maneuvering(
        "wigley-head-seas",
        "The Wigley hull, the classic seakeeping test hull (L 100 m, parabolic sections), with this plant at \
         20 knots (Froude number 0.33) into head seas of sea state 5: the encounter frequency of the energetic \
         waves is near its heave and pitch resonance, so it pitches and heaves more than the destroyer would, \
         and the propellers, 6.1 m deep, come near the surface.",
    );
    s.ship.hull.name = "wigley".into();
    s.commands[0].speed_kn = Some(20.0);
    s.initial.speed_kn = 20.0;
    s.sea.kind = SeaKind::Random;
    s.sea.sea_state = 5;
    s.sim.duration_s = 60.0;
    s.sim.seed = 1;
    sea_step(&mut s);
    s
}

/// Monte Carlo on the Wigley hull: 50 trials of `wigley_head_seas` (envelopes of motor power, h/R
/// and shaft speed, the histogram of motor power at 40 s).
pub fn mc_wigley() -> Scenario {
    let mut s = wigley_head_seas();
    s.name = "mc-wigley".into();
    s.description = "Monte Carlo on the Wigley hull: 50 trials of 60 s at 20 knots in head seas of sea state 5. \
        How the motor power, the hub depth and the shaft speed spread over random seas on a hull of one's own."
        .into();
    s.monte_carlo.trials = 50;
    s
}

/// The runs in waves step at 5 ms, the controllers' sample period, by the midpoint rule: in head
/// seas SS6 the traces agree with 1 ms RK4 steps to 0.035 rpm, 0.15 % of the peak motor power
/// and 0.004 pu of bus voltage, as close as RK4 at 5 ms (0.035 rpm, 0.12 %, 0.0035 pu): the sea's
/// inputs held over a step, not the method, set the error there. A trial costs 0.48 of one by
/// RK4 at 2.5 ms (scripts/bench-vs-baseline.sh; accuracy: tests/multirate.rs,
/// `wave_presets_step_of_5_ms_matches_1_ms`; issue 17).
fn sea_step(s: &mut Scenario) {
    s.stepping.dt_s = 0.005;
    s.stepping.integrator = crate::numerics::Integrator::Midpoint;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_is_valid() {
        for n in PRESET_NAMES {
            let s = preset(n).unwrap();
            s.validate().unwrap();
            assert_eq!(&s.name, n);
            assert!(!s.description.is_empty());
        }
        assert!(preset("nope").is_none());
    }
}
