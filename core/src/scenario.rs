//! The scenario: everything one run needs, as a public JSON format.
//!
//! Defaults are the thesis' values (Tables 2.1, 5.1-5.5). Where the thesis leaves a value open, the
//! chosen value and the reason stand next to the field. Units are in the field names; speeds of
//! rotating machines are given in rpm and ship speeds in knots because that is how engineers state
//! them; the physics converts to SI on load.

use crate::maneuvering::AbkowitzCoefficients;
use crate::rudder::{AutopilotParams, RudderParams};
use serde::{Deserialize, Serialize};
use std::fmt;

/// One complete run: ship, plant, propeller, controllers, commands and simulation settings.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Scenario {
    /// Short name (shown in summaries).
    pub name: String,
    /// One or two sentences for the reader: what this run shows.
    pub description: String,
    pub ship: ShipParams,
    pub hull: HullParams,
    pub rudder: RudderParams,
    pub propeller: PropellerParams,
    pub plant: PlantParams,
    pub controllers: ControllerParams,
    /// Time-stamped commands; the latest command whose time has come is in force.
    pub commands: Vec<Command>,
    pub initial: InitialConditions,
    pub sim: SimSettings,
    /// The sea (calm unless set).
    pub sea: SeaParams,
    /// Ship motions in waves and the propeller's surface losses (used when the sea is not calm).
    pub seakeeping: SeakeepingParams,
    /// What a Monte Carlo study of this scenario collects (`aes-sim mc`, the page's Monte Carlo
    /// tab); a single run ignores it.
    pub monte_carlo: MonteCarloParams,
}

/// A Monte Carlo study (thesis ch. 5.4): trial i runs the scenario with the sea of seed
/// `trial_seed(sim.seed, i)`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct MonteCarloParams {
    pub trials: u64,
    /// Signals whose envelope over trials (mean, +-2 sigma, min, max per recorded time) is kept.
    pub envelope_signals: Vec<String>,
    /// Histogram of `histogram_signal` at `histogram_time_s` over [`histogram_lo`, `histogram_hi`)
    /// (empty when the trials end before that time).
    pub histogram_signal: String,
    pub histogram_time_s: f64,
    pub histogram_lo: f64,
    pub histogram_hi: f64,
    pub histogram_bins: u32,
    /// Excess motor energy due to surface effects per trial: against the same trial without
    /// surface losses (doubles the cost).
    pub excess_energy: bool,
    /// Stop a trial `onset_window_s` after its first surface effect (beta_T < 1); trials without
    /// one run to the end and count as censored at `sim.duration_s`.
    pub stop_at_first_event: bool,
    /// Window of motor power kept after the onset [s] (Fig. 5-25).
    pub onset_window_s: f64,
    /// Traces of the first trials kept for display (at most 10).
    pub keep_traces: u32,
    /// Welch segment for the periodogram of motor power [s].
    pub periodogram_segment_s: f64,
}

impl Default for MonteCarloParams {
    fn default() -> Self {
        MonteCarloParams {
            trials: 100,
            envelope_signals: vec!["im_power_pu".into(), "h_over_r".into(), "prop_rpm".into()],
            histogram_signal: "im_power_pu".into(),
            histogram_time_s: 40.0,
            histogram_lo: 0.0,
            histogram_hi: 1.5,
            histogram_bins: 30,
            excess_energy: false,
            stop_at_first_event: false,
            onset_window_s: 12.0,
            keep_traces: 1,
            periodogram_segment_s: 25.6,
        }
    }
}

/// Which sea.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SeaKind {
    Calm,
    /// Bretschneider spectrum (eq. 2.58) sampled into components (ch. 2.5.4).
    Random,
    /// One regular wave (ch. 5.2.4).
    Regular,
}

/// The sea (thesis ch. 2.5.4). Directions are where the waves come FROM, in the earth frame of the
/// ship's heading (0 = north): a ship heading 0 deg in waves from 0 deg meets head seas.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SeaParams {
    pub kind: SeaKind,
    /// Table 2.4 sea state (2 to 6), used unless `h_sig_m` and `omega_n_rad_s` are both set.
    pub sea_state: u32,
    /// Significant wave height H_1/3 [m] and modal frequency [rad/s] (0: from the sea state).
    pub h_sig_m: f64,
    pub omega_n_rad_s: f64,
    /// Mean direction the waves come from [deg].
    pub from_deg: f64,
    /// Number of components N_s (ch. 2.5.4: 100 to 500).
    pub components: u32,
    /// Spectrum bounds [rad/s] (0: 0.6 and 4 times the modal frequency, 99.5 % of the energy).
    pub omega_min_rad_s: f64,
    pub omega_max_rad_s: f64,
    /// Exponent h of the cos^h spreading about the mean direction (0: long-crested).
    pub spreading: f64,
    /// Regular sea: amplitude [m] and frequency [rad/s].
    pub amplitude_m: f64,
    pub omega_rad_s: f64,
}

impl Default for SeaParams {
    fn default() -> Self {
        SeaParams {
            kind: SeaKind::Calm,
            sea_state: 6,
            h_sig_m: 0.0,
            omega_n_rad_s: 0.0,
            from_deg: 0.0,
            components: 200,
            omega_min_rad_s: 0.0,
            omega_max_rad_s: 0.0,
            spreading: 2.0,
            amplitude_m: 0.6096,
            omega_rad_s: 0.6,
        }
    }
}

impl SeaParams {
    /// (H_1/3 [m], modal frequency [rad/s]) of the random sea.
    pub fn spectrum(&self) -> (f64, f64) {
        if self.h_sig_m > 0.0 && self.omega_n_rad_s > 0.0 {
            (self.h_sig_m, self.omega_n_rad_s)
        } else {
            let (w, h) = crate::waves::sea_state(self.sea_state).unwrap_or((0.507, 5.0));
            (h, w)
        }
    }
}

/// How the stern's vertical motion enters the hub depth (eq. 2.57).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SternMotion {
    /// h = h0 + eta_s - eta3 - x_p eta5 with STF's bow-down pitch: the stern rises by
    /// eta3 + x_p eta5, and a hull that follows long waves keeps its propeller at h0.
    Consistent,
    /// Eq. 2.57 as printed, h0 + eta_s - eta3 + x_p eta5: pitch adds to the stern's relative
    /// motion instead of following the wave. Several times larger swings of h/R; with it the
    /// ch. 5.3 runs show the thesis' frequent ventilation at h0 = 6 m.
    #[serde(rename = "thesis_eq_2_57")]
    ThesisEq257,
}

