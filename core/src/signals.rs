//! The recorded signals, declared once.
//!
//! [`for_each_signal!`](crate::for_each_signal!) is the one table: for every trace column its enum variant, name, unit,
//! short label, description and the expression that computes it from the simulator's recording
//! context. This leaf module expands the table into [`Signal`] and [`SIGNALS`] (metadata only: the
//! expressions are discarded here, so this module depends on nothing); `sim::record` expands the
//! same table into the row it records. The trace header, the row, the summary keys and the page's
//! axis labels and units therefore all come from here, and no two lists are matched by position.
//!
//! Conventions: `_pu` signals are per unit of: turbine speed, the governor set point (3600 rpm);
//! bus voltage, the field controller's set point (5618 V); motor voltage, rated phase voltage;
//! motor power, rated power (38 MW). Per-shaft signals average the two shafts; `_1`, `_2` are the
//! shafts. In waves: heave up, pitch bow down (STF), roll starboard down, sway to starboard and yaw
//! bow to starboard (first-order motions about the maneuvering track, not fed back into it).
//!
//! To add a signal: add one line to the table (the compiler then asks for nothing else).

use serde::Serialize;

/// The table of signals: `callback!` receives, for every signal,
/// `Variant, "name", "unit", "label", "description", |r| expression;` in trace column order.
#[macro_export]
macro_rules! for_each_signal {
    ($callback:ident) => {
        $callback! {
            TS, "t_s", "s", "time", "Simulated time.", |r| r.t;
            ShipSpeedKn, "ship_speed_kn", "kn", "ship speed (unsigned)",
                "Speed through the water, sqrt(u^2 + v^2): positive ahead and astern.", |r| r.ship_speed_kn();
            SpeedCmdKn, "speed_cmd_kn", "kn", "ordered speed (negative: astern)", "Ship speed in force from the orders (negative: astern).",
                |r| r.speed_cmd_kn();
            PropRpm, "prop_rpm", "rpm", "propeller speed", "Propeller shaft speed, mean of the two shafts.",
                |r| r.mean_shaft(|s| r.shaft_rpm(s));
            PropRpm1, "prop_rpm_1", "rpm", "propeller speed, shaft 1", "Shaft 1 speed.", |r| r.shaft_rpm(0);
            PropRpm2, "prop_rpm_2", "rpm", "propeller speed, shaft 2", "Shaft 2 speed.", |r| r.shaft_rpm(1);
            PropRpmRef, "prop_rpm_ref", "rpm", "shaft speed reference",
                "Ramp-limited shaft speed reference of the speed controller.", |r| r.shaft_ref_rpm();
            TurbineSpeedPu, "turbine_speed_pu", "pu", "turbine speed",
                "Gas turbine speed per unit of the governor set point, mean of the four sets.",
                |r| r.mean_set(|k| r.turbine_speed_pu(k));
            Throttle, "throttle", "-", "throttle", "Governor throttle, 0 to 1, mean of the four sets.",
                |r| r.mean_set(|k| r.throttle(k));
            FieldCurrentA, "field_current_a", "A", "field current", "Generator field current, mean of the four sets.",
                |r| r.mean_set(|k| r.field_current(k));
            FieldVoltageV, "field_voltage_v", "V", "field voltage",
                "Field voltage the bus-voltage controller applies, mean of the four sets (ch. 2.2.1).",
                |r| r.mean_set(|k| r.ctl.held.field_voltage[k]);
            BusVoltagePu, "bus_voltage_pu", "pu", "bus voltage",
                "DC bus voltage per unit of the field controller's set point, mean of the two buses.",
                |r| r.mean_shaft(|s| r.bus_voltage_pu(s));
            BusVoltageV, "bus_voltage_v", "V", "bus voltage", "DC bus voltage, mean of the two buses.",
                |r| r.mean_shaft(|s| r.bus_voltage(s));
            MotorVoltagePu, "motor_voltage_pu", "pu", "motor voltage",
                "Motor phase voltage per unit of its rated value.", |r| r.mean_shaft(|s| r.motor_voltage_pu(s));
            SlipSpeedRadS, "slip_speed_rad_s", "rad/s", "slip speed", "Commanded slip speed of the volts-per-hertz control.",
                |r| r.mean_shaft(|s| r.slip(s));
            ImPowerPu, "im_power_pu", "pu", "motor power, each motor", "Motor shaft power per unit of its rating, mean of the two motors.",
                |r| r.motor_power_pu();
            ImTorqueKnm, "im_torque_knm", "kN m", "motor torque", "Motor torque, mean of the two motors.",
                |r| r.mean_shaft(|s| r.motor_torque(s)) / 1e3;
            ThrustKn, "thrust_kn", "kN", "thrust", "Total propeller thrust.", |r| r.thrust() / 1e3;
            AdvanceRatio, "advance_ratio", "-", "advance ratio J", "Propeller advance ratio, mean of the two.",
                |r| r.mean_shaft(|s| r.advance_ratio(s));
            PropEfficiency, "prop_efficiency", "-", "open-water efficiency", "Open-water efficiency at the advance ratio.",
                |r| r.mean_shaft(|s| r.open_water_efficiency(s));
            BetaT, "beta_t", "-", "beta_T", "Thrust kept under surface losses (eq. 2.13), 1 when fully submerged.",
                |r| r.beta_t();
            BetaQ, "beta_q", "-", "beta_Q", "Torque kept under surface losses (eq. 2.13).", |r| r.beta_q();
            XM, "x_m", "m", "north", "Position north of the start.", |r| r.x_m();
            YM, "y_m", "m", "east", "Position east of the start.", |r| r.y_m();
            HeadingDeg, "heading_deg", "deg", "heading", "Heading, clockwise from north, not wrapped.",
                |r| r.heading_deg();
            HeadingRefDeg, "heading_ref_deg", "deg", "heading order", "Heading reference of the autopilot.",
                |r| r.heading_ref_deg();
            RudderDeg, "rudder_deg", "deg", "rudder", "Rudder angle.", |r| r.rudder_deg();
            DriftAngleDeg, "drift_angle_deg", "deg", "drift angle", "Drift angle atan(v / |u|).", |r| r.drift_angle_deg();
            YawRateDegS, "yaw_rate_deg_s", "deg/s", "yaw rate", "Rate of turn.", |r| r.yaw_rate_deg_s();
            BrakePowerW, "brake_power_w", "W", "brake resistor power", "Power burnt in the brake resistors.",
                |r| r.brake_power();
            PTurbineW, "p_turbine_w", "W", "turbine power, the turbines online", "Shaft power of the gas turbines online (all four by default; Table 5.6).",
                |r| r.p_turbine;
            PGeneratorW, "p_generator_w", "W", "generator power, the generators online", "Electrical output of the generators online (all four by default; Table 5.6).",
                |r| r.p_generator();
            PInverterW, "p_inverter_w", "W", "inverter power, both", "Power into the two motors (Table 5.6).",
                |r| r.p_inverter();
            PMotorW, "p_motor_w", "W", "motor power, both motors", "Shaft power of the two motors (Table 5.6).", |r| r.p_motor;
            PShipW, "p_ship_w", "W", "ship power", "Resistance times speed, the useful power (Table 5.6).",
                |r| r.p_ship();
            WaveSternM, "wave_stern_m", "m", "wave at the stern", "Wave elevation at the port propeller (eq. 2.56).",
                |r| r.sea.wave_stern;
            HubDepthM, "hub_depth_m", "m", "hub depth", "Depth of the port propeller's hub below the local surface (eq. 2.57).",
                |r| r.sea.hub[0];
            HOverR, "h_over_r", "-", "h/R", "Hub depth over propeller radius, port shaft (ch. 2.3).", |r| r.h_over_r[0];
            HubDepthStbdM, "hub_depth_stbd_m", "m", "hub depth, starboard",
                "Depth of the starboard propeller's hub below the local surface (eq. 2.57 off the centreline).",
                |r| r.sea.hub[1];
            HOverRStbd, "h_over_r_stbd", "-", "h/R starboard", "Hub depth over propeller radius, starboard shaft (ch. 2.3).",
                |r| r.h_over_r[1];
            HeaveM, "heave_m", "m", "heave", "Heave, up.", |r| r.sea.heave;
            PitchDeg, "pitch_deg", "deg", "pitch", "Pitch, bow down.", |r| r.rad_to_deg(r.sea.pitch);
            RollDeg, "roll_deg", "deg", "roll", "Roll, starboard down.", |r| r.rad_to_deg(r.sea.roll);
            SwayM, "sway_m", "m", "sway", "First-order sway at the waterline, to starboard.", |r| r.sea.sway;
            YawDeg, "yaw_deg", "deg", "yaw", "First-order yaw, bow to starboard.", |r| r.rad_to_deg(r.sea.yaw);
            AddedResistanceN, "added_resistance_n", "N", "added resistance",
                "Slowly varying second-order force backwards (eq. 2.60).", |r| r.added_resistance();
            DriftForceN, "drift_force_n", "N", "drift force",
                "Slowly varying second-order force to starboard (eq. 2.60).", |r| r.drift_force();
            DriftMomentNm, "drift_moment_nm", "N m", "drift moment",
                "Slowly varying second-order yaw moment, bow to starboard (M_add of eq. 2.24).", |r| r.ctl.held.sea.wave_mz;
            FuelPowerW, "fuel_power_w", "W", "fuel power", "Fuel power of the turbines online (part-load curve; all four by default).",
                |r| r.fuel;
            ShipServiceW, "ship_service_w", "W", "ship service load, both buses",
                "Output of the two ship service converters (constant power behind their input filters; 0 without).",
                |r| r.out.bus.iter().map(|b| b.ship_service_w).sum::<f64>();
            FilterVoltagePu, "filter_voltage_pu", "pu", "ship service filter voltage",
                "Voltage of the ship service converters' input filter capacitors per unit of the bus set point, mean of the two (0 without).",
                |r| r.mean_shaft(|s| r.out.bus[s].filter_voltage_v) / r.v_ref;
            FilterRipplePu, "filter_ripple_pu", "pu", "ship service filter ringing",
                "The ship service filters' inductor voltage, the magnitude of v_bus - R_f i_L - v_f, per unit of the bus set point, the larger of the two: near 0 while the filter follows the bus, large when it rings (0 without).",
                |r| r.filter_ripple_pu();
            PulsedLoadW, "pulsed_load_w", "W", "pulsed load, both buses", "Power of the two pulsed loads (0 without).",
                |r| r.out.bus.iter().map(|b| b.pulse_w).sum::<f64>();
            StoragePowerW, "storage_power_w", "W", "storage power, both buses",
                "Power the two storages give the buses (negative: charging; 0 without).",
                |r| r.out.bus.iter().map(|b| b.storage_w).sum::<f64>();
            StorageSoc, "storage_soc", "-", "state of charge", "State of charge of the storages, mean of the two (0 without).",
                |r| r.mean_shaft(|s| r.out.bus[s].soc);
        }
    };
}

