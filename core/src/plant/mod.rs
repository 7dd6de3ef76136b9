//! The propulsion plant, turbine to propeller (thesis ch. 2.1-2.3): the gas turbine and its
//! governor, the synchronous generator, the DC link (rectifier, bus, inverter, brake), the induction
//! motor, the propeller with its surface losses, and the turbines' fuel; the other loads on each
//! bus and its energy storage (ch. 6.1).

pub mod bus_loads;
pub mod dc_link;
pub mod fuel;
pub mod generator;
pub mod motor;
pub mod online;
pub mod prime_mover;
pub mod propeller;
pub mod propeller_losses;
pub mod storage;