/// Ship motions in waves and propeller surface losses (ch. 2.3, 2.5.4). The seakeeping hull is the
/// DTMB 5415 at 6.15 m draft (`aes-sim rao` takes other hulls).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SeakeepingParams {
    /// The RAO table's grid.
    pub grid: crate::seakeeping::tables::SeakeepingGrid,
    /// Calm-water depth of the propeller hub below the surface, h0 [m] (ch. 5.3: 6.0).
    pub hub_depth_m: f64,
    /// Propellers' distance aft of the centre of gravity [m]: the 5415's LCG is 70.3 m forward of
    /// the aft perpendicular and a destroyer's propellers sit about 0.06 L forward of it, so 62 m.
    pub prop_x_aft_m: f64,
    /// Ventilation starts below this h/R and ends above `ventilation_off_h_over_r` (ch. 2.3; see
    /// `propeller_losses` for why 1.1 starts and 1.3 ends the loop).
    pub ventilation_on_h_over_r: f64,
    pub ventilation_off_h_over_r: f64,
    /// Thrust lost when fully ventilated [-] (ch. 2.3: 0.7).
    pub ventilation_loss: f64,
    /// Revolutions over which the lift returns (Wagner effect) [-] (ch. 2.3: about 4).
    pub recovery_revolutions: f64,
    /// beta_Q = beta_T^m (ch. 2.3: m = 0.85).
    pub torque_exponent: f64,
    /// Wave kinematics are summed every `sample_period_s` and carried between samples by a
    /// second-order Taylor series; RAOs are looked up again every `rao_refresh_s` (quasi-steady
    /// speed and heading, ch. 2.5.4) [s].
    pub sample_period_s: f64,
    pub rao_refresh_s: f64,
    /// Second-order slowly varying forces in the maneuvering equations (eq. 2.60).
    pub second_order_forces: bool,
    /// Propeller surface losses (ch. 2.3); off gives the fully submerged counterpart of a run.
    pub surface_losses: bool,
    /// Sign of the pitch term in the hub depth (eq. 2.57): "consistent" or "thesis_eq_2_57".
    pub stern_motion: SternMotion,
    /// Fuel: turbine thermal efficiency at rated power [-] (ch. 5.1: about 37 %), scaled by the
    /// part-load curve of `core/data/gas_turbine_part_load.csv`.
    pub turbine_rated_efficiency: f64,
}

impl Default for SeakeepingParams {
    fn default() -> Self {
        SeakeepingParams {
            grid: Default::default(),
            hub_depth_m: 6.0,
            prop_x_aft_m: 62.0,
            ventilation_on_h_over_r: 1.1,
            ventilation_off_h_over_r: 1.3,
            ventilation_loss: 0.7,
            recovery_revolutions: 4.0,
            torque_exponent: 0.85,
            sample_period_s: 0.05,
            rao_refresh_s: 0.25,
            second_order_forces: true,
            surface_losses: true,
            stern_motion: SternMotion::Consistent,
            turbine_rated_efficiency: 0.37,
        }
    }
}

/// Ship surge model (thesis eqs. 2.15-2.16, Table 5.1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ShipParams {
    /// Displaced mass m [kg]. Table 5.1: 7e6.
    pub mass_kg: f64,
    /// Surge added mass m_a [kg]. Not given in the thesis; 5 % of the displaced mass, the usual
    /// slender-hull value of -X_udot (Fossen 2011, ch. 6).
    pub added_mass_kg: f64,
    /// Wetted area A_w [m^2]. Table 5.1: 5200.
    pub wetted_area_m2: f64,
    /// Hull drag coefficient C_r [-] of eq. 2.15. Table 5.1: 3e-3.
    pub drag_coeff: f64,
    /// Thrust deduction t [-]. Table 5.1 (called "thrust coefficient" there): 0.1.
    pub thrust_deduction: f64,
    /// Wake fraction w [-] of eq. 2.12. Table 5.1: 0.1.
    pub wake_fraction: f64,
    /// Sea water density rho [kg/m^3]. Table 5.1: 1025.
    pub water_density_kg_m3: f64,
    /// Ship length L [m]. Table 5.5: 180 (used by the maneuvering model).
    pub length_m: f64,
}

/// Which hull model moves the ship.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HullModelKind {
    /// Straight-line surge (eqs. 2.15-2.16), as ch. 5.1 uses for start-up.
    Surge,
    /// Abkowitz 3-DOF maneuvering (eqs. 2.17-2.25) with the rudder; in surge it hands over smoothly
    /// to the surge model below `hull.handover_low_kn`.
    Maneuvering,
}

/// Hull model selection and the maneuvering model's data (ch. 2.4, Table 2.3).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct HullParams {
    /// "surge" (default) or "maneuvering".
    pub model: HullModelKind,
    /// Abkowitz coefficients, non-dimensional x 1e-5 (Table 2.3, the 22-knot set).
    pub abkowitz: AbkowitzCoefficients,
    /// Speed about which the expansion was made, u0 [knots]. Ch. 2.4: 22.
    pub linearization_speed_kn: f64,
    /// Drop the straight-running side force and yaw moment (Y_0, N_0 and their Delta-u terms), as a
    /// port-starboard symmetric hull must (see maneuvering.rs). Default true.
    pub symmetric_hull: bool,
    /// Below this speed surge follows the surge model alone [knots]. Our choice: 17. The Abkowitz
    /// surge polynomial, fitted at 11 and 22 knots, turns propulsive near 11 knots.
    pub handover_low_kn: f64,
    /// Above this speed surge follows the Abkowitz model alone [knots]. Our choice: 21.
    pub handover_high_kn: f64,
}

impl Default for HullParams {
    fn default() -> Self {
        HullParams {
            model: HullModelKind::Surge,
            abkowitz: AbkowitzCoefficients::default(),
            linearization_speed_kn: 22.0,
            symmetric_hull: true,
            handover_low_kn: 17.0,
            handover_high_kn: 21.0,
        }
    }
}

/// Which open-water model the propellers follow.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PropellerModelKind {
    /// Wageningen B-series polynomials, first quadrant only (eqs. 2.11-2.13).
    BSeries,
    /// Four-quadrant B4-70 Fourier series (ch. 5.2.2): any sign of thrust, torque and speed.
    FourQuadrant,
}

/// Wageningen B-series propeller, one per shaft (eqs. 2.11-2.13, Table 5.1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PropellerParams {
    /// Open-water model: "b_series" (default) or "four_quadrant" (needed for braking).
    pub model: PropellerModelKind,
    /// Diameter D [m]. Table 5.1: 4.5.
    pub diameter_m: f64,
    /// Pitch ratio P/D [-]. Table 5.1: 1.0.
    pub pitch_ratio: f64,
    /// Expanded blade area ratio Ae/A0 [-]. Not given in the thesis; 0.75, typical of a five-bladed
    /// destroyer propeller sized against cavitation at 30+ knots.
    pub blade_area_ratio: f64,
    /// Number of blades Z [-]. Not given in the thesis; 5, as on the DDG-51 class.
    pub blades: u32,
    /// Relative rotative efficiency eta_R [-] of eq. 2.11. Not given in the thesis; 0.98 from
    /// Holtrop's twin-screw regression (0.9737 + 0.111 (C_P - 0.0225 lcb) - 0.06325 P/D with
    /// C_P = 0.6, lcb = -1.5 %).
    pub rotative_efficiency: f64,
    /// Moment of inertia of one shaft line (propeller, shaft, motor rotor) [kg m^2].
    /// Table 5.1: 1.33e5.
    pub shaft_inertia_kg_m2: f64,
    /// Thrust loss coefficient beta_T of eq. 2.13 held for the whole run [-]; 1 in deep calm water.
    pub beta_t: f64,
    /// Torque loss coefficient beta_Q of eq. 2.13 held for the whole run [-]; 1 in deep calm water.
    pub beta_q: f64,
}

/// The split plant: per shaft two gas turbine-generator sets, one DC bus and one motor.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PlantParams {
    pub turbine: TurbineParams,
    pub generator: GeneratorParams,
    pub dc_link: DcLinkParams,
    pub motor: MotorParams,
}

