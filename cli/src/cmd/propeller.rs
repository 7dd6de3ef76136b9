//! `aes-sim propeller`: open-water KT, 10KQ and efficiency of a propeller computed from its blade
//! geometry by the vortex lattice (the run's model) or the lifting line (thesis ch. 3.2), the
//! lifting line's radial loading at one advance ratio, and its sections' cavitation margins with
//! the blade at 12 o'clock (ch. 3.2.2); for a scenario, the ship's calm-water cavitation-inception
//! speed.

use crate::common::{emit, emit_json, load, read_bounded, shorten, Failure};
use aes_core::plant::blade::cavitation::{check_point, PointCavitation, PropellerBuckets, Water};
use aes_core::plant::blade::{self, geometry::MAX_CSV_BYTES, Analysis, BladeGeometry, Flow};
use aes_core::sim::propeller_cavitation as pc;

/// The water of a blade table's analysis.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum WaterKind {
    /// Fresh water at 15 degC (a model basin's).
    Fresh,
    /// Sea water at 15 degC.
    Sea,
}

/// The open-water analysis.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Method {
    /// The vortex lattice: the chord resolved (the run's model).
    Lattice,
    /// The lifting line with Morgan's lifting-surface factors (its sections give the radial
    /// loading and the cavitation margins with either method).
    Line,
}

// The command line of `aes-sim propeller`.
#[derive(clap::Args)]
pub struct Args {
    /// A blade table, CSV with the header r_R,c_D,P_D,f0_c,t0_c,skew_deg,rake_D (`-` for standard
    /// input), or a scenario (`preset:NAME` or FILE.json): its `propeller.geometry` (the ship's
    /// B-series equivalent without one) at its diameter, in sea water.
    input: String,
    /// Number of blades Z of a blade table.
    #[arg(long)]
    blades: Option<u32>,
    /// Hub diameter over propeller diameter of a blade table.
    #[arg(long = "hub-ratio")]
    hub_ratio: Option<f64>,
    /// Override one parameter of a scenario (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    sets: Vec<String>,
    /// Propeller diameter [m] (default: a table's DTMB 4119 model, 1 ft; a scenario's own).
    #[arg(long = "diameter-m")]
    diameter_m: Option<f64>,
    /// Shaft speed [rpm], for the Reynolds numbers and the cavitation numbers (default: a table's
    /// 600, DTMB 4119's 10 rev/s test; a scenario's calm-water rpm at its fastest ordered speed).
    #[arg(long)]
    rpm: Option<f64>,
    /// The water of a blade table (a scenario's is the sea).
    #[arg(long, value_enum, default_value = "fresh")]
    water: WaterKind,
    /// Advance ratios FROM:TO:N (N points, ends included).
    #[arg(long, default_value = "0:1.2:25", value_name = "FROM:TO:N")]
    j: String,
    /// Also the radial circulation and section loading at this advance ratio (and the
    /// cavitation margins there only).
    #[arg(long = "at-j")]
    at_j: Option<f64>,
    /// Hub depth below the calm surface [m] for the cavitation margins (the blade at 12 o'clock);
    /// a blade table's margins are given only with it; a scenario's default is its calm-water hub
    /// depth.
    #[arg(long = "depth-m")]
    depth_m: Option<f64>,
    /// Markdown tables instead of JSON.
    #[arg(long)]
    markdown: bool,
    /// The open-water analysis: `lattice` (the vortex lattice, the run's model) or `line` (the
    /// lifting line, high at heavy loading). The radial loading and the cavitation margins are the
    /// lifting line's sections' with either.
    #[arg(long, value_enum, default_value = "lattice")]
    method: Method,
}

/// The advance ratios of `--j FROM:TO:N`.
fn advance_ratios(text: &str) -> Result<Vec<f64>, String> {
    let bad = || format!("--j '{}': expected FROM:TO:N, e.g. 0:1.2:25", shorten(text));
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

/// Refuses a flag's value outside `lo..=hi`, naming the flag, the value and the range.
fn within(flag: &str, v: f64, lo: f64, hi: f64, why: &str) -> Result<f64, String> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(format!("{flag}: {} is outside {lo}..={hi}{why}", shorten(&v.to_string())))
    }
}

/// What the command analyses: the blades, the flow, the hub depth of the margins, and for a
/// scenario its calm-water inception.
struct Subject {
    geometry: BladeGeometry,
    flow: Flow,
    depth_m: Option<f64>,
    scenario: Option<ScenarioPart>,
}

