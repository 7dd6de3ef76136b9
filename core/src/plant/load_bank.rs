//! A resistive load bank on each DC bus: a fixed resistor R across the bus, drawing i = v / R and
//! taking P = v^2 / R. Shipyards load generator sets with one in their acceptance trials; on the
//! bus it is a positive resistance beside the constant-power loads, so it damps where they do not
//! (a constant-power load's small-signal resistance is -v^2 / P).
//!
//! The smallest complete bus part (`plant::bus_part`): no state, one energy account. It has no
//! trace signal of its own yet, so the page's form leaves it out (no `group`): the page's power
//! inventory reads the loads' signals and would not see it.

use crate::plant::bus_part::{Account, Book, BusFlow, BusNode, BusPart};
use serde::{Deserialize, Serialize};

crate::params! {
    /// A resistive load bank on each bus; none by default.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields, default)]
    pub struct LoadBankParams {
        /// 10 ohm on the 5618 V bus is 3.2 MW, a tenth of a shaft's sets' rating.
        pub resistance_ohm: f64 = 0.0 => {
            label: "Load bank resistance", unit: "Ω", range: 0.1..=1.0e5, empty: "none",
            source: "none by default (a shipyard's resistive load bank for generator trials)",
            help: "Resistance of the load bank across each bus: it takes v²/R (10 Ω on 5618 V is 3.2 MW). Its energy is in energy_j.bus_loads; it has no trace signal yet, so the page does not offer it.",
        },
    }
}

impl crate::params::CrossCheck for LoadBankParams {}

/// One bus's load bank.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadBank {
    pub resistance_ohm: f64,
}

impl BusPart for LoadBank {
    type Params = LoadBankParams;
    const STATES: &'static [&'static str] = &[];
    const ACCOUNTS: &'static [Account] = &[Account { name: "load_bank", book: Book::Load }];
    const DRAWS: bool = true;

    fn build(p: &LoadBankParams, _v_ref: f64) -> Option<LoadBank> {
        Self::present(p).then_some(LoadBank { resistance_ohm: p.resistance_ohm })
    }
    fn present(p: &LoadBankParams) -> bool {
        p.resistance_ohm > 0.0
    }
    fn steady_input_w(&self, v_bus: f64) -> Result<f64, String> {
        Ok(v_bus * v_bus / self.resistance_ohm)
    }
    fn start(&self, _v_bus: f64, _p_load: f64, _x: &mut [f64]) {}

    #[inline(always)]
    fn derivatives(&self, _x: &[f64], node: &mut BusNode, _dx: &mut [f64], e: &mut [f64], _flow: &mut BusFlow) {
        let i = node.v / self.resistance_ohm;
        node.i_draw += i;
        node.p_load += node.v * i;
        e[0] += node.v * i;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plant::bus_loads::Demand;

    /// Ohm's law at the node: 10 ohm on 5618 V draws 561.8 A and takes 3.156 MW, booked once.
    #[test]
    fn draws_v_over_r() {
        let bank = LoadBank::build(&LoadBankParams { resistance_ohm: 10.0 }, 5618.0).unwrap();
        let mut node = BusNode { v: 5618.0, demand: Demand::default(), i_draw: 0.0, p_load: 1.0e6 };
        let mut e = [0.0];
        bank.derivatives(&[], &mut node, &mut [], &mut e, &mut BusFlow::default());
        assert_eq!(node.i_draw, 561.8);
        assert!((node.p_load - 1.0e6 - 3.156_192_4e6).abs() < 1.0, "{}", node.p_load);
        assert_eq!(e[0], node.p_load - 1.0e6);
        assert_eq!(bank.steady_input_w(5618.0), Ok(e[0]));
        assert!(LoadBank::build(&LoadBankParams::default(), 5618.0).is_none());
    }
}
