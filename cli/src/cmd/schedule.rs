//! `aes-sim schedule`: how many gas turbines should run, speed by speed and sea state by sea state
//! (thesis ch. 6.1; core/src/studies/schedule.rs).

use crate::common::{emit, emit_json, load, Failure};
use aes_core::studies::schedule::{self, Schedule};
use std::time::Instant;

// The command line of `aes-sim schedule`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario (its plant, ship and `plant.online` rules; its sea is ignored: sea states 2-6).
    #[arg(default_value = "preset:startup")]
    file: String,
    /// Print the whole schedule as JSON (every count's power, fuel and overload chance).
    #[arg(long)]
    json: bool,
    /// Also evaluate all 15 online sets at every cell, each with its own steady state, and check
    /// that the schedule's choice burns the least fuel among those that keep the reserve.
    #[arg(long)]
    exhaustive: bool,
    /// Override one parameter (repeatable), e.g. `--set plant.online.reserve_probability=1e-4`.
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
}

pub fn run(Args { file, json, exhaustive, sets }: Args) -> Result<(), Failure> {
    let sc = load(&file, &sets)?;
    sc.validate().map_err(|e| e.to_string())?;
    // One RAO-table build, timed (the schedule then reads the same table).
    let t0 = Instant::now();
    sc.rao_table()?;
    let rao_s = t0.elapsed().as_secs_f64();
    let t1 = Instant::now();
    let s = schedule::run(&sc)?;
    let schedule_s = t1.elapsed().as_secs_f64();
    aes_core::checks::check_finite(&s)?;
    let mut failed = Vec::new();
    if exhaustive {
        for c in &s.cells {
            let (_, best) = schedule::exhaustive(&sc, c.speed_kn, c.sea_state)?;
            let agree = match (best, c.fuel_power_w) {
                (Some(b), Some(f)) => (b - f).abs() <= 1e-9 * f.abs(),
                (None, _) => c.reserve_unmet || c.count.is_none(),
                _ => false,
            };
            if !agree {
                failed.push(format!(
                    "{} kn SS{}: exhaustive {best:?} W, schedule {:?} W",
                    c.speed_kn, c.sea_state, c.fuel_power_w
                ));
            }
        }
    }
    if json {
        emit_json(&serde_json::json!({
            "schedule": s,
            "rao_table_s": rao_s,
            "schedule_s": schedule_s,
            "exhaustive_failures": failed,
        }))?;
    } else {
        let mut text = table(&s);
        text.push_str(&format!(
            "\ncomputed in {schedule_s:.2} s (one RAO-table build of this ship: {rao_s:.2} s, before it)\n"
        ));
        if exhaustive {
            text.push_str(&if failed.is_empty() {
                format!(
                    "exhaustive check: all 15 online sets at each of the {} cells; the schedule's choice burns least\n",
                    s.cells.len()
                )
            } else {
                format!("exhaustive check FAILED at {} cells:\n{}\n", failed.len(), failed.join("\n"))
            });
        }
        emit(&text)?;
    }
    if !failed.is_empty() {
        return Err(Failure::from(format!("the exhaustive check failed at {} cells", failed.len())));
    }
    Ok(())
}

/// The schedule as a text table: sets online and the fuel saving against four.
fn table(s: &Schedule) -> String {
    let mut t = format!(
        "Gas turbines online for least fuel with the reserve (overload chance below {:e} in {:.0} s), head seas\n\
         cell: sets online (fuel saving against four online); * the reserve decides (fewer would burn less), \
         + the reserve needs sets below their minimum load, ! no count keeps the reserve, - beyond the plant\n\n speed kn |",
        s.reserve_probability, s.reserve_window_s
    );
    for ss in &s.sea_states {
        t.push_str(&format!("      SS{ss}     |"));
    }
    t.push('\n');
    for &v in &s.speeds_kn {
        t.push_str(&format!(" {v:>8.1} |"));
        for &ss in &s.sea_states {
            let cell = s.cell(v, ss);
            let txt = match cell.and_then(|c| c.count.map(|n| (n, c))) {
                None => "-".to_string(),
                Some((n, c)) => {
                    let mark = if c.reserve_unmet {
                        "!"
                    } else if c.below_min_load {
                        "+"
                    } else if c.reserve_decides {
                        "*"
                    } else {
                        " "
                    };
                    format!("{n}{mark} ({:>4.1} %)", 100.0 * c.saving.unwrap_or(0.0))
                }
            };
            t.push_str(&format!(" {txt:>12} |"));
        }
        t.push('\n');
    }
    t
}
