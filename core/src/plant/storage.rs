//! Energy storage on each MVDC bus (thesis ch. 5.2.2: braking energy "must be stored, for
//! instance by capacitors or flywheels, or dissipated"; ch. 6.1): a battery or an
//! ultracapacitor behind a bidirectional DC-DC converter, and the controller that moves it.
//!
//! Cells: open-circuit voltage V_oc (a battery's constant; an ultracapacitor's V_max sqrt(SOC),
//! its energy being C V^2 / 2) behind the internal resistance R_i. Drawing the terminal power
//! P_t takes the current i = (V_oc - sqrt(V_oc^2 - 4 R_i P_t)) / (2 R_i), and the stored energy
//! falls at dE/dt = -V_oc i = -(P_t + R_i i^2).
//!
//! Converter: its bus-side current i_b follows its reference through the current loop, a fast
//! lag di_b/dt = (i_ref - i_b) / tau_i; it delivers P_b = v_bus i_b to the bus and loses
//! (1 - eta) |P_b| (so a round trip through converter and cells keeps about eta^2 less the cells'
//! R_i i^2). P_t = P_b + (1 - eta) |P_b|.
//!
//! Controller (continuous, per bus), the sum of three parts, limited to the power rating and
//! tapered to zero as the state of charge reaches a limit:
//! - load levelling: the fast part of the bus's load, P_load - P_lp, where P_lp follows P_load
//!   through a first-order low-pass of corner f_c (dP_lp/dt = 2 pi f_c (P_load - P_lp)); the
//!   turbines are left the slow part P_lp. P_load is the motor's inverter, the pulsed load and the
//!   ship service converter's input.
//! - droop: P_rated (v_ref - v_bus) / (d v_ref), rated power at a deviation of d (per unit):
//!   voltage support. Braking energy raises the bus, so the droop charges the storage long before
//!   the brake chopper's threshold (1.10 pu by default): it goes into the storage before the
//!   resistor.
//! - state of charge: (E - E_set) / T_soc (a discharge above the set point, a charge below it)
//!   brings the charge back to its set point.
//!
//! Where the limits cut the reference, the low-pass is pulled towards the load by the cut power
//! over [`ANTI_WINDUP_S`] (back-calculation): the turbines then take what the storage cannot, and
//! a clipped charge in the waves' dips is not followed by an unclipped discharge when the load
//! returns (which would drain the charge step by step).

use crate::checks::Validator;
use crate::plant::bus_part::{Account, Book, BusFlow, BusNode, BusPart, CheckInfo, Column};
use crate::signals::Signal;
use serde::{Deserialize, Serialize};

/// The storage's states in its block of each bus: stored energy E \[J\], converter bus-side
/// current i_b \[A\], the low-passed bus load P_lp \[W\].
pub const ENERGY: usize = 0;
pub const CURRENT: usize = 1;
pub const LOWPASS: usize = 2;

/// Width of the taper at each state-of-charge limit \[fraction of the capacity\]: the controller's
/// power goes linearly to zero over it, so that the limits are not crossed by a jump.
pub const SOC_TAPER: f64 = 0.02;

/// Least time the taper takes to hand a storage's full power back to the turbines \[s\]: the taper
/// is at least `power_w * HANDOVER_S` of energy wide, so near a limit the power decays with a
/// time constant of at least this. With the 2 % taper alone a storage small beside its rating
/// crossed its taper in tens of milliseconds and dropped its whole power on the turbines in a
/// step: in `aes-sim storage-sizing` on head-seas-ss6 (600 s) 25 MJ at 20 MW swung the turbines'
/// speed 1.8 times as much as no storage; with 1 s 0.85 times, and the suggested 200 MJ at
/// 10 MW went from 4 % to 1 % of the swing without storage (3 s and 10 s help less: the taper
/// then eats the window the storage levels with).
pub const HANDOVER_S: f64 = 1.0;

