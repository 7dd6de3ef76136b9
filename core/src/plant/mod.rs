//! The propulsion plant, turbine to propeller (thesis ch. 2.1-2.3): the gas turbine and its
//! governor, the synchronous generator, the DC link (rectifier, bus, inverter, brake), the induction
//! motor, the propeller with its surface losses, and the turbines' fuel; the other loads on each
//! bus and its energy storage (ch. 6.1).

pub mod blade;
pub mod bus_loads;
pub mod bus_part;
pub mod dc_link;
pub mod fuel;
pub mod generator;
pub mod layout;
pub mod load_bank;
pub mod motor;
pub mod online;
pub mod prime_mover;
pub mod propeller;
pub mod propeller_geometry;
pub mod propeller_losses;
pub mod propeller_table;
pub mod storage;

crate::plant_section! {
    fixed {
        turbine: prime_mover::TurbineParams,
        generator: generator::GeneratorParams,
        dc_link: dc_link::DcLinkParams,
        motor: motor::MotorParams,
    }
    // The bus parts, one line each, in the order they meet at the bus node: a storage levels the
    // load of the parts before it, so it comes last.
    bus_parts {
        /// The ship service and pulsed loads on each bus (ch. 6.1); none by default.
        loads: bus_loads::BusLoads,
        /// A resistive load bank on each bus; none by default.
        load_bank: load_bank::LoadBank,
        /// Energy storage on each bus (ch. 5.2.2, 6.1); none by default.
        storage: storage::Storage,
    }
    last {
        /// Which sets run, and the rules of starting and stopping one (all four by default).
        online: online::OnlineParams,
    }
}
