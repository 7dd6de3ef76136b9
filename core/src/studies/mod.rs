//! Studies built on runs and on the model: Monte Carlo and its statistics (ch. 5.4), the fuel
//! study (Fig. 5-12), the controller study, regressions, the thesis' numbers (which the
//! validation report, crate aes-validation, compares with), and the IPS stability tool (ch. 4), and
//! the operability polar.

pub mod controller;
pub mod fuel;
pub mod ips;
pub mod montecarlo;
pub mod operability;
pub mod rare;
pub mod regression;
pub mod stats;
pub mod thesis_values;
