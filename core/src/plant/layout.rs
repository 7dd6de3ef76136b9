//! The coupled plant's state vector: its blocks in order, every slot named, and the energy
//! accumulators that ride along (so that the energy books are integrated with exactly the same
//! scheme as the states they describe). The bus parts' block and accounts are computed from their
//! registration (`plant::bus_part`); nothing here is counted by hand.

use crate::plant::bus_part::Account;
use crate::plant::BusParts;

/// Shafts (independent plants): the hull's count, owned by `ship_hull`.
pub use crate::geometry::N_SHAFTS;
/// Turbine-generator sets per shaft.
pub const SETS_PER_SHAFT: usize = 2;
/// Turbine-generator sets in all.
pub const N_SETS: usize = N_SHAFTS * SETS_PER_SHAFT;
// The online sets' rules count the same sets.
const _: () = assert!(N_SETS == crate::plant::online::SETS);

/// The blocks of the state vector. Their order and lengths are [`LAYOUT`]'s: a subsystem's states
/// are one line there, and every slot follows from it (no offset is computed by hand).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Block {
    /// Turbine shaft speed of each set \[rad/s\].
    TurbineSpeed,
    /// Field current of each set \[A\].
    FieldCurrent,
    /// Bus voltage of each shaft \[V\].
    BusVoltage,
    /// Propeller shaft speed of each shaft \[rad/s\].
    ShaftSpeed,
    /// The bus parts' states ([`BusParts`]): part by part in their order, each part's block bus by
    /// bus ([`part_slot`]).
    BusParts,
    /// The hull: surge u, sway v \[m/s\], yaw rate r \[rad/s\], north x, east y \[m\], heading psi \[rad\]
    /// ([`SURGE`] to [`HEADING`]).
    Hull,
    /// The energy accumulators \[J\] ([`Energy`]).
    Energy,
}

/// Energy accumulators of the drive train and hull ([`Energy`]).
pub const DRIVE_ACCOUNTS: usize = Energy::Regenerated as usize + 1;
/// Number of energy accumulators: the drive train's and hull's, then the bus parts' in their order.
pub const N_ENERGY: usize = DRIVE_ACCOUNTS + BusParts::N_ACCOUNTS;

/// The state vector's blocks in order, with their lengths. The bus's parts come before the hull,
/// with the drive train (the multi-rate step holds everything before [`SURGE`] during the hull's
/// step).
pub const LAYOUT: [(Block, usize); 7] = [
    (Block::TurbineSpeed, N_SETS),
    (Block::FieldCurrent, N_SETS),
    (Block::BusVoltage, N_SHAFTS),
    (Block::ShaftSpeed, N_SHAFTS),
    (Block::BusParts, N_SHAFTS * BusParts::STATES_PER_BUS),
    (Block::Hull, 6),
    (Block::Energy, N_ENERGY),
];

/// The slots of a block.
pub const fn slots(b: Block) -> std::ops::Range<usize> {
    let (mut at, mut i) = (0, 0);
    while i < LAYOUT.len() {
        if LAYOUT[i].0 as usize == b as usize {
            return at..at + LAYOUT[i].1;
        }
        at += LAYOUT[i].1;
        i += 1;
    }
    at..at
}

/// Size of the state vector.
pub const NX: usize = {
    let (mut n, mut i) = (0, 0);
    while i < LAYOUT.len() {
        n += LAYOUT[i].1;
        i += 1;
    }
    n
};

/// The slots of the drive train's states, by machine: `x\[slot::bus_voltage(s)\]` is a voltage,
/// `slot::bus_voltage(s)` an index.
pub mod slot {
    use super::{slots, Block};

    /// Turbine shaft speed of set k \[rad/s\].
    pub const fn turbine_speed(k: usize) -> usize {
        slots(Block::TurbineSpeed).start + k
    }
    /// Field current of set k \[A\].
    pub const fn field_current(k: usize) -> usize {
        slots(Block::FieldCurrent).start + k
    }
    /// Bus voltage of shaft s \[V\].
    pub const fn bus_voltage(s: usize) -> usize {
        slots(Block::BusVoltage).start + s
    }
    /// Propeller shaft speed of shaft s \[rad/s\].
    pub const fn shaft_speed(s: usize) -> usize {
        slots(Block::ShaftSpeed).start + s
    }
}

/// The slot of state `name` of a bus part on bus `s` (`name` one of [`BusParts::STATES`]: say
/// "filter_current" or "storage_energy"); None for another name.
pub const fn part_slot(name: &str, s: usize) -> Option<usize> {
    let mut at = slots(Block::BusParts).start;
    let mut p = 0;
    while p < BusParts::STATES.len() {
        let states = BusParts::STATES[p];
        let mut k = 0;
        while k < states.len() {
            if str_eq(states[k], name) {
                return Some(at + s * states.len() + k);
            }
            k += 1;
        }
        at += N_SHAFTS * states.len();
        p += 1;
    }
    None
}

/// The energy accumulator of a bus part's account `name` (one of [`BusParts::ACCOUNTS`]: say
/// "storage_to_bus"), an offset from [`ENERGY0`] as [`Energy`]'s; None for another name.
pub const fn part_account(name: &str) -> Option<usize> {
    let mut at = DRIVE_ACCOUNTS;
    let mut p = 0;
    while p < BusParts::ACCOUNTS.len() {
        let accounts = BusParts::ACCOUNTS[p];
        let mut k = 0;
        while k < accounts.len() {
            if str_eq(accounts[k].name, name) {
                return Some(at + k);
            }
            k += 1;
        }
        at += accounts.len();
        p += 1;
    }
    None
}

/// Every bus part's accounts in the order of the accumulators, from [`DRIVE_ACCOUNTS`] on.
pub fn part_accounts() -> impl Iterator<Item = &'static Account> {
    BusParts::ACCOUNTS.iter().flat_map(|a| a.iter())
}

/// String equality in a constant context.
const fn str_eq(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// Ship surge speed u \[m/s\].
pub const SURGE: usize = slots(Block::Hull).start;
/// Sway speed v \[m/s\].
pub const SWAY: usize = SURGE + 1;
/// Yaw rate r \[rad/s\].
pub const YAW_RATE: usize = SURGE + 2;
/// North position x \[m\].
pub const X_POS: usize = SURGE + 3;
/// East position y \[m\].
pub const Y_POS: usize = SURGE + 4;
/// Heading psi \[rad\], not wrapped.
pub const HEADING: usize = SURGE + 5;
/// First energy accumulator \[J\]; see [`Energy`].
pub const ENERGY0: usize = slots(Block::Energy).start;
/// The energy accumulators' slots.
pub const ENERGY: std::ops::Range<usize> = slots(Block::Energy);
// The hull's six named slots fill its block.
const _: () = assert!(HEADING + 1 == slots(Block::Hull).end);

/// The state vector.
pub type State = [f64; NX];

/// The drive train's and hull's energy accumulators (offsets from [`ENERGY0`]); sums over all
/// machines. The bus parts' follow ([`part_account`]).
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
    /// Work against the hull's resistance and the rudder's drag in surge (R_sp u in the surge model,
    /// Table 5.6 "ship"), and against the side force and yaw moment in sway and yaw (a turn's and
    /// the waves' side work; 0 on a straight course in calm water).
    Ship,
    /// Energy dissipated in the brake resistors.
    Brake,
    /// Energy the motors returned to the buses (integral of the negative part of the inverter power).
    Regenerated,
}