/// Width of the taper at each charge limit \[J\]: the wider of [`SOC_TAPER`] of the capacity and
/// [`HANDOVER_S`] of the rated power.
pub fn taper_j(capacity_j: f64, power_w: f64) -> f64 {
    (SOC_TAPER * capacity_j).max(power_w * HANDOVER_S)
}

/// Share of a bus's turbines' fastest pick-up (their rating times the governor's throttle slew,
/// the fuel schedule's limit) that a storage's hand-over near its floor may take \[-\]. The rest is
/// left for the load's own rise and for the governor, which reaches its slew limit only once a
/// speed error has built up. Chosen on the crash stop, the sharpest hand-over of any preset (a
/// 20 MW battery a bus carrying a rising astern load to its floor, the turbines at part load):
/// with the 1 s taper alone the bus fell to 0.751 pu at 150 MJ a bus and 0.694 pu at 200 MJ;
/// handing over at 1/2 of the pick-up, 0.878 pu at 150 MJ; at 1/4, 0.918-0.929 pu from 50 to
/// 200 MJ, inside the band (tests/astern.rs).
pub const HANDOVER_SHARE: f64 = 0.25;

/// The rate at which a storage hands its power back to the turbines near its floor \[W/s\]:
/// [`HANDOVER_SHARE`] of what `sets` turbines rated `rated_w` \[W\] take up at the throttle slew
/// `slew_per_s` \[1/s\].
pub fn handover_rate_w_per_s(sets: f64, rated_w: f64, slew_per_s: f64) -> f64 {
    HANDOVER_SHARE * sets * rated_w * slew_per_s
}

/// Energy a storage discharging at `power_w` keeps above its floor \[J\] so that it can hand that
/// power back at `rate_w_per_s` \[W/s\] (a linear ramp from P to 0 at rate R uses P^2 / (2 R)): its
/// discharge is limited to sqrt(2 R (E - E_min)), so near the floor the power falls at R and
/// reaches 0 there.
pub fn discharge_reserve_j(power_w: f64, rate_w_per_s: f64) -> f64 {
    power_w * power_w / (2.0 * rate_w_per_s)
}

/// Charge above the floor below which the controller starts to give less than its rating \[J\]:
/// the wider of the taper ([`taper_j`]) and the hand-over reserve at the rating
/// ([`discharge_reserve_j`]).
pub fn discharge_edge_j(capacity_j: f64, power_w: f64, rate_w_per_s: f64) -> f64 {
    taper_j(capacity_j, power_w).max(discharge_reserve_j(power_w, rate_w_per_s))
}

/// Time constant of the levelling filter's anti-windup \[s\]: how fast the turbines take over what
/// the storage's limits cut.
pub const ANTI_WINDUP_S: f64 = 1.0;

crate::choices! {
    /// The storage's cells.
    pub enum StorageKind {
        Battery = "battery", "battery: constant open-circuit voltage",
        Ultracapacitor = "ultracapacitor", "ultracapacitor: voltage as the square root of the charge",
    }
}