/// Metadata of one recorded signal.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct SignalInfo {
    /// Column name (units in the name where it has one).
    pub name: &'static str,
    /// Unit as printed on an axis ("-" for dimensionless, "pu" for per unit).
    pub unit: &'static str,
    /// Short human label.
    pub label: &'static str,
    /// One sentence: what it is and how it is computed.
    pub description: &'static str,
}

macro_rules! declare_signals {
    ($($variant:ident, $name:literal, $unit:literal, $label:literal, $desc:literal, |$r:ident| $e:expr;)*) => {
        /// A recorded signal; its discriminant is its trace column.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum Signal {
            $($variant,)*
        }

        /// Every signal's metadata, in trace column order.
        pub const SIGNALS: &[SignalInfo] = &[
            $(SignalInfo { name: $name, unit: $unit, label: $label, description: $desc },)*
        ];

        impl Signal {
            /// Every signal, in trace column order.
            pub const ALL: &'static [Signal] = &[$(Signal::$variant,)*];
        }
    };
}

for_each_signal!(declare_signals);

/// Number of recorded signals.
pub const N_SIGNALS: usize = SIGNALS.len();

impl Signal {
    /// Trace column index.
    pub fn index(self) -> usize {
        self as usize
    }

    /// The signal's metadata.
    pub fn info(self) -> &'static SignalInfo {
        &SIGNALS[self.index()]
    }

    /// Column name.
    pub fn name(self) -> &'static str {
        self.info().name
    }

    /// The signal of that column name.
    pub fn from_name(name: &str) -> Option<Signal> {
        SIGNALS.iter().position(|s| s.name == name).map(|i| Signal::ALL[i])
    }
}

/// Column names, in trace column order.
pub fn names() -> impl Iterator<Item = &'static str> {
    SIGNALS.iter().map(|s| s.name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_round_trip() {
        for (i, s) in Signal::ALL.iter().enumerate() {
            assert_eq!(s.index(), i);
            assert_eq!(Signal::from_name(s.name()), Some(*s));
            assert!(!s.info().unit.is_empty() && !s.info().label.is_empty(), "{}", s.name());
        }
        let mut names: Vec<_> = names().collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), N_SIGNALS);
        assert_eq!(Signal::from_name("nope"), None);
    }
}