/// GE LM2500 gas turbine, linear torque model (eq. 2.1, Table 5.2).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct TurbineParams {
    /// Full-throttle locking torque Q_lock [N m]. Table 5.2: 123 kN m.
    pub locking_torque_nm: f64,
    /// Full-throttle no-load speed n_t,max [rpm]. Table 5.2: 6875.
    pub no_load_speed_rpm: f64,
    /// Governor set point n_t* [rpm]: 60 Hz, ch. 2.1 (3600 rpm for the two-pole generator).
    pub rated_speed_rpm: f64,
    /// Shaft inertia of turbine and generator rotor I_t [kg m^2]. Table 5.2: 400.
    pub inertia_kg_m2: f64,
    /// Rated power [W]: 21.5 MW (ch. 2.1). Per-unit base for turbine power.
    pub rated_power_w: f64,
}

/// Synchronous generator and its field circuit (eqs. 2.2-2.4, Table 5.3).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct GeneratorParams {
    /// Stator resistance R_sg [ohm]. Table 5.3: 2.27e-2.
    pub stator_resistance_ohm: f64,
    /// Stator inductance L_sg [H]. Table 5.3: 0.391 mH. Also the commutating inductance of the
    /// rectifier (X_co = omega L_sg in eq. 2.8).
    pub stator_inductance_h: f64,
    /// Mutual inductance M_g [H]. Table 5.3: 18.0 mH.
    pub mutual_inductance_h: f64,
    /// Number of poles P_g [-]. Table 5.3: 2 (3600 rpm gives 60 Hz).
    pub poles: u32,
    /// Rated line-to-line rms voltage at rated speed [V]. Table 5.3 caption: 4160 V. Sets the
    /// initial field current (about 500 A with E_a taken as phase rms, see generator.rs).
    pub rated_voltage_ll_v: f64,
    /// Field winding resistance R_fg [ohm]. Not given in the thesis; 0.25 ohm puts the no-load
    /// field voltage at 125 V, usual for a 20-25 MVA machine.
    pub field_resistance_ohm: f64,
    /// Field winding inductance L_fg [H]. Not given in the thesis; 0.25 H gives a field time
    /// constant of 1 s, the order of the transient constant T'd of machines of this size.
    pub field_inductance_h: f64,
    /// Field voltage ceiling as a multiple of the no-load field voltage [-]. Not given in the
    /// thesis; 3, a common static-exciter ceiling.
    pub field_ceiling_ratio: f64,
    /// Constant part mu_1 of the friction torque Q_fric = mu_1 + mu_2 omega_t [N m]. Not given in
    /// the thesis; 0 (all of the loss is taken as speed-proportional, see mu_2).
    pub friction_constant_nm: f64,
    /// Viscous part mu_2 [N m s/rad]. Not given in the thesis; 2.46, i.e. 350 kW of friction,
    /// windage and (unmodelled) core loss at 3600 rpm. That constant loss is what Table 5.7's three
    /// generator efficiencies imply (0.35 MW at 20, 25 and 30 knots within 0.03 MW).
    pub friction_viscous_nm_s: f64,
}

/// Rectifier, DC bus and inverter (eqs. 2.7-2.10, Table 5.4).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct DcLinkParams {
    /// Bus capacitance C [F]. Table 5.4: 0.037.
    pub capacitance_f: f64,
    /// Notching resistance R_p between each rectifier and the bus [ohm]. Table 5.4: 0.05.
    pub notching_resistance_ohm: f64,
    /// Largest fundamental phase rms voltage the inverter can make, as a fraction of the bus
    /// voltage [-]. Not given in the thesis; sqrt(2)/pi = 0.450, six-step operation, so that the
    /// nominal 5618 V bus can drive the 4160 V motor at rated frequency with 5 % to spare.
    /// This is the "dynamic saturation of motor voltage" of ch. 2.2.3.
    pub inverter_voltage_ratio: f64,
    /// Rectifier: "diode" (power flows only from the generators to the bus) or "reversible" (an
    /// average model of a converter that also returns power to the generators, as ch. 5.2.2's
    /// unbuffered braking needs to overspeed the turbines).
    pub rectifier: RectifierKind,
    /// Braking (dump) resistor on each bus, switched by a chopper [ohm]; 0 for none. Ch. 5.2.2's
    /// "ideal power management". Our value for the braking preset: 1 ohm (31.6 MW at 5.62 kV).
    pub brake_resistor_ohm: f64,
    /// Bus voltage at which the chopper starts to conduct, per unit of the bus set point [-].
    /// Our choice: 1.10, above the no-load voltage of the generators at the field current of full
    /// power (1.08), so that the resistor takes the braking energy and not the generators' output;
    /// it conducts fully 5 % higher.
    pub brake_on_pu: f64,
}

/// Rectifier average model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RectifierKind {
    Diode,
    Reversible,
}

/// 38 MW induction motor (eqs. 2.5-2.6, Table 2.1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct MotorParams {
    /// Stator resistance R_sm [ohm]. Table 2.1: 2.2 mohm.
    pub stator_resistance_ohm: f64,
    /// Stator leakage inductance L_sm [H]. Table 2.1: 0.198 mH.
    pub stator_inductance_h: f64,
    /// Rotor resistance R_rm [ohm]. Table 2.1: 3.4 mohm.
    pub rotor_resistance_ohm: f64,
    /// Rotor leakage inductance L_rm [H]. Table 2.1: 0.330 mH.
    pub rotor_inductance_h: f64,
    /// Magnetizing inductance L_m [H]. Table 2.1: 11.74 mH.
    pub magnetizing_inductance_h: f64,
    /// Pole pairs [-]. Table 2.1 gives P = 12 and calls it pole pairs, while ch. 2.2.2 writes
    /// omega_r = (P_m/2) omega_rm as if P were poles. Twelve pole pairs make a 300 rpm machine at
    /// 60 Hz whose peak torque (1.34 MN m) delivers 38 MW there; twelve poles would make a 600 rpm
    /// machine, which contradicts the 300 rpm rating of ch. 5. So: 12 pole pairs.
    pub pole_pairs: u32,
    /// Rated line-to-line rms voltage [V]. Table 2.1: 4160.
    pub rated_voltage_ll_v: f64,
    /// Rated frequency [Hz]. Table 2.1: 60.
    pub rated_frequency_hz: f64,
    /// Rated shaft power [W]: 38 MW (ch. 2.2.2). The slip saturation keeps the motor under it.
    pub rated_power_w: f64,
    /// Efficiency eta_m of eq. 2.5 for friction, windage and stray loss [-]. Not given in the
    /// thesis; 0.998, i.e. 0.2 % mechanical loss, usual for large low-speed machines. Applied so
    /// that the loss is positive in both motoring and generating.
    pub efficiency: f64,
}

/// Gains of all the control loops.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ControllerParams {
    /// Sample period of the discrete controllers [s]. Must be a whole number of time steps.
    /// Not given in the thesis (which calls the governor "discrete"); 5 ms.
    pub sample_period_s: f64,
    pub governor: GovernorParams,
    pub field: FieldControlParams,
    pub slip: SlipControlParams,
    pub speed: SpeedControlParams,
    pub autopilot: AutopilotParams,
}