/// A scenario's own part of the output.
struct ScenarioPart {
    name: String,
    geometry: String,
    /// The calm point the default shaft speed came from (None: `--rpm` given).
    rpm_from: Option<pc::CalmPoint>,
    inception: Option<pc::Inception>,
}

fn is_scenario(input: &str) -> bool {
    input.starts_with("preset:") || input.to_ascii_lowercase().ends_with(".json")
}

/// A blade table's subject.
fn table(a: &Args) -> Result<Subject, String> {
    let text = read_bounded(&a.input, MAX_CSV_BYTES as u64, "a blade table")?;
    if !a.sets.is_empty() {
        return Err("--set: a blade table has no scenario to set (give preset:NAME or FILE.json)".into());
    }
    let blades = a.blades.ok_or("--blades: a blade table needs its number of blades (2..=7)")?;
    let hub = a.hub_ratio.ok_or("--hub-ratio: a blade table needs its hub ratio (0.05..=0.5)")?;
    let g = BladeGeometry::from_csv(&text, blades, hub)?;
    let d = a.diameter_m.unwrap_or(0.3048);
    let n = within("--rpm", a.rpm.unwrap_or(600.0), 6.0, 12000.0, "")? / 60.0;
    let flow = match a.water {
        WaterKind::Fresh => Flow::fresh_water(d, n),
        WaterKind::Sea => Flow::sea_water(d, n),
    };
    flow.check().map_err(|e| format!("--{}", e.replace("diameter_m", "diameter-m")))?;
    Ok(Subject { geometry: g, flow, depth_m: a.depth_m, scenario: None })
}

/// A scenario's subject: its geometry (the B-series equivalent without one) on the geometry model.
fn scenario(a: &Args) -> Result<Subject, String> {
    for (flag, given) in [("--blades", a.blades.is_some()), ("--hub-ratio", a.hub_ratio.is_some())] {
        if given {
            return Err(format!("{flag}: a scenario's geometry has its own (propeller.geometry)"));
        }
    }
    if a.water != WaterKind::Fresh {
        return Err("--water: a scenario's propeller works in the sea (ship.water_density_kg_m3)".into());
    }
    let mut sc = load(&a.input, &a.sets)?;
    if let Some(d) = a.diameter_m {
        sc.propeller.diameter_m = within("--diameter-m", d, 0.1, 15.0, " (propeller.diameter_m's range)")?;
    }
    let spec = sc.propeller.geometry.clone().unwrap_or_default();
    sc.propeller.model = aes_core::scenario::PropellerModelKind::Geometry;
    sc.propeller.geometry = Some(spec.clone());
    sc.validate().map_err(|e| e.to_string())?;
    let plant = aes_core::sim::plant::Plant::new(&sc)?;
    let g = pc::blades(&sc)?.ok_or("the scenario has no propeller geometry")?;
    let depth = match a.depth_m {
        Some(h) => h,
        None => sc.ship_hull()?.hub_depth_m,
    };
    let (n, rpm_from) = match a.rpm {
        Some(rpm) => (within("--rpm", rpm, 6.0, 12000.0, "")? / 60.0, None),
        None => {
            let u = pc::fastest_order_kn(&sc);
            if u <= 0.0 {
                return Err(format!("--rpm: {} never orders a speed ahead; give the shaft speed", shorten(&a.input)));
            }
            let p = pc::calm_point(&plant, u);
            (p.rev_per_s, Some(p))
        }
    };
    let flow = Flow::sea_water(sc.propeller.diameter_m, n);
    flow.check().map_err(|e| format!("--rpm: the shaft speed's {e}"))?;
    if a.depth_m.is_none() && depth < 0.5 * flow.diameter_m {
        return Err(format!(
            "the scenario's calm-water hub depth {depth:.2} m (ship.hull) is less than the propeller's radius {} m: the \
             blade at 12 o'clock would be out of the water; give --depth-m",
            0.5 * flow.diameter_m
        ));
    }
    check_depth(depth, flow.diameter_m)?;
    let inception = pc::calm_inception(&g, sc.propeller.diameter_m, &plant, depth)?;
    Ok(Subject {
        geometry: g,
        flow,
        depth_m: Some(depth),
        scenario: Some(ScenarioPart { name: sc.name.clone(), geometry: spec.name, rpm_from, inception }),
    })
}

/// The hub must be deep enough for the blade at 12 o'clock to be under water.
fn check_depth(depth_m: f64, diameter_m: f64) -> Result<(), String> {
    let r = 0.5 * diameter_m;
    within(
        "--depth-m",
        depth_m,
        r,
        1000.0,
        &format!(" (from the propeller's radius, {r} m: the blade at 12 o'clock under water)"),
    )
    .map(|_| ())
}