crate::params! {
    /// Energy storage on each bus behind a bidirectional DC-DC converter; none by default.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct StorageParams {
        /// Storage sizing's suggested size (docs/studies/storage-sizing.md) for head-seas-ss6 is the "with storage" preset's.
        pub energy_j: f64 = 0.0 => {
            label: "Storage energy", unit: "J", range: 1.0e5..=1.0e12, empty: "none", group: "plant",
            source: "none by default; the with-storage preset's size for head-seas-ss6",
            help: "Energy capacity of the storage on each bus (0: no storage).",
        },
        pub kind: StorageKind = StorageKind::Battery => {
            label: "Storage cells", group: "plant", source: "our choice",
            help: "Battery (constant open-circuit voltage) or ultracapacitor (voltage as the square root of the charge).",
        },
        pub power_w: f64 = 10.0e6 => {
            label: "Storage power rating", unit: "W", range: 1.0e4..=1.0e8, group: "plant",
            source: "our choice: a quarter of a motor's 38 MW rating",
            help: "Largest power the converter takes from or gives to the bus.",
        },
        pub voltage_v: f64 = 1000.0 => {
            label: "Storage voltage", unit: "V", range: 10.0..=2.0e4, group: "plant",
            source: "our choice: a 1 kV string",
            help: "Open-circuit voltage of the cells (an ultracapacitor's when full).",
        },
        pub internal_resistance_ohm: f64 = 0.002 => {
            label: "Storage internal resistance", unit: "Ω", range: 0.0..=10.0, group: "plant",
            source: "our choice: 2 % loss at 10 MW from 1 kV",
            help: "Resistance of the cells in series.",
        },
        pub converter_efficiency: f64 = 0.98 => {
            label: "Converter efficiency", unit: "-", range: 0.5..=1.0, group: "plant",
            source: "our choice: a DC-DC converter's 98 %",
            help: "Of the DC-DC converter, each way (the round trip keeps its square, less the cells' loss).",
        },
        pub soc_min: f64 = 0.2 => {
            label: "Lowest state of charge", unit: "-", range: 0.0..=1.0, group: "plant",
            source: "our choice: a battery's usual window", help: "The controller stops discharging here.",
        },
        pub soc_max: f64 = 0.9 => {
            label: "Highest state of charge", unit: "-", range: 0.0..=1.0, group: "plant",
            source: "our choice: a battery's usual window", help: "The controller stops charging here.",
        },
        pub soc_set: f64 = 0.55 => {
            label: "State of charge set point", unit: "-", range: 0.0..=1.0, group: "plant",
            source: "our choice: the middle of the window", help: "Where the charge starts and returns to.",
        },
        pub current_time_constant_s: f64 = 0.01 => {
            label: "Current loop time constant", unit: "s", range: 1.0e-4..=10.0, group: "plant",
            source: "our choice: a fast lag beside the waves' seconds, resolved by the 5 ms step",
            help: "The converter's current follows its reference with this lag.",
        },
        pub droop_pu: f64 = 0.05 => {
            label: "Voltage droop", unit: "pu", range: 1.0e-3..=1.0, group: "plant",
            base: "the bus voltage set point (controllers.field.bus_voltage_ref_v)",
            source: "our choice: rated power at 5 % deviation, a usual droop",
            help: "Bus voltage deviation at which the droop alone asks for rated power.",
        },
        pub corner_hz: f64 = 0.02 => {
            label: "Load levelling corner", unit: "Hz", range: 1.0e-5..=10.0, group: "plant",
            source: "our choice: below the waves' 0.05-0.2 Hz, so the storage takes their swings",
            help: "The storage takes the bus load's changes faster than this; the turbines the slower part.",
        },
        pub soc_return_s: f64 = 300.0 => {
            label: "Charge return time", unit: "s", range: 1.0..=1.0e7, group: "plant",
            source: "our choice: slow beside the waves",
            help: "Time constant with which the charge returns to its set point.",
        },
    }
}

impl crate::params::CrossCheck for StorageParams {
    fn cross_check(&self, v: &mut Validator) {
        if self.soc_min >= self.soc_max {
            v.fail("soc_min", crate::checks::num(self.soc_min), format!("must be below soc_max = {}", self.soc_max));
        } else if !(self.soc_min..=self.soc_max).contains(&self.soc_set) {
            v.fail(
                "soc_set",
                crate::checks::num(self.soc_set),
                format!("must lie within the limits soc_min = {} to soc_max = {}", self.soc_min, self.soc_max),
            );
        }
        if self.energy_j > 0.0 && self.kind == StorageKind::Battery {
            // The cells' largest power V^2 / (4 R) must cover the rating and its converter loss.
            let r = self.internal_resistance_ohm;
            if r > 0.0 && self.voltage_v * self.voltage_v / (4.0 * r) < self.power_w * (2.0 - self.converter_efficiency)
            {
                v.fail(
                    "internal_resistance_ohm",
                    crate::checks::num(r),
                    format!(
                        "is too high for power_w = {} W from voltage_v = {} V (the cells give at most V^2 / (4 R))",
                        self.power_w, self.voltage_v
                    ),
                );
            }
        }
    }
}