/// Discrete PI governor on turbine speed acting on the throttle (ch. 2.1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct GovernorParams {
    /// Proportional gain K_p,t [throttle fraction per per-unit speed error]. Not given in the
    /// thesis; 10, which with K_i,t gives a critically damped loop near 2 rad/s (throttle moves the
    /// per-unit speed at 0.39 /s per unit throttle at 3600 rpm).
    pub kp: f64,
    /// Integral gain K_i,t [throttle fraction per per-unit speed error per second]. Not given; 10.
    pub ki: f64,
    /// Throttle slew limit Delta_t [1/s]. Not given in the thesis; 0.1, i.e. zero to full fuel in
    /// 10 s, a conservative fuel schedule against compressor surge.
    pub slew_rate_per_s: f64,
}

/// PI control of the bus voltage through the field voltage (ch. 2.2.1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FieldControlParams {
    /// Bus voltage set point [V]: the no-load output of the rectifier (3 sqrt(2)/pi) 4160 V =
    /// 5618 V, the per-unit base of the bus voltage.
    pub bus_voltage_ref_v: f64,
    /// Proportional gain K_p,v [V of field voltage per V of bus error]. Ch. 5.2.1 baseline: 1e-4.
    /// The thesis does not state the units; volts per volt is the reading under which its own
    /// remark holds that this loop acts only "slightly".
    pub kp: f64,
    /// Integral gain K_i,v [V per V s]. Ch. 5.2.1 baseline: 5e-4.
    pub ki: f64,
}

/// Volts-per-hertz slip-speed PI on rotor speed error (ch. 2.2.4).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SlipControlParams {
    /// Proportional gain [rad/s of slip per rad/s of electrical rotor speed error]. Not given in
    /// the thesis; 0.1: near zero slip the motor torque is 430 kN m per rad/s of slip, so the
    /// shaft speed loop closes near 2 rad/s with K_i below.
    pub kp: f64,
    /// Integral gain [rad/s of slip per rad of electrical rotor angle error]. Not given; 0.1.
    pub ki: f64,
    /// Allow negative slip, so the motor brakes as a generator (AC braking, ch. 5.2.2). Only
    /// meaningful with a path for the returned power (brake resistor or reversible rectifier).
    pub allow_braking: bool,
    /// The "offset discontinuity" of ch. 5.2.2 [rad/s]: the slip command skips the band
    /// (-offset, offset). The thesis needed it because its circuit is singular at zero slip; ours
    /// (written in admittances) is regular there, so the default is 0; set it to reproduce the
    /// thesis' scheme.
    pub zero_slip_offset_rad_s: f64,
}

/// Outer ship-speed loop: a calm-water rpm map trimmed by a PI on ship speed error.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SpeedControlParams {
    /// Proportional trim [rpm per knot of ship speed error]. Our design; 4. The calm-water map has
    /// about 8 rpm per knot, so the loop gain is 0.5 and the 30 s surge lag closes near 20 s.
    pub kp_rpm_per_kn: f64,
    /// Integral trim [rpm per knot second]. Our design; 0.2 (a 40 s integral time: it removes the
    /// steady error that waves, turns or fouling leave on the calm-water map).
    pub ki_rpm_per_kn_s: f64,
    /// Largest trim as a fraction of the mapped shaft speed [-]. Our design; 0.4 (a tight turn at
    /// 25 knots needs about a quarter more shaft speed than the straight-line map).
    pub trim_limit: f64,
    /// Rate limit of the shaft speed reference [rpm/s]. Our design; 5 rpm/s keeps the turbines'
    /// load rise within their slew limit. 0 means no limit (a true step command).
    pub shaft_ramp_rpm_per_s: f64,
    /// Largest shaft speed reference [rpm]. Our design; 320 (the motor is rated near 300 rpm and
    /// ch. 5.2.1 shows it overrunning that at full ahead).
    pub max_shaft_rpm: f64,
}

/// A command; the latest one whose time has come is in force.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Command {
    /// Time at which the command takes effect [s].
    pub t_s: f64,
    /// Ordered ship speed [knots]. Omitted: keep the previous order.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub speed_kn: Option<f64>,
    /// Ordered heading [degrees, clockwise from north, not wrapped: 360 means one full turn to
    /// starboard]. Needs `hull.model = "maneuvering"`. Omitted: keep the previous order.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heading_deg: Option<f64>,
    /// Rate at which the heading reference moves to the ordered heading [deg/s]; omitted: the
    /// autopilot's `turn_rate_deg_s`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heading_rate_deg_s: Option<f64>,
}

/// Where the run starts.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct InitialConditions {
    /// Initial ship speed [knots]. With 0 the run starts from idle: turbines at rated speed on
    /// idle fuel, bus charged, shafts stopped. Above 0 the plant starts at the calm-water steady
    /// state for that speed (solved on load).
    pub speed_kn: f64,
}

/// Integration and recording.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SimSettings {
    /// Simulated time [s].
    pub duration_s: f64,
    /// Fixed RK4 step [s]. The DC link time constant is about 3.5 ms, so 1 ms.
    pub dt_s: f64,
    /// Interval between recorded trace rows [s]. Must be a whole number of time steps.
    pub record_interval_s: f64,
    /// Seed of every random number in the run (the calm-water drive train uses none).
    pub seed: u64,
}

impl Default for Scenario {
    fn default() -> Self {
        Scenario {
            name: "custom".into(),
            description: String::new(),
            ship: ShipParams::default(),
            hull: HullParams::default(),
            rudder: RudderParams::default(),
            propeller: PropellerParams::default(),
            plant: PlantParams::default(),
            controllers: ControllerParams::default(),
            commands: vec![Command { t_s: 0.0, speed_kn: Some(25.0), heading_deg: None, heading_rate_deg_s: None }],
            initial: InitialConditions::default(),
            sim: SimSettings::default(),
            sea: SeaParams::default(),
            seakeeping: SeakeepingParams::default(),
            monte_carlo: MonteCarloParams::default(),
        }
    }
}

impl Default for ShipParams {
    fn default() -> Self {
        ShipParams {
            mass_kg: 7.0e6,
            added_mass_kg: 3.5e5,
            wetted_area_m2: 5200.0,
            drag_coeff: 3.0e-3,
            thrust_deduction: 0.1,
            wake_fraction: 0.1,
            water_density_kg_m3: 1025.0,
            length_m: 180.0,
        }
    }
}

impl Default for PropellerParams {
    fn default() -> Self {
        PropellerParams {
            model: PropellerModelKind::BSeries,
            diameter_m: 4.5,
            pitch_ratio: 1.0,
            blade_area_ratio: 0.75,
            blades: 5,
            rotative_efficiency: 0.98,
            shaft_inertia_kg_m2: 1.33e5,
            beta_t: 1.0,
            beta_q: 1.0,
        }
    }
}

impl Default for TurbineParams {
    fn default() -> Self {
        TurbineParams {
            locking_torque_nm: 123.0e3,
            no_load_speed_rpm: 6875.0,
            rated_speed_rpm: 3600.0,
            inertia_kg_m2: 400.0,
            rated_power_w: 21.5e6,
        }
    }
}

impl Default for GeneratorParams {
    fn default() -> Self {
        GeneratorParams {
            stator_resistance_ohm: 2.27e-2,
            stator_inductance_h: 0.391e-3,
            mutual_inductance_h: 18.0e-3,
            poles: 2,
            rated_voltage_ll_v: 4160.0,
            field_resistance_ohm: 0.25,
            field_inductance_h: 0.25,
            field_ceiling_ratio: 3.0,
            friction_constant_nm: 0.0,
            friction_viscous_nm_s: 2.46,
        }
    }
}

