//! `aes-sim propeller`: open-water KT, 10KQ and efficiency of a propeller computed from its blade
//! geometry by the lifting line (thesis ch. 3.2), and its radial loading at one advance ratio.

use crate::common::{emit, emit_json, read_bounded, Failure};
use aes_core::plant::blade::{self, geometry::MAX_CSV_BYTES, BladeGeometry, Flow};

// The command line of `aes-sim propeller`.
#[derive(clap::Args)]
pub struct Args {
    /// A blade table, CSV with the header r_R,c_D,P_D,f0_c,t0_c,skew_deg,rake_D (`-` for standard
    /// input). A scenario does not yet carry a propeller geometry, so only a table is accepted.
    input: String,
    /// Number of blades Z.
    #[arg(long)]
    blades: u32,
    /// Hub diameter over propeller diameter.
    #[arg(long = "hub-ratio")]
    hub_ratio: f64,
    /// Propeller diameter [m], for the sections' Reynolds numbers (default: DTMB 4119's model, 1 ft).
    #[arg(long = "diameter-m", default_value_t = 0.3048)]
    diameter_m: f64,
    /// Shaft speed [rpm], for the Reynolds numbers (default 600, DTMB 4119's 10 rev/s test).
    #[arg(long, default_value_t = 600.0)]
    rpm: f64,
    /// Advance ratios FROM:TO:N (N points, ends included).
    #[arg(long, default_value = "0:1.2:25", value_name = "FROM:TO:N")]
    j: String,
    /// Also the radial circulation and section loading at this advance ratio.
    #[arg(long = "at-j")]
    at_j: Option<f64>,
    /// Markdown tables instead of JSON.
    #[arg(long)]
    markdown: bool,
}

/// The advance ratios of `--j FROM:TO:N`.
fn advance_ratios(text: &str) -> Result<Vec<f64>, String> {
    let bad = || format!("--j '{}': expected FROM:TO:N, e.g. 0:1.2:25", crate::common::shorten(text));
    let parts: Vec<&str> = text.split(':').collect();
    let [from, to, n] = parts[..] else { return Err(bad()) };
    let (from, to): (f64, f64) = (from.parse().map_err(|_| bad())?, to.parse().map_err(|_| bad())?);
    let n: usize = n.parse().map_err(|_| bad())?;
    let range = blade::ADVANCE_RATIO;
    for (name, v) in [("FROM", from), ("TO", to)] {
        if !(v.is_finite() && range.contains(&v)) {
            return Err(format!("--j {name}: {v} is outside {}..={}", range.start(), range.end()));
        }
    }
    if !(1..=400).contains(&n) || (n == 1 && from != to) || to < from {
        return Err(format!("--j N: {n} points from {from} to {to}; N is 1..=400 and TO is not below FROM"));
    }
    Ok((0..n).map(|k| if n == 1 { from } else { from + (to - from) * k as f64 / (n - 1) as f64 }).collect())
}

pub fn run(a: Args) -> Result<(), Failure> {
    let text = read_bounded(&a.input, MAX_CSV_BYTES as u64, "a blade table")?;
    let g = BladeGeometry::from_csv(&text, a.blades, a.hub_ratio)?;
    // The flow's own ranges, said in the flags' units.
    if !(a.rpm.is_finite() && (6.0..=12000.0).contains(&a.rpm)) {
        return Err(format!("--rpm: {} is outside 6..=12000", crate::common::shorten(&a.rpm.to_string())).into());
    }
    let flow = Flow::fresh_water(a.diameter_m, a.rpm / 60.0);
    flow.check().map_err(|e| format!("--{}", e.replace("diameter_m", "diameter-m")))?;
    let js = advance_ratios(&a.j)?;
    let curve = blade::open_water(&g, &js, &flow)?;
    let at = a.at_j.map(|j| blade::analyse(&g, j, &flow).map_err(|e| format!("--at-j: {e}"))).transpose()?;
    if a.markdown {
        let mut s = String::from("| J | KT | 10KQ | eta | converged |\n|---|---|---|---|---|\n");
        for p in &curve {
            s += &format!("| {:.3} | {:.4} | {:.4} | {:.3} | {} |\n", p.j, p.kt, 10.0 * p.kq, p.eta, p.converged);
        }
        if let Some(p) = &at {
            s += &format!(
                "\nAt J = {}: KT {:.4}, 10KQ {:.4}\n\n| r/R | chord [m] | G | beta_i [deg] | alpha [deg] | V* [m/s] | CL | CD | Re |\n|---|---|---|---|---|---|---|---|---|\n",
                p.j,
                p.kt,
                10.0 * p.kq
            );
            for x in &p.sections {
                s += &format!(
                    "| {:.3} | {:.4} | {:.5} | {:.2} | {:.2} | {:.2} | {:.3} | {:.4} | {:.3e} |\n",
                    x.r_r,
                    x.chord_m,
                    x.circulation,
                    x.beta_i_rad.to_degrees(),
                    x.alpha_rad.to_degrees(),
                    x.v_star_m_s,
                    x.cl,
                    x.cd,
                    x.reynolds
                );
            }
        }
        return emit(s.trim_end());
    }
    let rows: Vec<_> = curve
        .iter()
        .map(|p| serde_json::json!({"j": p.j, "kt": p.kt, "kq": p.kq, "eta": p.eta, "converged": p.converged}))
        .collect();
    let mut out = serde_json::json!({
        "model": "lifting line (Wrench induction, hub image, Eckhardt & Morgan 1955 camber factor)",
        "blades": g.blades,
        "hub_ratio": g.hub_ratio,
        "flow": flow,
        "open_water": rows,
        // The cavitation margins per radius come here (--depth-m) when the section pressure
        // solution is merged.
        "cavitation": serde_json::Value::Null,
    });
    if let Some(p) = at {
        out["at_j"] = serde_json::to_value(p).map_err(|e| e.to_string())?;
    }
    emit_json(&out)
}