/// The run's warning when the storage has no energy (`energy_j` = 0, none) but other storage
/// fields were set away from their defaults: they are ignored, which a user who set a power
/// rating and forgot the energy would not expect.
pub fn ignored_without_energy(p: &StorageParams) -> Option<String> {
    if p.energy_j > 0.0 {
        return None;
    }
    let (set, default) = (serde_json::to_value(p).ok()?, serde_json::to_value(StorageParams::default()).ok()?);
    let changed: Vec<String> = set
        .as_object()?
        .iter()
        .filter(|(k, v)| default.get(k.as_str()) != Some(v))
        .map(|(k, _)| format!("plant.storage.{k}"))
        .collect();
    (!changed.is_empty()).then(|| {
        format!(
            "plant.storage.energy_j = 0: no storage, so {} set here {} ignored; give the storage an energy (from 1e5 J) to use {}",
            changed.join(", "),
            if changed.len() == 1 { "is" } else { "are" },
            if changed.len() == 1 { "it" } else { "them" }
        )
    })
}

/// One bus's storage: its constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Storage {
    pub capacity_j: f64,
    pub ultracapacitor: bool,
    pub power_w: f64,
    pub voltage_v: f64,
    pub r_ohm: f64,
    pub efficiency: f64,
    pub e_min: f64,
    pub e_max: f64,
    pub e_set: f64,
    pub tau_i: f64,
    /// Droop gain \[W/V\]: P_rated / (d v_ref).
    pub droop_w_per_v: f64,
    /// Low-pass rate 2 pi f_c \[1/s\].
    pub corner_rad_s: f64,
    pub soc_return_s: f64,
    /// Bus voltage set point \[V\].
    pub v_ref: f64,
    /// Rate at which it hands its power back near its floor \[W/s\] ([`handover_rate_w_per_s`],
    /// set by `with_handover`); infinite until set.
    pub handover_w_per_s: f64,
}

/// What the storage does at one instant.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct StorageFlow {
    /// dE/dt \[W\], di_b/dt \[A/s\], dP_lp/dt \[W/s\].
    pub de: f64,
    pub di_b: f64,
    pub dp_lp: f64,
    /// Power to the bus v i_b \[W\] (negative: charging).
    pub p_bus: f64,
    /// Converter and cell losses \[W\].
    pub p_loss: f64,
    /// The controller's power reference \[W\].
    pub p_ref: f64,
}

impl Storage {
    /// The storage of `p` on a bus held at `v_ref` \[V\]; None without storage.
    pub fn new(p: &StorageParams, v_ref: f64) -> Option<Storage> {
        (p.energy_j > 0.0).then(|| Storage {
            capacity_j: p.energy_j,
            ultracapacitor: p.kind == StorageKind::Ultracapacitor,
            power_w: p.power_w,
            voltage_v: p.voltage_v,
            r_ohm: p.internal_resistance_ohm,
            efficiency: p.converter_efficiency,
            e_min: p.soc_min * p.energy_j,
            e_max: p.soc_max * p.energy_j,
            e_set: p.soc_set * p.energy_j,
            tau_i: p.current_time_constant_s,
            droop_w_per_v: p.power_w / (p.droop_pu * v_ref),
            corner_rad_s: 2.0 * std::f64::consts::PI * p.corner_hz,
            soc_return_s: p.soc_return_s,
            v_ref,
            handover_w_per_s: f64::INFINITY,
        })
    }