impl Default for DcLinkParams {
    fn default() -> Self {
        DcLinkParams {
            capacitance_f: 0.037,
            notching_resistance_ohm: 0.05,
            inverter_voltage_ratio: std::f64::consts::SQRT_2 / std::f64::consts::PI,
            rectifier: RectifierKind::Diode,
            brake_resistor_ohm: 0.0,
            brake_on_pu: 1.10,
        }
    }
}

impl Default for MotorParams {
    fn default() -> Self {
        MotorParams {
            stator_resistance_ohm: 2.2e-3,
            stator_inductance_h: 0.198e-3,
            rotor_resistance_ohm: 3.4e-3,
            rotor_inductance_h: 0.330e-3,
            magnetizing_inductance_h: 11.74e-3,
            pole_pairs: 12,
            rated_voltage_ll_v: 4160.0,
            rated_frequency_hz: 60.0,
            rated_power_w: 38.0e6,
            efficiency: 0.998,
        }
    }
}

impl Default for ControllerParams {
    fn default() -> Self {
        ControllerParams {
            sample_period_s: 0.005,
            governor: GovernorParams::default(),
            field: FieldControlParams::default(),
            slip: SlipControlParams::default(),
            speed: SpeedControlParams::default(),
            autopilot: AutopilotParams::default(),
        }
    }
}

impl Default for GovernorParams {
    fn default() -> Self {
        GovernorParams { kp: 10.0, ki: 10.0, slew_rate_per_s: 0.1 }
    }
}

impl Default for FieldControlParams {
    fn default() -> Self {
        FieldControlParams { bus_voltage_ref_v: 5618.0, kp: 1.0e-4, ki: 5.0e-4 }
    }
}

impl Default for SlipControlParams {
    fn default() -> Self {
        SlipControlParams { kp: 0.1, ki: 0.1, allow_braking: false, zero_slip_offset_rad_s: 0.0 }
    }
}

impl Default for SpeedControlParams {
    fn default() -> Self {
        SpeedControlParams {
            kp_rpm_per_kn: 4.0,
            ki_rpm_per_kn_s: 0.2,
            trim_limit: 0.4,
            shaft_ramp_rpm_per_s: 5.0,
            max_shaft_rpm: 320.0,
        }
    }
}

impl Default for InitialConditions {
    fn default() -> Self {
        InitialConditions { speed_kn: 0.0 }
    }
}

impl Default for SimSettings {
    fn default() -> Self {
        SimSettings { duration_s: 300.0, dt_s: 0.001, record_interval_s: 0.1, seed: 0 }
    }
}

/// One problem with a scenario, naming the field, its value and what is allowed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FieldError {
    /// Dotted path of the field, e.g. `plant.motor.pole_pairs` or `commands.2.speed_kn`.
    pub path: String,
    /// The offending value as text.
    pub value: String,
    /// What is allowed.
    pub message: String,
}

impl fmt::Display for FieldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} = {}: {}", self.path, self.value, self.message)
    }
}

/// Every problem found in a scenario.
#[derive(Debug, Clone, PartialEq)]
pub struct ScenarioError(pub Vec<FieldError>);

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, e) in self.0.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{e}")?;
        }
        Ok(())
    }
}

impl std::error::Error for ScenarioError {}

struct Checker {
    errors: Vec<FieldError>,
}

impl Checker {
    fn range(&mut self, path: &str, v: f64, lo: f64, hi: f64) {
        if !(v.is_finite() && v >= lo && v <= hi) {
            self.errors.push(FieldError {
                path: path.into(),
                value: format!("{v}"),
                message: format!("must be a number from {lo} to {hi}"),
            });
        }
    }
    fn range_u(&mut self, path: &str, v: u64, lo: u64, hi: u64) {
        if v < lo || v > hi {
            self.errors.push(FieldError {
                path: path.into(),
                value: format!("{v}"),
                message: format!("must be a whole number from {lo} to {hi}"),
            });
        }
    }
    fn fail(&mut self, path: &str, value: String, message: &str) {
        self.errors.push(FieldError { path: path.into(), value, message: message.into() });
    }
}

/// How many recorded rows a run may hold; beyond it the run is refused before it starts.
pub const MAX_RECORDED_ROWS: f64 = 2.0e6;
/// How many time steps a run may take.
pub const MAX_STEPS: f64 = 1.0e9;

fn whole_multiple(a: f64, b: f64) -> bool {
    let r = a / b;
    (r - r.round()).abs() < 1e-6 && r.round() >= 1.0
}