/// One open-water point's cavitation as JSON.
fn point_json(c: &PointCavitation) -> serde_json::Value {
    let sections: Vec<_> = c
        .sections
        .iter()
        .map(|s| {
            serde_json::json!({
                "r_r": s.r_r,
                "sigma": s.sigma,
                "minus_cp_min_back": s.min_cp.suction,
                "minus_cp_min_face": s.min_cp.pressure,
                "margin": s.margin,
                "cavitates": s.cavitates(),
                "sectioned": s.sectioned,
                "bucket_deg": s.bucket_rad.map(|(lo, hi)| [lo.to_degrees(), hi.to_degrees()]),
            })
        })
        .collect();
    serde_json::json!({
        "j": c.j,
        "cavitating_r_r": c.cavitating_r_r,
        "worst_margin": c.worst_margin,
        "onset_h_over_r": c.onset_h_over_r,
        "sections": sections,
    })
}

fn inception_json(i: &Option<pc::Inception>) -> serde_json::Value {
    i.map_or(serde_json::Value::Null, |i| serde_json::to_value(i).unwrap_or(serde_json::Value::Null))
}

/// One open-water row of either method.
struct Row {
    j: f64,
    kt: f64,
    kq: f64,
    eta: f64,
    converged: bool,
    /// The lattice's aligned wake pitch over R (the lifting line's varies with radius).
    wake_pitch: Option<f64>,
}

/// What the open-water rows are, by method.
fn model_text(m: Method) -> &'static str {
    match m {
        Method::Lattice => {
            "vortex lattice (6 x 12 horseshoes on the nose-tail helicoid, aligned helical wake, hub image, \
             leading-edge suction turned normal by Polhamus's analogy; no lifting-surface factors, no thickness), \
             the run's model: docs/propeller.md"
        }
        Method::Line => {
            "lifting line (Wrench induction, hub image, Morgan, Silovic & Denny 1968 lifting-surface corrections)"
        }
    }
}

pub fn run(a: Args) -> Result<(), Failure> {
    let s = if is_scenario(&a.input) { scenario(&a)? } else { table(&a)? };
    let (g, flow) = (&s.geometry, s.flow);
    let js = advance_ratios(&a.j)?;
    if let Some(h) = a.depth_m {
        check_depth(h, flow.diameter_m)?;
    }
    // The lifting line's sections carry the radial loading and the cavitation margins.
    let line = blade::open_water(g, &js, &flow)?;
    let rows: Vec<Row> = match a.method {
        Method::Line => line
            .iter()
            .map(|p| Row { j: p.j, kt: p.kt, kq: p.kq, eta: p.eta, converged: p.converged, wake_pitch: None })
            .collect(),
        Method::Lattice => blade::vortex_lattice::open_water(g, &js, &flow)?
            .into_iter()
            .map(|p| Row {
                j: p.j,
                kt: p.kt,
                kq: p.kq,
                eta: p.eta,
                converged: p.converged,
                wake_pitch: Some(p.wake_pitch),
            })
            .collect(),
    };
    let at = a.at_j.map(|j| blade::analyse(g, j, &flow).map_err(|e| format!("--at-j: {e}"))).transpose()?;
    // The cavitation margins: only when a depth is given (the sections' buckets cost a panel
    // solution each), at --at-j or else at every J of the curve.
    let cavitation: Option<Vec<PointCavitation>> = match s.depth_m {
        None => None,
        Some(h) => {
            let b = PropellerBuckets::cached(g, flow.diameter_m)?;
            let w = Water::of(&flow);
            let points: Vec<&Analysis> = match &at {
                Some(p) => vec![p],
                None => line.iter().collect(),
            };
            Some(points.into_iter().map(|p| check_point(&b, &w, p, flow.rev_per_s, h)).collect())
        }
    };
    if a.markdown {
        return emit(markdown(&s, &rows, at.as_ref(), cavitation.as_deref()).trim_end());
    }
    let rows: Vec<_> = rows
        .iter()
        .map(|p| {
            let mut r = serde_json::json!({"j": p.j, "kt": p.kt, "kq": p.kq, "eta": p.eta, "converged": p.converged});
            if let Some(w) = p.wake_pitch {
                r["wake_pitch"] = w.into();
            }
            r
        })
        .collect();
    let mut out = serde_json::json!({
        "model": model_text(a.method),
        "blades": g.blades,
        "hub_ratio": g.hub_ratio,
        "flow": flow,
        "open_water": rows,
        "cavitation": cavitation.as_ref().map(|c| serde_json::json!({
            "hub_depth_m": s.depth_m,
            "rev_per_s": flow.rev_per_s,
            "note": "blade at 12 o'clock; steady 2D sections (panel method) on the lifting line's loads; \
                     sectioned = inside the outermost row with a chord (outboard, the tip vortex is not predicted)",
            "points": c.iter().map(point_json).collect::<Vec<_>>(),
        })),
    });
    if let Some(sp) = &s.scenario {
        out["scenario"] = serde_json::json!({
            "name": sp.name,
            "geometry": sp.geometry,
            "rpm_from": sp.rpm_from,
            "calm_inception": inception_json(&sp.inception),
        });
    }
    if let Some(p) = at {
        out["at_j"] = serde_json::to_value(p).map_err(|e| e.to_string())?;
        out["at_j_model"] = model_text(Method::Line).into();
    }
    emit_json(&out)
}

