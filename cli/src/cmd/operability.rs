//! `aes-sim operability`: the operability polar of a scenario's ship (speed x heading x sea),
//! with the limiting criterion of every cell and the operable share of a wave scatter diagram.

use crate::common::{emit_json, load, read_bounded, shorten, Failure};
use crate::study::{execute, ShardArgs};
use aes_core::studies::operability::scatter::{Scatter, MAX_SCATTER_BYTES};
use aes_core::studies::operability::study::{OperabilityPolar, PolarStudySpec};
use aes_core::studies::operability::{table_2_4, PolarRequest};
use aes_core::studies::study::Study;

// The command line of `aes-sim operability`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario (file, `-` or `preset:NAME`): its hull, loading, hub depth, spreading
    /// (sea.spreading), hub-depth formula and `operability` section (points, criteria).
    #[arg(default_value = "preset:startup")]
    file: String,
    /// Ship speeds [kn], comma separated (default 0 to 30 in 3 kn steps).
    #[arg(long, value_delimiter = ',')]
    speeds: Vec<f64>,
    /// Wave headings relative to the ship [deg], comma separated: 180 head seas, 90 waves from
    /// starboard, 0 following (default 0 to 345 in 15 deg steps).
    #[arg(long, value_delimiter = ',')]
    headings: Vec<f64>,
    /// Sea states of Table 2.4 (2 to 6), comma separated (default all five).
    #[arg(long = "sea-states", value_delimiter = ',')]
    sea_states: Vec<u32>,
    /// Seas of one's own instead, as H_1/3:T_p pairs [m:s], comma separated (e.g. 2:8,4:10,6:12).
    #[arg(long, value_delimiter = ',', conflicts_with = "sea_states")]
    seas: Vec<String>,
    /// Wave scatter diagram CSV (the layout of core/data/iacs_rec34_north_atlantic.csv), or
    /// `none`; default: the IACS Rec. 34 North Atlantic.
    #[arg(long)]
    scatter: Option<String>,
    #[command(flatten)]
    shards: ShardArgs,
    /// Override one parameter (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
}

/// `--seas` pairs H:Tp as [H m, T_p s].
fn own_seas(pairs: &[String]) -> Result<Vec<[f64; 2]>, String> {
    pairs
        .iter()
        .map(|p| {
            let bad = || format!("--seas '{}': expected H_1/3:T_p in m:s, e.g. 4:10", shorten(p));
            let (h, t) = p.split_once(':').ok_or_else(bad)?;
            let h: f64 = h.trim().parse().map_err(|_| bad())?;
            let t: f64 = t.trim().parse().map_err(|_| bad())?;
            if !(t.is_finite() && t > 0.0) {
                return Err(format!("--seas '{}': T_p must be a positive number of seconds", shorten(p)));
            }
            Ok([h, t])
        })
        .collect()
}

pub fn run(Args { file, speeds, headings, sea_states, seas, scatter, shards, sets }: Args) -> Result<(), Failure> {
    let sc = load(&file, &sets)?;
    sc.validate().map_err(|e| format!("{}: {e}", shorten(&file)))?;
    let mut request = PolarRequest::default();
    if !speeds.is_empty() {
        request.speeds_kn = Some(speeds);
    }
    if !headings.is_empty() {
        request.headings_deg = Some(headings);
    }
    if !sea_states.is_empty() {
        table_2_4(&sea_states).map_err(|e| format!("--sea-states: {e}"))?;
        request.sea_states = Some(sea_states);
    }
    if !seas.is_empty() {
        request.seas = Some(own_seas(&seas)?);
    }
    match scatter.as_deref() {
        None => {}
        Some("none") => request.scatter_csv = Some("none".into()),
        Some(path) => {
            let text = read_bounded(path, MAX_SCATTER_BYTES as u64, "a scatter diagram")?;
            Scatter::parse(&text, path).map_err(|e| format!("--scatter {}: {e}", shorten(path)))?;
            request.scatter_csv = Some(text);
            request.scatter_name = Some(path.to_string());
        }
    }
    let study = OperabilityPolar::new(PolarStudySpec { scenario: sc, request })?;
    execute(study, &shards, "operability", &file, |_, polar| emit_json(polar))
}