impl Scenario {
    /// Checks every field against its allowed range; returns all problems at once.
    pub fn validate(&self) -> Result<(), ScenarioError> {
        let mut c = Checker { errors: Vec::new() };
        let s = &self.ship;
        c.range("ship.mass_kg", s.mass_kg, 1.0e4, 1.0e9);
        c.range("ship.added_mass_kg", s.added_mass_kg, 0.0, 1.0e9);
        c.range("ship.wetted_area_m2", s.wetted_area_m2, 1.0, 1.0e5);
        c.range("ship.drag_coeff", s.drag_coeff, 1.0e-5, 0.1);
        c.range("ship.thrust_deduction", s.thrust_deduction, 0.0, 0.5);
        c.range("ship.wake_fraction", s.wake_fraction, 0.0, 0.6);
        c.range("ship.water_density_kg_m3", s.water_density_kg_m3, 900.0, 1100.0);
        c.range("ship.length_m", s.length_m, 5.0, 500.0);

        let h = &self.hull;
        c.range("hull.linearization_speed_kn", h.linearization_speed_kn, 1.0, 40.0);
        c.range("hull.handover_low_kn", h.handover_low_kn, 0.0, 40.0);
        c.range("hull.handover_high_kn", h.handover_high_kn, 0.0, 40.0);
        if h.handover_high_kn <= h.handover_low_kn {
            c.fail("hull.handover_high_kn", format!("{}", h.handover_high_kn), "must be above hull.handover_low_kn");
        }
        if let Ok(serde_json::Value::Object(map)) = serde_json::to_value(&h.abkowitz) {
            for (name, v) in map {
                c.range(&format!("hull.abkowitz.{name}"), v.as_f64().unwrap_or(f64::NAN), -1.0e6, 1.0e6);
            }
        }
        for (name, v) in [
            ("xudot_minus_m", h.abkowitz.xudot_minus_m),
            ("yvdot_minus_m", h.abkowitz.yvdot_minus_m),
            ("nrdot_minus_iz", h.abkowitz.nrdot_minus_iz),
        ] {
            if v >= 0.0 {
                c.fail(&format!("hull.abkowitz.{name}"), format!("{v}"), "must be negative (added mass less the mass)");
            }
        }
        let r = &self.rudder;
        c.range("rudder.area_m2", r.area_m2, 0.0, 500.0);
        c.range("rudder.x_p_m", r.x_p_m, 0.0, 500.0);
        c.range("rudder.lift_slope", r.lift_slope, 0.0, 10.0);
        c.range("rudder.drag_slope", r.drag_slope, 0.0, 5.0);
        c.range("rudder.max_angle_deg", r.max_angle_deg, 1.0, 45.0);
        c.range("rudder.swing_rate_rad_s", r.swing_rate_rad_s, 0.001, 1.0);
        let p = &self.propeller;
        c.range("propeller.diameter_m", p.diameter_m, 0.1, 15.0);
        // Ranges of the Oosterveld & van Oossanen regression.
        c.range("propeller.pitch_ratio", p.pitch_ratio, 0.5, 1.4);
        c.range("propeller.blade_area_ratio", p.blade_area_ratio, 0.3, 1.05);
        c.range_u("propeller.blades", p.blades as u64, 2, 7);
        c.range("propeller.rotative_efficiency", p.rotative_efficiency, 0.8, 1.2);
        c.range("propeller.shaft_inertia_kg_m2", p.shaft_inertia_kg_m2, 1.0, 1.0e8);
        c.range("propeller.beta_t", p.beta_t, 0.0, 1.0);
        c.range("propeller.beta_q", p.beta_q, 0.0, 1.0);

        let t = &self.plant.turbine;
        c.range("plant.turbine.locking_torque_nm", t.locking_torque_nm, 1.0e3, 1.0e7);
        c.range("plant.turbine.no_load_speed_rpm", t.no_load_speed_rpm, 100.0, 1.0e5);
        c.range("plant.turbine.rated_speed_rpm", t.rated_speed_rpm, 100.0, 1.0e5);
        if t.rated_speed_rpm >= t.no_load_speed_rpm {
            c.fail(
                "plant.turbine.rated_speed_rpm",
                format!("{}", t.rated_speed_rpm),
                "must be below plant.turbine.no_load_speed_rpm (eq. 2.1 gives no torque there)",
            );
        }
        c.range("plant.turbine.inertia_kg_m2", t.inertia_kg_m2, 1.0, 1.0e6);
        c.range("plant.turbine.rated_power_w", t.rated_power_w, 1.0e4, 1.0e9);

        let g = &self.plant.generator;
        c.range("plant.generator.stator_resistance_ohm", g.stator_resistance_ohm, 0.0, 10.0);
        c.range("plant.generator.stator_inductance_h", g.stator_inductance_h, 0.0, 1.0);
        c.range("plant.generator.mutual_inductance_h", g.mutual_inductance_h, 1.0e-5, 10.0);
        if g.poles % 2 != 0 {
            c.fail("plant.generator.poles", format!("{}", g.poles), "must be even (2, 4, ...)");
        }
        c.range_u("plant.generator.poles", g.poles as u64, 2, 64);
        c.range("plant.generator.rated_voltage_ll_v", g.rated_voltage_ll_v, 100.0, 1.0e5);
        c.range("plant.generator.field_resistance_ohm", g.field_resistance_ohm, 1.0e-3, 100.0);
        c.range("plant.generator.field_inductance_h", g.field_inductance_h, 1.0e-3, 100.0);
        c.range("plant.generator.field_ceiling_ratio", g.field_ceiling_ratio, 1.0, 10.0);
        c.range("plant.generator.friction_constant_nm", g.friction_constant_nm, 0.0, 1.0e5);
        c.range("plant.generator.friction_viscous_nm_s", g.friction_viscous_nm_s, 0.0, 1.0e3);

        let d = &self.plant.dc_link;
        c.range("plant.dc_link.capacitance_f", d.capacitance_f, 1.0e-4, 100.0);
        c.range("plant.dc_link.notching_resistance_ohm", d.notching_resistance_ohm, 1.0e-4, 10.0);
        c.range("plant.dc_link.inverter_voltage_ratio", d.inverter_voltage_ratio, 0.1, 0.5);
        if d.brake_resistor_ohm != 0.0 {
            c.range("plant.dc_link.brake_resistor_ohm", d.brake_resistor_ohm, 0.01, 1.0e4);
        }
        c.range("plant.dc_link.brake_on_pu", d.brake_on_pu, 1.0, 1.5);

        let m = &self.plant.motor;
        c.range("plant.motor.stator_resistance_ohm", m.stator_resistance_ohm, 0.0, 10.0);
        c.range("plant.motor.stator_inductance_h", m.stator_inductance_h, 0.0, 1.0);
        c.range("plant.motor.rotor_resistance_ohm", m.rotor_resistance_ohm, 1.0e-6, 10.0);
        c.range("plant.motor.rotor_inductance_h", m.rotor_inductance_h, 0.0, 1.0);
        c.range("plant.motor.magnetizing_inductance_h", m.magnetizing_inductance_h, 1.0e-5, 10.0);
        c.range_u("plant.motor.pole_pairs", m.pole_pairs as u64, 1, 64);
        c.range("plant.motor.rated_voltage_ll_v", m.rated_voltage_ll_v, 100.0, 1.0e5);
        c.range("plant.motor.rated_frequency_hz", m.rated_frequency_hz, 1.0, 1000.0);
        c.range("plant.motor.rated_power_w", m.rated_power_w, 1.0e3, 1.0e9);
        c.range("plant.motor.efficiency", m.efficiency, 0.5, 1.0);

        let k = &self.controllers;
        c.range("controllers.sample_period_s", k.sample_period_s, 1.0e-4, 1.0);
        c.range("controllers.governor.kp", k.governor.kp, 0.0, 1.0e3);
        c.range("controllers.governor.ki", k.governor.ki, 0.0, 1.0e3);
        c.range("controllers.governor.slew_rate_per_s", k.governor.slew_rate_per_s, 1.0e-3, 100.0);
        c.range("controllers.field.bus_voltage_ref_v", k.field.bus_voltage_ref_v, 10.0, 1.0e5);
        c.range("controllers.field.kp", k.field.kp, 0.0, 10.0);
        c.range("controllers.field.ki", k.field.ki, 0.0, 10.0);
        c.range("controllers.slip.kp", k.slip.kp, 0.0, 100.0);
        c.range("controllers.slip.ki", k.slip.ki, 0.0, 100.0);
        c.range("controllers.slip.zero_slip_offset_rad_s", k.slip.zero_slip_offset_rad_s, 0.0, 1.0);
        c.range("controllers.autopilot.kp", k.autopilot.kp, 0.0, 1.0e3);
        c.range("controllers.autopilot.ki", k.autopilot.ki, 0.0, 1.0e3);
        c.range("controllers.autopilot.kd", k.autopilot.kd, 0.0, 1.0e4);
        c.range("controllers.autopilot.ka", k.autopilot.ka, 0.0, 1.0e5);
        c.range("controllers.autopilot.max_turn_rate_nondim", k.autopilot.max_turn_rate_nondim, 0.01, 2.0);
        c.range("controllers.autopilot.turn_rate_deg_s", k.autopilot.turn_rate_deg_s, 0.01, 10.0);
        c.range("controllers.speed.kp_rpm_per_kn", k.speed.kp_rpm_per_kn, 0.0, 100.0);
        c.range("controllers.speed.ki_rpm_per_kn_s", k.speed.ki_rpm_per_kn_s, 0.0, 100.0);
        c.range("controllers.speed.trim_limit", k.speed.trim_limit, 0.0, 1.0);
        c.range("controllers.speed.shaft_ramp_rpm_per_s", k.speed.shaft_ramp_rpm_per_s, 0.0, 1.0e4);
        c.range("controllers.speed.max_shaft_rpm", k.speed.max_shaft_rpm, 1.0, 2000.0);

        if self.commands.len() > 10_000 {
            c.fail("commands", format!("{} commands", self.commands.len()), "at most 10000");
        }
        let mut last_t = f64::NEG_INFINITY;
        for (i, cmd) in self.commands.iter().enumerate().take(10_000) {
            let base = format!("commands.{i}");
            c.range(&format!("{base}.t_s"), cmd.t_s, 0.0, 1.0e7);
            if cmd.t_s < last_t {
                c.fail(&format!("{base}.t_s"), format!("{}", cmd.t_s), "commands must be in time order");
            }
            last_t = cmd.t_s;
            if let Some(kn) = cmd.speed_kn {
                c.range(&format!("{base}.speed_kn"), kn, 0.0, 40.0);
            }
            if let Some(hd) = cmd.heading_deg {
                c.range(&format!("{base}.heading_deg"), hd, -3600.0, 3600.0);
                if self.hull.model != HullModelKind::Maneuvering {
                    c.fail(
                        &format!("{base}.heading_deg"),
                        format!("{hd}"),
                        "heading commands need hull.model = \"maneuvering\" (the surge model only goes straight)",
                    );
                }
            }
            if let Some(rate) = cmd.heading_rate_deg_s {
                c.range(&format!("{base}.heading_rate_deg_s"), rate, 0.01, 10.0);
            }
        }
        if self.commands.first().and_then(|c| c.speed_kn).is_none() {
            c.fail(
                "commands.0.speed_kn",
                "missing".into(),
                "the first command must order a ship speed (0 to 40 knots)",
            );
        }

        c.range("initial.speed_kn", self.initial.speed_kn, 0.0, 35.0);

        let m = &self.monte_carlo;
        c.range_u("monte_carlo.trials", m.trials, 1, 10_000_000);
        if m.envelope_signals.len() > 20 {
            c.fail("monte_carlo.envelope_signals", format!("{} signals", m.envelope_signals.len()), "at most 20");
        }
        for (i, n) in m.envelope_signals.iter().enumerate().take(20) {
            if !crate::signals::Signal::from_name(n).is_some() {
                c.fail(
                    &format!("monte_carlo.envelope_signals.{i}"),
                    n.chars().take(40).collect(),
                    "is not a trace column",
                );
            }
        }
        if !crate::signals::Signal::from_name(&m.histogram_signal).is_some() {
            c.fail(
                "monte_carlo.histogram_signal",
                m.histogram_signal.chars().take(40).collect(),
                "is not a trace column",
            );
        }
        c.range("monte_carlo.histogram_time_s", m.histogram_time_s, 0.0, 1.0e6);
        c.range("monte_carlo.histogram_lo", m.histogram_lo, -1.0e9, 1.0e9);
        c.range("monte_carlo.histogram_hi", m.histogram_hi, m.histogram_lo, 1.0e9);
        c.range_u("monte_carlo.histogram_bins", m.histogram_bins as u64, 1, 1000);
        c.range("monte_carlo.onset_window_s", m.onset_window_s, 0.0, 600.0);
        c.range_u("monte_carlo.keep_traces", m.keep_traces as u64, 0, 10);
        c.range("monte_carlo.periodogram_segment_s", m.periodogram_segment_s, 1.0, 1.0e4);

        let sea = &self.sea;
        if sea.kind != SeaKind::Calm {
            c.range_u("sea.sea_state", sea.sea_state as u64, 2, 6);
            if sea.h_sig_m != 0.0 || sea.omega_n_rad_s != 0.0 {
                c.range("sea.h_sig_m", sea.h_sig_m, 0.01, 20.0);
                c.range("sea.omega_n_rad_s", sea.omega_n_rad_s, 0.2, 3.0);
            }
            c.range("sea.from_deg", sea.from_deg, -3600.0, 3600.0);
            c.range_u("sea.components", sea.components as u64, 1, 2000);
            if sea.omega_min_rad_s != 0.0 || sea.omega_max_rad_s != 0.0 {
                c.range("sea.omega_min_rad_s", sea.omega_min_rad_s, 0.05, 5.0);
                c.range("sea.omega_max_rad_s", sea.omega_max_rad_s, sea.omega_min_rad_s.max(0.05) + 0.01, 6.0);
            }
            c.range("sea.spreading", sea.spreading, 0.0, 100.0);
            if sea.kind == SeaKind::Regular {
                c.range("sea.amplitude_m", sea.amplitude_m, 0.0, 10.0);
                c.range("sea.omega_rad_s", sea.omega_rad_s, 0.1, 5.0);
            }
            if self.hull.model != HullModelKind::Maneuvering {
                c.fail("sea.kind", format!("{:?}", sea.kind).to_lowercase(), "waves need hull.model = \"maneuvering\"");
            }
            let k = &self.seakeeping;
            if let Err(e) = k.grid.validate() {
                let (path, rest) = e.split_once(" = ").unwrap_or(("seakeeping.grid", e.as_str()));
                let (value, msg) = rest.split_once(' ').unwrap_or((rest, ""));
                c.fail(path, value.to_string(), msg);
            }
            c.range("seakeeping.hub_depth_m", k.hub_depth_m, 0.0, 50.0);
            c.range("seakeeping.prop_x_aft_m", k.prop_x_aft_m, 0.0, 300.0);
            c.range("seakeeping.ventilation_on_h_over_r", k.ventilation_on_h_over_r, -1.0, 5.0);
            c.range("seakeeping.ventilation_off_h_over_r", k.ventilation_off_h_over_r, k.ventilation_on_h_over_r, 5.0);
            c.range("seakeeping.ventilation_loss", k.ventilation_loss, 0.0, 1.0);
            c.range("seakeeping.recovery_revolutions", k.recovery_revolutions, 0.01, 100.0);
            c.range("seakeeping.torque_exponent", k.torque_exponent, 0.1, 2.0);
            c.range("seakeeping.sample_period_s", k.sample_period_s, self.sim.dt_s, 0.5);
            c.range("seakeeping.rao_refresh_s", k.rao_refresh_s, k.sample_period_s, 10.0);
            c.range("seakeeping.turbine_rated_efficiency", k.turbine_rated_efficiency, 0.05, 0.8);
        }

        let sim = &self.sim;
        c.range("sim.duration_s", sim.duration_s, 0.0, 1.0e6);
        c.range("sim.dt_s", sim.dt_s, 1.0e-5, 0.01);
        c.range("sim.record_interval_s", sim.record_interval_s, 1.0e-4, 1.0e4);
        if sim.dt_s.is_finite() && sim.dt_s > 0.0 {
            if !whole_multiple(sim.record_interval_s, sim.dt_s) {
                c.fail(
                    "sim.record_interval_s",
                    format!("{}", sim.record_interval_s),
                    &format!("must be a whole number (1 or more) of sim.dt_s = {}", sim.dt_s),
                );
            }
            if !whole_multiple(k.sample_period_s, sim.dt_s) {
                c.fail(
                    "controllers.sample_period_s",
                    format!("{}", k.sample_period_s),
                    &format!("must be a whole number (1 or more) of sim.dt_s = {}", sim.dt_s),
                );
            }
            let steps = sim.duration_s / sim.dt_s;
            if steps > MAX_STEPS {
                c.fail(
                    "sim.duration_s",
                    format!("{}", sim.duration_s),
                    &format!("with sim.dt_s = {} this is {steps:.3e} steps; at most 1e9", sim.dt_s),
                );
            }
            let rows = sim.duration_s / sim.record_interval_s;
            if rows > MAX_RECORDED_ROWS {
                c.fail(
                    "sim.record_interval_s",
                    format!("{}", sim.record_interval_s),
                    &format!("would record {rows:.3e} rows; at most 2e6 (raise the interval)"),
                );
            }
        }

        if c.errors.is_empty() {
            Ok(())
        } else {
            Err(ScenarioError(c.errors))
        }
    }