    /// The same handing its power back at `handover_w_per_s` \[W/s\] near its floor.
    pub fn with_handover(self, handover_w_per_s: f64) -> Storage {
        Storage { handover_w_per_s, ..self }
    }

    /// Open-circuit voltage at stored energy `e` \[V\].
    pub fn open_circuit_v(&self, e: f64) -> f64 {
        if self.ultracapacitor {
            self.voltage_v * libm::sqrt((e / self.capacity_j).max(1e-6))
        } else {
            self.voltage_v
        }
    }

    /// Cell current \[A\] and loss \[W\] at terminal power `p_t` \[W\] and stored energy `e` \[J\].
    pub fn cells(&self, p_t: f64, e: f64) -> (f64, f64) {
        let v = self.open_circuit_v(e);
        if self.r_ohm <= 0.0 {
            return (p_t / v, 0.0);
        }
        let disc = (v * v - 4.0 * self.r_ohm * p_t).max(0.0);
        let i = (v - libm::sqrt(disc)) / (2.0 * self.r_ohm);
        (i, self.r_ohm * i * i)
    }

    /// The controller's power reference \[W\] with the bus at `v_bus`, its load at `p_load`, the
    /// low-passed load `p_lp` and the stored energy `e` (levelling + droop + charge return,
    /// limited and tapered at the charge limits).
    pub fn reference_w(&self, v_bus: f64, p_load: f64, p_lp: f64, e: f64) -> f64 {
        self.reference_parts_w(v_bus, p_load, p_lp, e).1
    }

    /// The reference before and after its limits \[W\].
    fn reference_parts_w(&self, v_bus: f64, p_load: f64, p_lp: f64, e: f64) -> (f64, f64) {
        let raw = (p_load - p_lp) + self.droop_w_per_v * (self.v_ref - v_bus) + (e - self.e_set) / self.soc_return_s;
        let p = raw.clamp(-self.power_w, self.power_w);
        let taper = taper_j(self.capacity_j, self.power_w);
        let p = if p > 0.0 {
            let reserve = libm::sqrt(2.0 * self.handover_w_per_s * (e - self.e_min).max(0.0));
            (p * ((e - self.e_min) / taper).clamp(0.0, 1.0)).min(reserve)
        } else {
            p * ((self.e_max - e) / taper).clamp(0.0, 1.0)
        };
        (raw, p)
    }

    /// The storage's rates with the bus at `v_bus`, its load `p_load` \[W\] and the states
    /// (`e`, `i_b`, `p_lp`).
    pub fn flow(&self, v_bus: f64, p_load: f64, e: f64, i_b: f64, p_lp: f64) -> StorageFlow {
        let (raw, p_ref) = self.reference_parts_w(v_bus, p_load, p_lp, e);
        let i_ref = p_ref / v_bus.max(0.5 * self.v_ref);
        let p_bus = v_bus * i_b;
        let p_conv = (1.0 - self.efficiency) * p_bus.abs();
        let p_t = p_bus + p_conv;
        let (i_c, p_cells) = self.cells(p_t, e);
        StorageFlow {
            de: -self.open_circuit_v(e) * i_c,
            di_b: (i_ref - i_b) / self.tau_i,
            dp_lp: self.corner_rad_s * (p_load - p_lp) + (raw - p_ref) / ANTI_WINDUP_S,
            p_bus,
            p_loss: p_conv + p_cells,
            p_ref,
        }
    }
}

