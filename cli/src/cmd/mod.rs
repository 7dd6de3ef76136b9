//! The commands of `aes-sim`, one module each: its arguments (clap) and what it does.

pub mod bench;
pub mod design;
pub mod fuel;
pub mod fuel_per_mile;
pub mod health;
pub mod ips;
pub mod lesson;
pub mod maneuvers;
pub mod mc;
pub mod merge;
pub mod operability;
pub mod params;
pub mod presets;
pub mod propeller;
pub mod rao;
pub mod rare;
pub mod run;
pub mod schedule;
pub mod section;
pub mod signals;
pub mod stability_map;
pub mod storage_sizing;
pub mod validate;