    /// Parses a scenario from JSON, naming the field of any type error or unknown field, then
    /// validates every range.
    pub fn from_json(text: &str) -> Result<Scenario, ScenarioError> {
        let value: serde_json::Value = parse_bounded(text)?;
        Scenario::from_value(value)
    }

    /// Like [`Scenario::from_json`], from an already parsed JSON value.
    pub fn from_value(value: serde_json::Value) -> Result<Scenario, ScenarioError> {
        let sc: Scenario = serde_path_to_error::deserialize(value).map_err(|e| {
            let path = e.path().to_string();
            ScenarioError(vec![FieldError {
                path: if path == "." { "(top level)".into() } else { path },
                value: String::new(),
                message: e.into_inner().to_string(),
            }])
        })?;
        sc.validate()?;
        Ok(sc)
    }

    /// The scenario as pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// Sets one parameter by dotted path (`sim.duration_s`, `commands.0.speed_kn`) to a value
    /// given as text (JSON; bare words are taken as strings), then re-validates.
    pub fn with_override(&self, path: &str, value_text: &str) -> Result<Scenario, ScenarioError> {
        let mut root = serde_json::to_value(self).map_err(|e| one_error(path, value_text, &e))?;
        let new_value: serde_json::Value =
            serde_json::from_str(value_text).unwrap_or_else(|_| serde_json::Value::String(value_text.to_string()));
        let mut node = &mut root;
        let parts: Vec<&str> = path.split('.').collect();
        for (i, part) in parts.iter().enumerate() {
            let last = i + 1 == parts.len();
            let here = parts[..=i].join(".");
            node = match node {
                serde_json::Value::Object(map) => {
                    if !map.contains_key(*part) {
                        if last {
                            // Optional fields (e.g. commands.N.heading_deg) are absent when unset.
                            map.insert(part.to_string(), serde_json::Value::Null);
                        } else {
                            return Err(unknown_path(&here, value_text));
                        }
                    }
                    map.get_mut(*part).ok_or_else(|| unknown_path(&here, value_text))?
                }
                serde_json::Value::Array(items) => {
                    let idx: usize = part.parse().map_err(|_| unknown_path(&here, value_text))?;
                    let len = items.len();
                    items.get_mut(idx).ok_or_else(|| {
                        one_error(&here, value_text, &format!("index out of range (0 to {})", len.saturating_sub(1)))
                    })?
                }
                _ => return Err(unknown_path(&here, value_text)),
            };
        }
        *node = new_value;
        Scenario::from_value(root)
    }
}

