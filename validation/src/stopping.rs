//! The crash stop (full astern at once, `crash_stop`): the energy books through the shafts'
//! reversal, the energy the brake resistors burn beside the thesis' AC-braking figure (ch. 5.2.2,
//! a milder case), and the booklet's full-astern stopping test against IMO's 15 ship lengths.

use crate::rows::{reference, row, thesis_text};
use crate::runs::run;
use crate::{Kind, Row, Section, Tolerance};
use aes_core::scenario::presets::preset;

pub(crate) fn stopping() -> Result<Section, String> {
    let mut rows: Vec<Row> = Vec::new();
    let mut from = |kn: f64, name: &str| -> Result<aes_core::RunResult, String> {
        let mut sc = preset(name).ok_or("no preset")?;
        sc.initial.speed_kn = kn;
        sc.commands[0].speed_kn = Some(kn);
        let r = run(&sc)?;
        rows.push(
            row(
                &format!("energy books through a crash stop from {kn} kn ({name}): residual / turbine work"),
                "conservation",
                0.0,
                r.summary.energy_j.relative_residual,
                "-",
                Tolerance::Abs(1e-9),
                "propeller to shaft to motor (regenerating) to inverter to bus to brake resistors and storage, \
                 turbines unloading: RK4 at 0.5 ms closes the books through the reversal as runs ahead do at 1 ms",
            )
            .kind(Kind::Analytic),
        );
        Ok(r)
    };
    let c25 = from(25.0, "crash-stop")?;
    from(30.0, "crash-stop")?;
    let s25 = from(25.0, "crash-stop-storage")?;
    let e_text = thesis_text("ch_5_2_2.brake_energy_per_plant_mj");
    for (r, what) in [(&c25, "brake resistors only"), (&s25, "with a 150 MJ battery on each bus")] {
        let e = &r.summary.energy_j;
        rows.push(
            row(
                &format!("energy the brake resistors burn per plant in a crash stop from 25 kn, {what}"),
                &format!("ch. 5.2.2 text (\"about {e_text} MJ\" in AC braking, no reversal)"),
                reference("ch_5_2_2.brake_energy_per_plant_mj"),
                e.brake / 2.0 / 1e6,
                "MJ",
                Tolerance::Abs(0.0),
                &format!(
                    "another case: full astern drives the shafts through zero and keeps braking until the ship is \
                     dead in the water, where the thesis' AC braking only lets the propellers windmill. Over the \
                     run (300 s: the stop and astern) the motors returned {:.0} MJ, the storages took {:.0} MJ and \
                     the resistors burnt {:.0} MJ in all: what the motors did not return came from the generators \
                     while the turbines unloaded",
                    e.regenerated / 1e6,
                    (-e.storage_to_bus).max(0.0) / 1e6,
                    e.brake / 1e6
                ),
            )
            .shown(Kind::Context),
        );
    }
    let b = aes_core::studies::maneuvers::booklet(&preset("turn-360").ok_or("no preset")?)?;
    let stop_note = match &b.stopping {
        Some(st) => format!(
            "The booklet's full-astern stopping test (`aes-sim maneuvers`, from {:.0} kn with the whole drive \
             train) gives a track reach of {:.2} ship lengths ({:.0} m), a head reach of {:.0} m and a lateral \
             deviation of {:.1} m, dead in the water {:.0} s after the order, the bus peaking at {:.3} pu and the \
             resistors burning {:.0} MJ: within IMO's 15 L (MSC.137(76), for merchant ships; the thesis' ship is a \
             naval destroyer, so a reference).",
            st.approach_kn,
            st.track_reach_l,
            st.track_reach_m,
            st.head_reach_m,
            st.lateral_deviation_m,
            st.time_to_dead_s,
            st.peak_bus_voltage_pu,
            st.brake_energy_j / 1e6
        ),
        None => format!("The booklet's stopping test was refused: {}", b.stopping_refused.unwrap_or_default()),
    };
    let note = format!(
        "{stop_note} No crash-stop trial of a ship of this size with a public source was found to compare with, so \
         none is claimed. The thesis' AC-braking case (ch. 5.2.2, the ac-braking preset) orders no reversal: its \
         rows in Chapter 5 above are the run as before the astern orders (its golden record is checked bit for bit)."
    );
    Ok(Section {
        title: "The crash stop: energy through the reversal",
        note,
        rows,
        figures: Vec::new(),
        finding: String::new(),
    })
}
