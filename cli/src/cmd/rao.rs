//! `aes-sim rao`: RAOs and mean drift forces of a hull (ch. 2.5.2-2.5.3).

use crate::common::{emit_json, load, read_bounded, Failure};
use aes_core::sea::seakeeping::tables::rao_json;

// The command line of `aes-sim rao`.
#[derive(clap::Args)]
pub struct Args {
    /// The hull: an embedded one by name (dtmb5415, wigley) or an offsets CSV file (the long
    /// format of dtmb5415_offsets.csv). Default: the hull of --scenario, else the DTMB 5415.
    #[arg(long)]
    hull: Option<String>,
    /// Take the hull and its loading from this scenario's `ship.hull` (file, `-` or
    /// `preset:NAME`), and its `seakeeping.aft_end_terms` and `short_wave_force`: the RAOs its runs use.
    #[arg(long)]
    scenario: Option<String>,
    /// Waterline above the baseline [m] (default: the hull's design draft).
    #[arg(long)]
    draft: Option<f64>,
    /// Displaced mass [kg], instead of --draft: the draft is solved for it.
    #[arg(long)]
    mass: Option<f64>,
    /// Centre of gravity above the baseline [m] (needed for an offsets file).
    #[arg(long)]
    kg: Option<f64>,
    /// Radii of gyration [m]: roll, pitch, yaw (defaults: the hull's; for an offsets file
    /// 0.37 B, 0.25 Lpp, 0.25 Lpp).
    #[arg(long)]
    kxx: Option<f64>,
    #[arg(long)]
    kyy: Option<f64>,
    #[arg(long)]
    kzz: Option<f64>,
    /// Ship speed [kn].
    #[arg(long = "speed-kn")]
    speed_kn: f64,
    /// Wave heading [deg]: 180 head seas, 90 waves from starboard, 0 following seas.
    #[arg(long = "heading-deg")]
    heading_deg: f64,
    /// Wave frequencies [rad/s], comma separated.
    #[arg(long, value_delimiter = ',', required = true)]
    omega: Vec<f64>,
    /// Wave amplitude at which the nonlinear roll damping is linearised [m].
    #[arg(long = "roll-wave-amplitude", default_value_t = 1.0)]
    roll_wave_amplitude: f64,
}

pub fn run(
    Args { hull, scenario, draft, mass, kg, kxx, kyy, kzz, speed_kn, heading_deg, omega, roll_wave_amplitude }: Args,
) -> Result<(), Failure> {
    if !(roll_wave_amplitude.is_finite() && (0.01..=20.0).contains(&roll_wave_amplitude)) {
        return Err(format!("--roll-wave-amplitude = {roll_wave_amplitude} is outside [0.01, 20]").into());
    }
    let (mut ship, aft_end_terms, short_wave) = match &scenario {
        Some(path) => {
            let sc = load(path, &[])?;
            (sc.ship, sc.seakeeping.aft_end_terms, sc.seakeeping.short_wave_force)
        }
        None => (aes_core::scenario::ShipParams::default(), true, Default::default()),
    };
    let spec = &mut ship.hull;
    if let Some(h) = &hull {
        if aes_core::ship::hull::HULL_NAMES.contains(&h.as_str()) && h != "custom" {
            *spec = aes_core::ship::hull::HullSpec { name: h.clone(), ..Default::default() };
        } else {
            let text = read_bounded(h, aes_core::ship::sections::MAX_HULL_BYTES as u64, "a hull offsets file")?;
            *spec = aes_core::ship::hull::HullSpec { name: "custom".into(), offsets_csv: text, ..Default::default() };
        }
    }
    if draft.is_some() || mass.is_some() {
        spec.draft_m = draft;
        spec.mass_kg = mass;
    }
    for (field, v) in [(&mut spec.kg_m, kg), (&mut spec.kxx_m, kxx), (&mut spec.kyy_m, kyy), (&mut spec.kzz_m, kzz)] {
        if v.is_some() {
            *field = v;
        }
    }
    // The hull section's own checks, with the flags' names for its fields.
    let mut v = aes_core::checks::Validator::new();
    v.section("hull", |v| ship.hull.validate(v, ship.water_density_kg_m3));
    v.finish().map_err(|e| {
        let e = e.to_string();
        format!(
            "{e}\n(--draft, --mass, --kg, --kxx, --kyy, --kzz set hull.draft_m, mass_kg, kg_m, kxx_m, kyy_m, kzz_m)"
        )
    })?;
    let resolved = ship.hull.resolve(ship.water_density_kg_m3).map_err(|(f, e)| format!("hull.{f}: {e}"))?;
    let mut strips = resolved.strip_ship()?;
    strips.aft_end_terms = aft_end_terms;
    strips.short_wave = short_wave;
    let v = rao_json(
        &strips,
        speed_kn * aes_core::numerics::units::KNOT_M_S,
        heading_deg.to_radians(),
        &omega,
        roll_wave_amplitude,
    )?;
    emit_json(&v)?;
    Ok(())
}
