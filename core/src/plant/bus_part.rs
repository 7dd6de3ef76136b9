//! One shape for a part on each DC bus (a load, a storage, a filter): what it declares once and
//! what the coupled plant then does for it.
//!
//! A part implements [`BusPart`]: its parameters (a `params!` section, which gives the scenario
//! format, the checks and the page's form), its states on each bus with their names, its energy
//! accounts with how the books count them, its start from the steady state, its derivatives and
//! flows, and the energy it stores. It is registered by one line in `plant_section!`
//! (`plant/mod.rs`), which adds its section to `plant` and its slot to `BusParts`. The state
//! layout, the number of energy accounts, the run's active states and the stability map's states
//! are then computed from the list (`plant::layout`), never counted by hand.
//!
//! Order matters where parts meet at the bus node: a part sees the load of the parts before it
//! ([`BusNode::p_load`]), so storage, which levels the bus's load, comes last.

use crate::signals::Signal;

/// Buses: one a shaft (the hull's count).
pub const SHAFTS: usize = crate::geometry::N_SHAFTS;

/// What the loads' profiles of one bus demand at one instant \[W\] (`plant::bus_loads`), held over
/// a step.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Demand {
    /// Ship service converter's output power.
    pub ship_service_w: f64,
    /// Pulsed load's power.
    pub pulse_w: f64,
}

/// How the energy books count an account.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Book {
    /// Energy a load took from the bus and used (ship service, pulses, a load bank).
    Load,
    /// Energy lost as heat in the part (filter resistance, converter and cells).
    Loss,
    /// Energy a store gave the bus (negative: took); its stored energy closes the books.
    ToBus,
}

/// One energy account of a part.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Account {
    /// Its name, lower case with underscores (tests and reports look it up by name).
    pub name: &'static str,
    pub book: Book,
}

/// The bus node of one shaft at one instant, as the parts see it in their order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BusNode {
    /// Bus voltage \[V\].
    pub v: f64,
    /// What the loads' profiles demand now (held over the step).
    pub demand: Demand,
    /// Net current the parts so far draw from the bus \[A\] (negative: give).
    pub i_draw: f64,
    /// Power taken from the bus by the motor's inverter and the parts so far \[W\]: what a storage
    /// registered after them levels.
    pub p_load: f64,
}

/// A recorded signal's column of a finished run, by signal.
pub type Column<'a> = &'a dyn Fn(Signal) -> &'a [f64];

/// One health check as the docs list it (`sim::health`).
#[derive(Debug, Clone, PartialEq)]
pub struct CheckInfo {
    pub name: &'static str,
    pub threshold: String,
    pub reason: &'static str,
}

/// A part on each DC bus. See the module's text.
pub trait BusPart: Sized {
    /// Its section of `plant` in the scenario.
    type Params;
    /// Its states on each bus, named (in the state vector's order).
    const STATES: &'static [&'static str];
    /// Its energy accounts (summed over the buses).
    const ACCOUNTS: &'static [Account];

    /// The part of `p` on a bus held at `v_ref` \[V\]; None when the scenario has none of it.
    fn build(p: &Self::Params, v_ref: f64) -> Option<Self>;
    /// Whether the scenario has it (its states and accounts count in a run's work).
    fn present(p: &Self::Params) -> bool;
    /// Whether it draws power from a bus at rest (the bus then sits at its set point, not at the
    /// rectifiers' open-circuit voltage).
    const DRAWS: bool = false;
    /// Whether its states take part in the bus's small-signal dynamics (the stability map).
    fn linearized(p: &Self::Params) -> bool {
        Self::present(p)
    }
    /// Power it takes from a bus held at `v_bus` \[V\] in the steady state at t = 0 \[W\], or why
    /// there is none.
    fn steady_input_w(&self, _v_bus: f64) -> Result<f64, String> {
        Ok(0.0)
    }
    /// Its states `x` of one bus at the steady state: the bus at `v_bus` \[V\] carrying `p_load` \[W\]
    /// (the motor's and every part's steady input).
    fn start(&self, v_bus: f64, p_load: f64, x: &mut [f64]);
    /// Its derivatives `dx` at its states `x` of one bus: adds its current and power to the
    /// node, its energies to `e` (its accounts, in order) and writes what it shows to `flow`.
    fn derivatives(&self, x: &[f64], node: &mut BusNode, dx: &mut [f64], e: &mut [f64], flow: &mut BusFlow);
    /// Adds the energy it stores in the states `x` of one bus to `e` \[J\].
    fn add_stored_energy(&self, _x: &[f64], _e: &mut f64) {}
    /// Its health checks, each with its threshold and reason (`aes-sim health`).
    fn checks() -> Vec<CheckInfo> {
        Vec::new()
    }
    /// Its health checks on a finished run of a scenario with section `p`: `t` the recorded
    /// times \[s\], `column` a recorded signal; each check that fails adds its sentence to `out`.
    fn assess(_p: &Self::Params, _t: &[f64], _column: Column<'_>, _out: &mut Vec<String>) {}
}