impl BusPart for Storage {
    type Params = StorageParams;
    const STATES: &'static [&'static str] = &["storage_energy", "storage_current", "storage_lowpass"];
    const ACCOUNTS: &'static [Account] =
        &[Account { name: "storage_to_bus", book: Book::ToBus }, Account { name: "storage_loss", book: Book::Loss }];

    fn build(p: &StorageParams, v_ref: f64) -> Option<Storage> {
        Storage::new(p, v_ref)
    }
    fn present(p: &StorageParams) -> bool {
        p.energy_j > 0.0
    }

    /// At its charge set point, giving nothing, its levelling filter at the bus's load.
    fn start(&self, _v_bus: f64, p_load: f64, x: &mut [f64]) {
        x[ENERGY] = self.e_set;
        x[CURRENT] = 0.0;
        x[LOWPASS] = p_load;
    }

    /// Levels the load of the parts before it (and the motor's).
    #[inline(always)]
    fn derivatives(&self, x: &[f64], node: &mut BusNode, dx: &mut [f64], e: &mut [f64], flow: &mut BusFlow) {
        let f = self.flow(node.v, node.p_load, x[ENERGY], x[CURRENT], x[LOWPASS]);
        dx[ENERGY] = f.de;
        dx[CURRENT] = f.di_b;
        dx[LOWPASS] = f.dp_lp;
        node.i_draw -= x[CURRENT];
        e[0] += f.p_bus;
        e[1] += f.p_loss;
        flow.storage_w = f.p_bus;
        flow.soc = x[ENERGY] / self.capacity_j;
    }

    fn add_stored_energy(&self, x: &[f64], e: &mut f64) {
        *e += x[ENERGY];
    }

    fn checks() -> Vec<CheckInfo> {
        vec![CheckInfo {
            name: "storage charge outside its limits",
            threshold: "the storage's state of charge (mean of the two) below `plant.storage.soc_min` or above \
                            `soc_max` at a recorded time"
                .into(),
            reason: "the controller tapers its power to zero at each limit; a charge beyond one means the cells \
                         are worked outside the window their life is rated for",
        }]
    }

    /// The charge against its limits.
    fn assess(st: &StorageParams, _t: &[f64], column: Column<'_>, out: &mut Vec<String>) {
        if st.energy_j <= 0.0 {
            return;
        }
        let soc = column(Signal::StorageSoc);
        let (lo, hi) = soc.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
        if lo < st.soc_min || hi > st.soc_max {
            out.push(format!(
                "storage charge outside its limits: {lo:.3} to {hi:.3} against plant.storage.soc_min = {} and \
                 soc_max = {}",
                st.soc_min, st.soc_max
            ));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn storage() -> Storage {
        Storage::new(&StorageParams { energy_j: 100.0e6, ..Default::default() }, 5618.0).unwrap()
    }

    /// The cells' books: what leaves the store is the terminal power plus R i^2 (measured
    /// residual 0 W at 10 MW; the loss 2.1 % of it).
    #[test]
    fn cells_conserve_energy() {
        let s = storage();
        for p in [-10.0e6, -1.0e6, 0.0, 3.0e6, 10.0e6] {
            let (i, loss) = s.cells(p, 50.0e6);
            let out = s.open_circuit_v(50.0e6) * i;
            assert!((out - p - loss).abs() < 1e-9 * p.abs().max(1.0), "{p}: {out} {loss}");
        }
        let (_, loss) = s.cells(10.0e6, 50.0e6);
        assert!(loss > 0.019 * 10.0e6 && loss < 0.022 * 10.0e6, "{loss}");
    }

    /// The reference stops discharging at the lowest charge and charging at the highest, and is
    /// limited to the rating.
    #[test]
    fn reference_respects_limits() {
        let s = storage();
        assert_eq!(s.reference_w(5618.0, 50.0e6, 0.0, 0.5 * 100.0e6), s.power_w);
        assert_eq!(s.reference_w(5618.0, 5.0e6, 0.0, s.e_min), 0.0);
        assert_eq!(s.reference_w(5618.0, -5.0e6, 0.0, s.e_max), 0.0);
        // Bus 1 % low: droop alone asks a fifth of the rating (5 % droop).
        let p = s.reference_w(0.99 * 5618.0, 0.0, 0.0, s.e_set);
        assert!((p - 0.2 * s.power_w).abs() < 1e-6 * s.power_w, "{p}");
    }
}