/// The `--markdown` tables.
fn markdown(s: &Subject, rows: &[Row], at: Option<&Analysis>, cav: Option<&[PointCavitation]>) -> String {
    let mut out = String::from("| J | KT | 10KQ | eta | wake pitch | converged |\n|---|---|---|---|---|---|\n");
    for p in rows {
        let w = p.wake_pitch.map_or("-".to_string(), |w| format!("{w:.4}"));
        out += &format!("| {:.3} | {:.4} | {:.4} | {:.3} | {w} | {} |\n", p.j, p.kt, 10.0 * p.kq, p.eta, p.converged);
    }
    if let Some(p) = at {
        out += &format!(
            "\nAt J = {} by the lifting line: KT {:.4}, 10KQ {:.4}\n\n| r/R | chord [m] | G | beta_i [deg] | alpha [deg] | V* [m/s] | CL | CD | Re |\n|---|---|---|---|---|---|---|---|---|\n",
            p.j,
            p.kt,
            10.0 * p.kq
        );
        for x in &p.sections {
            out += &format!(
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
    if let Some(points) = cav {
        out += &format!(
            "\nCavitation with the hub {:.2} m deep at {:.2} rev/s, the blade at 12 o'clock (steady 2D sections; the \
             tip's points, outboard of the last row with a chord, are marked tip and not counted):\n\n\
             | J | worst margin | onset h/R | cavitating r/R |\n|---|---|---|---|\n",
            s.depth_m.unwrap_or(f64::NAN),
            s.flow.rev_per_s
        );
        for c in points {
            let radii: Vec<String> = c.cavitating_r_r.iter().map(|r| format!("{r:.3}")).collect();
            out += &format!(
                "| {:.3} | {:+.3} | {:.2} | {} |\n",
                c.j,
                c.worst_margin,
                c.onset_h_over_r,
                if radii.is_empty() { "none".to_string() } else { radii.join(", ") }
            );
        }
        if let [c] = points {
            out += &format!(
                "\nAt J = {:.3}:\n\n| r/R | sigma | -Cp_min back | -Cp_min face | margin | cavitates | bucket [deg] |\n|---|---|---|---|---|---|---|\n",
                c.j
            );
            for x in &c.sections {
                let bucket = x
                    .bucket_rad
                    .map_or("none".to_string(), |(lo, hi)| format!("{:.1} to {:.1}", lo.to_degrees(), hi.to_degrees()));
                out += &format!(
                    "| {:.3}{} | {:.3} | {:.3} | {:.3} | {:+.3} | {} | {bucket} |\n",
                    x.r_r,
                    if x.sectioned { "" } else { " (tip)" },
                    x.sigma,
                    x.min_cp.suction,
                    x.min_cp.pressure,
                    x.margin,
                    if x.cavitates() { "yes" } else { "no" }
                );
            }
        }
    }
    if let Some(sp) = &s.scenario {
        out += &format!("\nScenario {} (propeller.geometry \"{}\")", sp.name, sp.geometry);
        if let Some(p) = &sp.rpm_from {
            out += &format!(": shaft speed from the calm-water self-propulsion at {}", pc::describe(p));
        }
        out += &match &sp.inception {
            Some(i) => format!(
                ".\nCalm-water cavitation inception: {} with the hub {:.2} m deep, first at r/R {}.\n",
                pc::describe(&i.at),
                i.hub_depth_m,
                i.first_r_r.map_or("-".into(), |r| format!("{r:.3}"))
            ),
            None => ".\nCalm-water cavitation inception: no section cavitates up to 40 kn.\n".into(),
        };
    }
    out
}