/// What the parts of one bus do at one instant (the trace's signals read it).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct BusFlow {
    /// Ship service converter's output \[W\] and the power its filter takes from the bus \[W\].
    pub ship_service_w: f64,
    pub ship_service_in_w: f64,
    /// Ship service filter capacitor voltage \[V\] (0 without one).
    pub filter_voltage_v: f64,
    /// Pulsed load \[W\].
    pub pulse_w: f64,
    /// Storage power to the bus \[W\] (negative: charging), its state of charge \[-\] (0 without).
    pub storage_w: f64,
    pub soc: f64,
}

/// Declares the plant's section of the scenario and its bus parts, in order. Each bus part is
/// one line `name: Type,` with its doc comment: the part's parameters become `plant.name`, and
/// [`BusParts`](crate::plant::BusParts) holds it. (The macro keeps the section's fixed subsystems around the parts in the
/// order the format has always had.)
#[macro_export]
macro_rules! plant_section {
    (
        fixed { $($(#[$fa:meta])* $f:ident : $fty:ty),* $(,)? }
        bus_parts { $($(#[$pa:meta])* $p:ident : $pty:ty),* $(,)? }
        last { $($(#[$la:meta])* $l:ident : $lty:ty),* $(,)? }
    ) => {
        $crate::params! {
            /// The split plant: per shaft two gas turbine-generator sets, one DC bus and one motor,
            /// and the bus's other parts.
            #[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
            #[serde(deny_unknown_fields, default)]
            pub struct PlantParams {
                $($(#[$fa])* pub $f: $fty = <$fty>::default() => {},)*
                $($(#[$pa])* pub $p: <$pty as $crate::plant::bus_part::BusPart>::Params
                    = Default::default() => {},)*
                $($(#[$la])* pub $l: $lty = <$lty>::default() => {},)*
            }
        }

        /// Number of registered bus parts.
        pub const N_BUS_PARTS: usize = [$(stringify!($p)),*].len();

        /// The bus parts of a plant, one of each registered kind on every bus (None: absent).
        #[derive(Debug, Clone, PartialEq)]
        pub struct BusParts {
            $(pub $p: Option<$pty>,)*
        }

        impl BusParts {
            /// The parts' names, in order.
            pub const NAMES: &'static [&'static str] = &[$(stringify!($p)),*];
            /// Each part's states on one bus, in order.
            pub const STATES: &'static [&'static [&'static str]] =
                &[$(<$pty as $crate::plant::bus_part::BusPart>::STATES),*];
            /// Each part's energy accounts, in order.
            pub const ACCOUNTS: &'static [&'static [$crate::plant::bus_part::Account]] =
                &[$(<$pty as $crate::plant::bus_part::BusPart>::ACCOUNTS),*];

            /// The parts of `p` on buses held at `v_ref` \[V\].
            pub fn new(p: &PlantParams, v_ref: f64) -> BusParts {
                BusParts { $($p: $crate::plant::bus_part::BusPart::build(&p.$p, v_ref),)* }
            }

            /// Whether any part is there.
            pub fn any(&self) -> bool {
                false $(|| self.$p.is_some())*
            }

            /// Whether a part that draws power from a bus at rest is there.
            pub fn draws(&self) -> bool {
                false $(|| (<$pty as $crate::plant::bus_part::BusPart>::DRAWS && self.$p.is_some()))*
            }

            /// Which parts the scenario has, in order.
            pub fn present(p: &PlantParams) -> [bool; N_BUS_PARTS] {
                [$(<$pty as $crate::plant::bus_part::BusPart>::present(&p.$p)),*]
            }

            /// Which parts' states take part in the small-signal dynamics, in order.
            pub fn linearized(p: &PlantParams) -> [bool; N_BUS_PARTS] {
                [$(<$pty as $crate::plant::bus_part::BusPart>::linearized(&p.$p)),*]
            }

            /// States of one bus, all parts.
            pub const STATES_PER_BUS: usize = 0 $(+ <$pty as $crate::plant::bus_part::BusPart>::STATES.len())*;
            /// Energy accounts, all parts.
            pub const N_ACCOUNTS: usize = 0 $(+ <$pty as $crate::plant::bus_part::BusPart>::ACCOUNTS.len())*;

            /// The power the bus carries in the steady state at t = 0: `p` \[W\] (the motor's) and
            /// each part's input in order, with the bus at `v_bus` \[V\].
            pub fn steady_load_w(&self, v_bus: f64, p: f64) -> Result<f64, String> {
                let mut p = p;
                $(if let Some(x) = &self.$p {
                    p += $crate::plant::bus_part::BusPart::steady_input_w(x, v_bus)?;
                })*
                Ok(p)
            }

            /// Every part's states on every bus at the steady state (`x`: the parts' block of the
            /// state vector; an absent part's states are 0).
            pub fn start(&self, v_bus: f64, p_load: f64, x: &mut [f64]) {
                let mut _at = 0;
                $(
                    let n = <$pty as $crate::plant::bus_part::BusPart>::STATES.len();
                    for s in 0..$crate::plant::bus_part::SHAFTS {
                        let xs = &mut x[_at + s * n.._at + (s + 1) * n];
                        match &self.$p {
                            Some(part) => $crate::plant::bus_part::BusPart::start(part, v_bus, p_load, xs),
                            None => xs.fill(0.0),
                        }
                    }
                    _at += $crate::plant::bus_part::SHAFTS * n;
                )*
            }

            /// The parts of bus `s` in order at the node: their derivatives in `dx` (the parts'
            /// block; 0 for an absent part), their energies added to `e` (the parts' accounts).
            #[inline(always)]
            pub fn derivatives(
                &self,
                s: usize,
                x: &[f64],
                node: &mut $crate::plant::bus_part::BusNode,
                dx: &mut [f64],
                e: &mut [f64],
                flow: &mut $crate::plant::bus_part::BusFlow,
            ) {
                let (mut _at, mut _acc) = (0, 0);
                $(
                    let n = <$pty as $crate::plant::bus_part::BusPart>::STATES.len();
                    let k = <$pty as $crate::plant::bus_part::BusPart>::ACCOUNTS.len();
                    let r = _at + s * n.._at + (s + 1) * n;
                    match &self.$p {
                        Some(part) => $crate::plant::bus_part::BusPart::derivatives(
                            part, &x[r.clone()], node, &mut dx[r], &mut e[_acc.._acc + k], flow,
                        ),
                        None => dx[r].fill(0.0),
                    }
                    _at += $crate::plant::bus_part::SHAFTS * n;
                    _acc += k;
                )*
            }

            /// Every part's health checks, in their order.
            pub fn checks() -> Vec<$crate::plant::bus_part::CheckInfo> {
                let mut _out = Vec::new();
                $(_out.extend(<$pty as $crate::plant::bus_part::BusPart>::checks());)*
                _out
            }

            /// Every part's health checks on a finished run, in their order
            /// ([`BusPart::assess`](crate::plant::bus_part::BusPart::assess)).
            pub fn assess(
                p: &PlantParams,
                t: &[f64],
                column: $crate::plant::bus_part::Column<'_>,
                out: &mut Vec<String>,
            ) {
                $(<$pty as $crate::plant::bus_part::BusPart>::assess(&p.$p, t, column, out);)*
            }

            /// Adds the energy every part stores on every bus to `e` \[J\], part by part.
            pub fn add_stored_energy(&self, x: &[f64], e: &mut f64) {
                let mut _at = 0;
                $(
                    let n = <$pty as $crate::plant::bus_part::BusPart>::STATES.len();
                    if let Some(part) = &self.$p {
                        for s in 0..$crate::plant::bus_part::SHAFTS {
                            $crate::plant::bus_part::BusPart::add_stored_energy(part, &x[_at + s * n.._at + (s + 1) * n], e);
                        }
                    }
                    _at += $crate::plant::bus_part::SHAFTS * n;
                )*
            }
        }
    };
}
