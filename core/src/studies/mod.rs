//! Studies built on runs and on the model: Monte Carlo and its statistics (ch. 5.4), the fuel
//! study (Fig. 5-12), the controller study, regressions, the thesis' numbers (which the
//! validation report, crate aes-validation, compares with), and the IPS stability tool (ch. 4), and
//! the operability polar.

pub mod controller;
pub mod fuel;
pub mod fuel_per_mile;
pub mod ips;
pub mod maneuvers;
pub mod montecarlo;
pub mod operability;
pub mod rare;
pub mod regression;
pub mod rice;
pub mod schedule;
pub mod stability_map;
pub mod stats;
pub mod stopping;
pub mod storage_sizing;
pub mod study;
pub mod thesis_values;
/// Every study on the shared pipeline ([`study::Study`]), for the code that picks one by its kind
/// (`aes-sim merge`, the wasm's `studyRange`): a new study adds its type here, once.
#[macro_export]
macro_rules! for_each_study {
    ($m:ident) => {
        $m!(
            $crate::studies::montecarlo::MonteCarlo,
            $crate::studies::rare::RareEvents,
            $crate::studies::rare::RarePair,
            $crate::studies::operability::study::OperabilityPolar,
            $crate::studies::fuel_per_mile::FuelPerMileStudy,
            $crate::studies::storage_sizing::StorageSizing,
            $crate::studies::stability_map::StabilityMapStudy,
        );
    };
}
