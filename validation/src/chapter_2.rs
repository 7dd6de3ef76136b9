//! Chapter 2's sea states (Table 2.4): the Bretschneider parameters as printed and the spectrum's area.

use crate::rows::{calibrated, reference, row, thesis_f64};
use crate::{Kind, Section, Tolerance};

pub(crate) fn table_2_4() -> Result<Section, String> {
    let printed = [
        (2, "table_2_4.ss2.peak_frequency_rad_s", "table_2_4.ss2.significant_height_ft"),
        (3, "table_2_4.ss3.peak_frequency_rad_s", "table_2_4.ss3.significant_height_ft"),
        (4, "table_2_4.ss4.peak_frequency_rad_s", "table_2_4.ss4.significant_height_ft"),
        (5, "table_2_4.ss5.peak_frequency_rad_s", "table_2_4.ss5.significant_height_ft"),
        (6, "table_2_4.ss6.peak_frequency_rad_s", "table_2_4.ss6.significant_height_ft"),
    ];
    let mut rows = Vec::new();
    for (ss, w_key, h_key) in printed {
        let (w_ours, h_ours) = aes_core::sea::waves::sea_state(ss).ok_or("no sea state")?;
        rows.push(
            calibrated(
                &format!("SS{ss} peak frequency"),
                "Table 2.4",
                reference(w_key),
                w_ours,
                "rad/s",
                Tolerance::Abs(0.0),
                "copied",
            )
            .kind(Kind::Copied),
        );
        rows.push(
            calibrated(
                &format!("SS{ss} significant height"),
                "Table 2.4",
                reference(h_key),
                h_ours / 0.3048,
                "ft",
                Tolerance::Rel(1e-12),
                "copied (stored in metres)",
            )
            .kind(Kind::Copied),
        );
        // Eq. 2.58's zeroth moment is H^2/16 in closed form; the integral of our spectrum.
        let w = thesis_f64(w_key);
        let (lo, hi, n) = (0.05 * w, 20.0 * w, 20_000);
        let dw = (hi - lo) / n as f64;
        let m0: f64 =
            (0..n).map(|i| aes_core::sea::waves::bretschneider(lo + (i as f64 + 0.5) * dw, h_ours, w) * dw).sum();
        rows.push(
            row(
                &format!("SS{ss} spectral area m0 / (H^2/16)"),
                "eq. 2.58 (closed form)",
                1.0,
                m0 / (h_ours * h_ours / 16.0),
                "-",
                Tolerance::Abs(1e-4),
                "midpoint rule on 0.05 to 20 omega_n; the tails beyond hold under 1e-5",
            )
            .kind(Kind::Analytic),
        );
    }
    Ok(Section {
        finding: String::new(),
        title: "Table 2.4: Bretschneider sea states",
        note: String::new(),
        rows,
        figures: Vec::new(),
    })
}
