//! `aes-sim storage-sizing`: how big a storage the scenario's seaway needs (thesis ch. 5.2.2,
//! 6.1; core/src/studies/storage_sizing.rs): one run per storage size beside the run without,
//! whole or one shard of it (the study pipeline's flags: `--trial-range` over the sizes, item 0
//! the run without storage).

use crate::common::{emit, emit_json, load, shorten, Failure};
use crate::study::{execute, ShardArgs};
use aes_core::studies::storage_sizing::{Cell, Sizing, StorageSizing, StorageSizingSpec};
use aes_core::studies::study::Study;

// The command line of `aes-sim storage-sizing`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario (file, `-` or `preset:NAME`); each size is its run with `plant.storage.energy_j`
    /// and `power_w` set, the other storage fields as it has them.
    #[arg(default_value = "preset:head-seas-ss6")]
    file: String,
    /// Storage energies on each bus [MJ], comma-separated.
    #[arg(long = "energy-mj", value_name = "LIST", default_value = "25,50,100,200,400")]
    energy_mj: String,
    /// Storage power ratings on each bus [MW], comma-separated.
    #[arg(long = "power-mw", value_name = "LIST", default_value = "2.5,5,10,20")]
    power_mw: String,
    /// Length of each run [s] (the scenario's own is overridden): long enough that the charge
    /// settles about its set point and the cycling is counted over many wave groups.
    #[arg(long = "duration-s", default_value_t = 600.0)]
    duration_s: f64,
    /// Print the study as JSON (every size's measures and warnings).
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    shards: ShardArgs,
    /// Override one parameter (repeatable), e.g. `--set plant.loads.pulse_power_w=5e6`.
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
}

/// A comma-separated list of positive numbers times `scale`.
fn list(flag: &str, text: &str, scale: f64) -> Result<Vec<f64>, String> {
    text.split(',')
        .map(|t| {
            t.trim().parse::<f64>().ok().filter(|v| v.is_finite() && *v > 0.0).map(|v| v * scale).ok_or_else(|| {
                format!("{flag} '{}': expected positive numbers separated by commas, e.g. 50,100,200", shorten(text))
            })
        })
        .collect()
}

pub fn run(a: Args) -> Result<(), Failure> {
    let mut sc = load(&a.file, &a.sets)?;
    sc.sim.duration_s = a.duration_s;
    sc.validate().map_err(|e| format!("--duration-s: {e}"))?;
    let energies_j = list("--energy-mj", &a.energy_mj, 1e6)?;
    let powers_w = list("--power-mw", &a.power_mw, 1e6)?;
    let study = StorageSizing::new(StorageSizingSpec { scenario: sc, energies_j, powers_w })?;
    let json = a.json;
    execute(study, &a.shards, "storage-sizing", &a.file, |_, s| {
        if json {
            emit_json(s)
        } else {
            aes_core::checks::check_finite(s)?;
            emit(&table(s))
        }
    })
}

/// One row of the table.
fn row(c: &Cell, base: &Cell) -> String {
    let size = if c.energy_j > 0.0 {
        format!("{:>6.1} {:>5.1}", c.energy_j / 1e6, c.power_w / 1e6)
    } else {
        format!("{:>12}", "none")
    };
    let storage = if c.energy_j > 0.0 {
        format!(
            "{:>+6.1} | {:.2}-{:.2} {:>3.0} % | {:>4.1} % | {:>6.1}",
            c.storage_net_j / 1e6,
            c.soc_min,
            c.soc_max,
            100.0 * c.taper_share,
            100.0 * c.at_rating_share,
            c.cycles_per_hour
        )
    } else {
        format!("{:>6} | {:>15} | {:>6} | {:>6}", "-", "-", "-", "-")
    };
    format!(
        "{size} | {:.4} {:>4.0} % | {:.3}-{:.3} | {:>5.1} | {:>6.1} {:>+5.1} % {:>4.0} % | {:>5.1} | {storage} | {}",
        c.turbine_speed_std_pu,
        100.0 * c.turbine_speed_std_pu / base.turbine_speed_std_pu.max(1e-300),
        c.bus_voltage_min_pu,
        c.bus_voltage_max_pu,
        c.turbine_power_mean_w / 1e6,
        c.fuel_power_mean_w / 1e6,
        100.0 * (c.fuel_power_mean_w / base.fuel_power_mean_w.max(1e-300) - 1.0),
        100.0 * c.below_curve_share,
        c.brake_energy_j / 1e6,
        c.warnings.len()
    )
}

/// The study as a text table, the run without storage first.
fn table(s: &Sizing) -> String {
    let mut t = format!(
        "Storage sizing on {} ({:.0} s, one sea); each size is the energy [MJ] and power rating [MW] on each bus.\n\
         speed: the turbines' speed standard deviation [pu], and against no storage; bus: lowest-highest [pu];\n\
         turbines: mean shaft power [MW]; fuel: mean fuel power [MW], against no storage, and the share of the run\n\
         below the part-load curve's 30 % (extrapolated there, with too little fuel: swings down there look cheap);\n\
         brake: energy burnt [MJ]; given: net energy the storages gave the buses [MJ]; charge: lowest-highest,\n\
         and the share of the run in the taper before a limit (where the storage gives or takes less and less);\n\
         rating: share of the run at the power rating; cycles: equivalent full cycles an hour.\n\n",
        crate::common::shorten(&s.scenario),
        s.duration_s
    );
    t.push_str(
        "  E MJ  P MW | speed std     | bus pu      | turb. | fuel MW, <30 % load  | brake | given  | charge, taper   | rating | cycles | warnings\n",
    );
    t.push_str(&row(&s.without, &s.without));
    t.push('\n');
    for c in &s.cells {
        t.push_str(&row(c, &s.without));
        t.push('\n');
    }
    t
}