fn one_error(path: &str, value: &str, msg: &dyn fmt::Display) -> ScenarioError {
    ScenarioError(vec![FieldError { path: path.into(), value: value.into(), message: msg.to_string() }])
}

fn unknown_path(path: &str, value: &str) -> ScenarioError {
    one_error(path, value, &"no such parameter (see `aes-sim preset startup` for the names)")
}

/// Largest scenario text accepted [bytes].
pub const MAX_SCENARIO_BYTES: usize = 4 << 20;
/// Deepest nesting accepted in a scenario file.
pub const MAX_SCENARIO_DEPTH: usize = 32;

/// Parses JSON after bounding its size and nesting, so hostile input cannot exhaust memory or stack.
pub fn parse_bounded(text: &str) -> Result<serde_json::Value, ScenarioError> {
    if text.len() > MAX_SCENARIO_BYTES {
        return Err(one_error(
            "(file)",
            &format!("{} bytes", text.len()),
            &format!("a scenario may be at most {MAX_SCENARIO_BYTES} bytes"),
        ));
    }
    let mut depth = 0usize;
    let mut in_str = false;
    let mut escaped = false;
    for b in text.bytes() {
        if in_str {
            match (escaped, b) {
                (true, _) => escaped = false,
                (false, b'\\') => escaped = true,
                (false, b'"') => in_str = false,
                _ => {}
            }
            continue;
        }
        match b {
            b'"' => in_str = true,
            b'{' | b'[' => {
                depth += 1;
                if depth > MAX_SCENARIO_DEPTH {
                    return Err(one_error(
                        "(file)",
                        &format!("nesting deeper than {MAX_SCENARIO_DEPTH}"),
                        &"a scenario is at most a few levels deep",
                    ));
                }
            }
            b'}' | b']' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    serde_json::from_str(text).map_err(|e| one_error("(file)", "", &format!("not valid JSON: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_round_trip() {
        let s = Scenario::default();
        s.validate().unwrap();
        let back = Scenario::from_json(&s.to_json()).unwrap();
        assert_eq!(back, s);
    }

    #[test]
    fn unknown_field_is_named() {
        let e = Scenario::from_json(r#"{"ship": {"mass_kgg": 1}}"#).unwrap_err();
        let text = e.to_string();
        assert!(text.contains("mass_kgg"), "{text}");
    }

    #[test]
    fn wrong_type_is_named_with_path() {
        let e = Scenario::from_json(r#"{"plant": {"motor": {"pole_pairs": "twelve"}}}"#).unwrap_err();
        assert_eq!(e.0[0].path, "plant.motor.pole_pairs");
    }

    #[test]
    fn out_of_range_names_field_value_and_range() {
        let mut s = Scenario::default();
        s.ship.mass_kg = -5.0;
        s.sim.dt_s = f64::NAN;
        let e = s.validate().unwrap_err();
        let paths: Vec<_> = e.0.iter().map(|f| f.path.as_str()).collect();
        assert!(paths.contains(&"ship.mass_kg"));
        assert!(paths.contains(&"sim.dt_s"));
        let m = e.0.iter().find(|f| f.path == "ship.mass_kg").unwrap();
        assert_eq!(m.value, "-5");
        assert!(m.message.contains("10000") && m.message.contains("1000000000"), "{}", m.message);
    }

    #[test]
    fn override_by_path() {
        let s = Scenario::default();
        let t = s.with_override("commands.0.speed_kn", "20").unwrap();
        assert_eq!(t.commands[0].speed_kn, Some(20.0));
        let t = s.with_override("sim.duration_s", "12.5").unwrap();
        assert_eq!(t.sim.duration_s, 12.5);
        assert!(s.with_override("sim.nope", "1").unwrap_err().0[0].path == "sim.nope");
        assert!(s.with_override("commands.7.speed_kn", "1").is_err());
        assert!(s.with_override("ship.mass_kg", "abc").is_err());
    }

    #[test]
    fn hostile_input_is_bounded() {
        let deep = "[".repeat(10_000);
        assert!(Scenario::from_json(&deep).is_err());
        assert!(Scenario::from_json("{\"name\": 1e999}").is_err());
        assert!(Scenario::from_json("").is_err());
    }

    #[test]
    fn record_interval_must_be_whole_steps() {
        let mut s = Scenario::default();
        s.sim.record_interval_s = 0.0015;
        assert!(s.validate().is_err());
    }
}
