//! Line plots as SVG text, for the validation report's figures (docs/validation/*.svg): a pure
//! function of the data, no I/O (the CLI writes the files). One or more panels stacked over a
//! shared x axis, each with its own y axis; solid, dashed (a reference: the thesis' number, a
//! limit) or marker series; ticks at 1-2-5 steps; a legend beside each panel, outside the data.
//!
//! Deterministic: every number is written with a fixed number of decimals and every computation
//! goes through IEEE arithmetic or libm, so a figure is byte-identical on every platform and
//! `aes-sim validate --check` can compare it with the committed file. Axis labels must carry a
//! unit in square brackets (`time [s]`, `h/R [-]`): [`svg`] refuses a label without one.

use std::fmt::Write;

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    Solid,
    /// A reference (the thesis' value, a limit, the as-printed run).
    Dashed,
    /// Points only (a published or sampled set).
    Markers,
}

/// One named set of (x, y) points. Non-finite points are skipped (they break a line).
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    pub style: Style,
    /// Index into the palette.
    pub color: usize,
}

impl Series {
    pub fn line(name: &str, color: usize, points: Vec<(f64, f64)>) -> Series {
        Series { name: name.into(), points, style: Style::Solid, color }
    }

    pub fn dashed(name: &str, color: usize, points: Vec<(f64, f64)>) -> Series {
        Series { style: Style::Dashed, ..Series::line(name, color, points) }
    }

    pub fn markers(name: &str, color: usize, points: Vec<(f64, f64)>) -> Series {
        Series { style: Style::Markers, ..Series::line(name, color, points) }
    }

    /// A horizontal reference line at `y` from `x0` to `x1`.
    pub fn level(name: &str, color: usize, y: f64, x0: f64, x1: f64) -> Series {
        Series::dashed(name, color, vec![(x0, y), (x1, y)])
    }

    /// A series from two columns of equal length.
    pub fn from_columns(name: &str, color: usize, x: &[f64], y: &[f64]) -> Series {
        Series::line(name, color, x.iter().copied().zip(y.iter().copied()).collect())
    }
}

/// One y axis and its series.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// With its unit in square brackets.
    pub y_label: String,
    pub series: Vec<Series>,
    /// Fixed limits; None: from the data, widened to whole ticks.
    pub y_range: Option<(f64, f64)>,
}

impl Panel {
    pub fn new(y_label: &str, series: Vec<Series>) -> Panel {
        Panel { y_label: y_label.into(), series, y_range: None }
    }

    pub fn with_range(self, lo: f64, hi: f64) -> Panel {
        Panel { y_range: Some((lo, hi)), ..self }
    }
}

/// A figure: panels stacked over one x axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Plot {
    pub title: String,
    /// With its unit in square brackets.
    pub x_label: String,
    pub x_range: Option<(f64, f64)>,
    pub panels: Vec<Panel>,
}

/// Colours: blue, orange, green, red, purple, grey (distinguishable in colour-blind palettes).
const PALETTE: [&str; 6] = ["#1f77b4", "#e6550d", "#2ca02c", "#c0392b", "#7b4fa0", "#555555"];

const WIDTH: f64 = 860.0;
const LEFT: f64 = 78.0;
const PLOT_W: f64 = 560.0;
const PANEL_H: f64 = 160.0;
const PANEL_GAP: f64 = 28.0;
const TOP: f64 = 44.0;
const BOTTOM: f64 = 56.0;
const LEGEND_X: f64 = LEFT + PLOT_W + 16.0;
/// Most points drawn per series: longer ones keep each bucket's minimum and maximum.
const MAX_POINTS: usize = 1200;

/// Whether a label carries a unit: a non-empty `[...]` at its end.
pub fn has_unit(label: &str) -> bool {
    let l = label.trim_end();
    l.ends_with(']') && l.rfind('[').is_some_and(|i| i + 2 < l.len())
}

/// The SVG text of a plot; an error for a label without a unit, no panels, or an empty or
/// non-finite fixed range.
pub fn svg(p: &Plot) -> Result<String, String> {
    if p.panels.is_empty() {
        return Err(format!("plot '{}': no panels", p.title));
    }
    for l in std::iter::once(&p.x_label).chain(p.panels.iter().map(|q| &q.y_label)) {
        if !has_unit(l) {
            return Err(format!("plot '{}': axis label '{l}' has no unit in [brackets]", p.title));
        }
    }
    let all_x = p.panels.iter().flat_map(|q| &q.series).flat_map(|s| s.points.iter().map(|&(x, _)| x));
    let (x0, x1) = match p.x_range {
        Some(r) => checked_range(r, &p.title)?,
        None => nice_range(data_range(all_x)),
    };
    let n = p.panels.len() as f64;
    let height = TOP + n * PANEL_H + (n - 1.0) * PANEL_GAP + BOTTOM;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{WIDTH:.0}\" height=\"{height:.0}\" \
         viewBox=\"0 0 {WIDTH:.0} {height:.0}\" font-family=\"Helvetica, Arial, sans-serif\" font-size=\"12\">"
    );
    let _ = writeln!(s, "<rect x=\"0\" y=\"0\" width=\"{WIDTH:.0}\" height=\"{height:.0}\" fill=\"#ffffff\"/>");
    let _ = writeln!(
        s,
        "<text x=\"{:.1}\" y=\"24\" text-anchor=\"middle\" font-size=\"15\" font-weight=\"bold\">{}</text>",
        LEFT + PLOT_W / 2.0,
        esc(&p.title)
    );
    let xt = ticks(x0, x1);
    let xdec = decimals(&xt);
    for (i, panel) in p.panels.iter().enumerate() {
        let top = TOP + i as f64 * (PANEL_H + PANEL_GAP);
        let ys = panel.series.iter().flat_map(|s| s.points.iter().map(|&(_, y)| y));
        let (y0, y1) = match panel.y_range {
            Some(r) => checked_range(r, &p.title)?,
            None => nice_range(data_range(ys)),
        };
        let fx = |x: f64| LEFT + (x - x0) / (x1 - x0) * PLOT_W;
        let fy = |y: f64| top + PANEL_H - (y - y0) / (y1 - y0) * PANEL_H;
        // Grid and ticks.
        let yt = ticks(y0, y1);
        let ydec = decimals(&yt);
        s.push_str("<g stroke=\"#dddddd\" stroke-width=\"1\">\n");
        for &x in &xt {
            let _ = writeln!(
                s,
                "<line x1=\"{0:.2}\" y1=\"{1:.2}\" x2=\"{0:.2}\" y2=\"{2:.2}\"/>",
                fx(x),
                top,
                top + PANEL_H
            );
        }
        for &y in &yt {
            let _ = writeln!(
                s,
                "<line x1=\"{0:.2}\" y1=\"{1:.2}\" x2=\"{2:.2}\" y2=\"{1:.2}\"/>",
                LEFT,
                fy(y),
                LEFT + PLOT_W
            );
        }
        s.push_str("</g>\n");
        let _ = writeln!(
            s,
            "<rect x=\"{LEFT:.2}\" y=\"{top:.2}\" width=\"{PLOT_W:.2}\" height=\"{PANEL_H:.2}\" fill=\"none\" stroke=\"#000000\"/>"
        );
        for &y in &yt {
            let _ = writeln!(
                s,
                "<text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\">{}</text>",
                LEFT - 6.0,
                fy(y) + 4.0,
                tick_label(y, ydec)
            );
        }
        let last = i + 1 == p.panels.len();
        for &x in &xt {
            let _ = writeln!(
                s,
                "<line x1=\"{0:.2}\" y1=\"{1:.2}\" x2=\"{0:.2}\" y2=\"{2:.2}\" stroke=\"#000000\"/>",
                fx(x),
                top + PANEL_H,
                top + PANEL_H + 4.0
            );
            if last {
                let _ = writeln!(
                    s,
                    "<text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"middle\">{}</text>",
                    fx(x),
                    top + PANEL_H + 18.0,
                    tick_label(x, xdec)
                );
            }
        }
        // The y label, turned, centred on the panel.
        let (lx, ly) = (16.0, top + PANEL_H / 2.0);
        let _ = writeln!(
            s,
            "<text x=\"{lx:.2}\" y=\"{ly:.2}\" text-anchor=\"middle\" transform=\"rotate(-90 {lx:.2} {ly:.2})\">{}</text>",
            esc(&panel.y_label)
        );
        // The data, clipped to the panel.
        let _ = writeln!(
            s,
            "<clipPath id=\"c{i}\"><rect x=\"{LEFT:.2}\" y=\"{top:.2}\" width=\"{PLOT_W:.2}\" height=\"{PANEL_H:.2}\"/></clipPath>"
        );
        let _ = writeln!(s, "<g clip-path=\"url(#c{i})\" fill=\"none\" stroke-width=\"1.6\">");
        for ser in &panel.series {
            let color = PALETTE[ser.color % PALETTE.len()];
            let pts = thin(&ser.points);
            match ser.style {
                Style::Markers => {
                    for &(x, y) in pts.iter().filter(|(x, y)| x.is_finite() && y.is_finite()) {
                        let _ = writeln!(
                            s,
                            "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"3\" fill=\"{color}\" stroke=\"none\"/>",
                            fx(x),
                            fy(y)
                        );
                    }
                }
                Style::Solid | Style::Dashed => {
                    let dash = if ser.style == Style::Dashed { " stroke-dasharray=\"7 4\"" } else { "" };
                    for run in pts.split(|(x, y)| !(x.is_finite() && y.is_finite())).filter(|r| r.len() > 1) {
                        s.push_str("<polyline points=\"");
                        for (k, &(x, y)) in run.iter().enumerate() {
                            let _ = write!(s, "{}{:.2},{:.2}", if k == 0 { "" } else { " " }, fx(x), fy(y));
                        }
                        let _ = writeln!(s, "\" stroke=\"{color}\"{dash}/>");
                    }
                }
            }
        }
        s.push_str("</g>\n");
        // The legend, beside the panel.
        for (k, ser) in panel.series.iter().enumerate() {
            let color = PALETTE[ser.color % PALETTE.len()];
            let y = top + 14.0 + 18.0 * k as f64;
            match ser.style {
                Style::Markers => {
                    let _ = writeln!(
                        s,
                        "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"3\" fill=\"{color}\"/>",
                        LEGEND_X + 12.0,
                        y - 4.0
                    );
                }
                Style::Solid | Style::Dashed => {
                    let dash = if ser.style == Style::Dashed { " stroke-dasharray=\"7 4\"" } else { "" };
                    let _ = writeln!(
                        s,
                        "<line x1=\"{0:.2}\" y1=\"{1:.2}\" x2=\"{2:.2}\" y2=\"{1:.2}\" stroke=\"{color}\" stroke-width=\"1.6\"{dash}/>",
                        LEGEND_X,
                        y - 4.0,
                        LEGEND_X + 24.0
                    );
                }
            }
            let _ = writeln!(s, "<text x=\"{:.2}\" y=\"{y:.2}\">{}</text>", LEGEND_X + 30.0, esc(&ser.name));
        }
    }
    let _ = writeln!(
        s,
        "<text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"middle\">{}</text>",
        LEFT + PLOT_W / 2.0,
        height - 14.0,
        esc(&p.x_label)
    );
    s.push_str("</svg>\n");
    Ok(s)
}

fn checked_range((a, b): (f64, f64), title: &str) -> Result<(f64, f64), String> {
    if a.is_finite() && b.is_finite() && b > a {
        Ok((a, b))
    } else {
        Err(format!("plot '{title}': axis range {a} to {b} is empty or not finite"))
    }
}

/// The finite data's extent with a 4 % margin; (0, 1) for none, widened around a constant.
fn data_range(v: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) =
        v.filter(|x| x.is_finite()).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
    if lo > hi {
        (0.0, 1.0)
    } else if hi - lo <= 1e-12 * lo.abs().max(1.0) {
        let d = 0.5 * lo.abs().max(1.0);
        (lo - d, hi + d)
    } else {
        // A margin, so that a level at the data's edge is not hidden by the frame.
        let m = 0.04 * (hi - lo);
        (lo - m, hi + m)
    }
}

/// A 1-2-5 tick step giving about five intervals over `span`.
fn step(span: f64) -> f64 {
    let raw = span / 5.0;
    let mag = libm::pow(10.0, libm::floor(libm::log10(raw)));
    let f = raw / mag;
    mag * if f < 1.5 {
        1.0
    } else if f < 3.5 {
        2.0
    } else if f < 7.5 {
        5.0
    } else {
        10.0
    }
}

/// The range widened out to whole steps.
fn nice_range((lo, hi): (f64, f64)) -> (f64, f64) {
    let d = step(hi - lo);
    (libm::floor(lo / d + 1e-9) * d, libm::ceil(hi / d - 1e-9) * d)
}

/// Ticks at whole steps inside [lo, hi].
fn ticks(lo: f64, hi: f64) -> Vec<f64> {
    let d = step(hi - lo);
    let first = libm::ceil(lo / d - 1e-9);
    (0..).map(|k| (first + k as f64) * d).take_while(|&t| t <= hi + 1e-9 * d).take(50).collect()
}

/// Decimals enough to tell the ticks apart.
fn decimals(t: &[f64]) -> usize {
    let d = if t.len() > 1 { t[1] - t[0] } else { 1.0 };
    let mut n = 0;
    while n < 6 && (d * libm::pow(10.0, n as f64) - libm::round(d * libm::pow(10.0, n as f64))).abs() > 1e-6 {
        n += 1;
    }
    n
}

fn tick_label(x: f64, dec: usize) -> String {
    let s = format!("{x:.dec$}");
    // No "-0".
    if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

/// At most MAX_POINTS points: each bucket keeps its minimum and maximum in y, in order.
fn thin(p: &[(f64, f64)]) -> Vec<(f64, f64)> {
    if p.len() <= MAX_POINTS {
        return p.to_vec();
    }
    let buckets = MAX_POINTS / 2;
    let mut out = Vec::with_capacity(MAX_POINTS + 2);
    for b in 0..buckets {
        let (i0, i1) = (b * p.len() / buckets, (b + 1) * p.len() / buckets);
        let chunk = &p[i0..i1];
        let finite = || chunk.iter().enumerate().filter(|(_, q)| q.0.is_finite() && q.1.is_finite());
        let lo = finite().min_by(|a, b| a.1 .1.total_cmp(&b.1 .1));
        let hi = finite().max_by(|a, b| a.1 .1.total_cmp(&b.1 .1));
        match (lo, hi) {
            (Some((a, &pa)), Some((b, &pb))) if a < b => out.extend([pa, pb]),
            (Some((a, &pa)), Some((b, &pb))) if a > b => out.extend([pb, pa]),
            (Some((_, &pa)), _) => out.push(pa),
            _ => out.push((f64::NAN, f64::NAN)),
        }
    }
    out
}

fn esc(t: &str) -> String {
    t.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// Checks of an SVG text without a parser: every tag closed in order, no NaN or infinity, every
/// number finite. Used by the tests here and by the validation report's own test.
pub fn check_well_formed(svg: &str) -> Result<(), String> {
    // A NaN or infinity printed anywhere, as a word of its own (text or attribute).
    for w in svg.split(|c: char| c.is_whitespace() || "<>\"=,;()".contains(c)) {
        if w.parse::<f64>().is_ok_and(|x| !x.is_finite()) {
            return Err(format!("contains '{w}'"));
        }
    }
    let mut stack: Vec<&str> = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find('<') {
        let after = &rest[i + 1..];
        let j = after.find('>').ok_or("a tag is not closed by '>'")?;
        let tag = &after[..j];
        if tag.contains('<') {
            return Err(format!("'<' inside the tag '{tag}'"));
        }
        if let Some(name) = tag.strip_prefix('/') {
            match stack.pop() {
                Some(open) if open == name.trim() => {}
                other => return Err(format!("</{name}> closes {other:?}")),
            }
        } else if !tag.ends_with('/') {
            let name = tag.split_whitespace().next().ok_or("an empty tag")?;
            stack.push(name);
        }
        // Attribute values: quoted, and numbers among them finite.
        if tag.matches('"').count() % 2 != 0 {
            return Err(format!("unbalanced quotes in '{tag}'"));
        }
        for v in tag.split('"').skip(1).step_by(2) {
            for w in v.split([' ', ',']).filter(|w| !w.is_empty()) {
                if w.parse::<f64>().is_ok_and(|x| !x.is_finite()) {
                    return Err(format!("non-finite number '{w}'"));
                }
            }
        }
        rest = &after[j + 1..];
    }
    if !stack.is_empty() {
        return Err(format!("unclosed tags: {stack:?}"));
    }
    if !svg.trim_start().starts_with("<svg") || !svg.trim_end().ends_with("</svg>") {
        return Err("not one <svg> element".into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Plot {
        let t: Vec<f64> = (0..3000).map(|i| i as f64 * 0.1).collect();
        let y: Vec<f64> = t.iter().map(|&t| 200.0 * (1.0 - libm::exp(-t / 40.0))).collect();
        let mut gap = Series::from_columns("with a gap <&>", 2, &t[..100], &y[..100]);
        gap.points[10].1 = f64::NAN;
        Plot {
            title: "Start-up \"25 kn\"".into(),
            x_label: "time [s]".into(),
            x_range: None,
            panels: vec![
                Panel::new(
                    "shaft speed [rpm]",
                    vec![
                        Series::from_columns("ours", 0, &t, &y),
                        Series::level("thesis, Fig. 5-1", 1, 225.0, 0.0, 300.0),
                        gap,
                    ],
                ),
                Panel::new("turbine speed [pu]", vec![Series::markers("points", 3, vec![(0.0, 1.0), (100.0, 0.8)])])
                    .with_range(0.7, 1.05),
            ],
        }
    }

    /// The writer's output is well-formed: tags balanced, quotes paired, no NaN or infinity
    /// (a NaN point in the data is skipped), every axis label and the title present and escaped.
    #[test]
    fn svg_is_well_formed_and_labelled() {
        let s = svg(&sample()).unwrap();
        check_well_formed(&s).unwrap();
        for l in
            ["time [s]", "shaft speed [rpm]", "turbine speed [pu]", "with a gap &lt;&amp;&gt;", "&quot;25 kn&quot;"]
        {
            assert!(s.contains(l), "missing {l}");
        }
        // Two polylines for the series with a gap, one each for the others.
        assert_eq!(s.matches("<polyline").count(), 4);
        // Thinned to at most MAX_POINTS a series.
        let longest = s.lines().filter(|l| l.starts_with("<polyline")).map(|l| l.matches(',').count()).max();
        assert!(longest.unwrap() <= MAX_POINTS);
        // Byte-stable: the same plot twice gives the same text.
        assert_eq!(s, svg(&sample()).unwrap());
    }

    /// A label without a unit, a plot without panels and an empty fixed range are refused.
    #[test]
    fn svg_refuses_labels_without_units() {
        let mut p = sample();
        p.panels[0].y_label = "shaft speed".into();
        assert!(svg(&p).unwrap_err().contains("no unit"));
        let mut p = sample();
        p.x_label = "time []".into();
        assert!(svg(&p).is_err());
        let mut p = sample();
        p.panels[1].y_range = Some((1.0, 1.0));
        assert!(svg(&p).is_err());
        let mut p = sample();
        p.panels.clear();
        assert!(svg(&p).is_err());
        assert!(has_unit("h/R [-]") && has_unit("RAO [m/m]") && !has_unit("x [") && !has_unit("x"));
    }

    /// The checker catches what it is for.
    #[test]
    fn checker_catches_faults() {
        assert!(check_well_formed("<svg><g></svg>").is_err());
        assert!(check_well_formed("<svg><line x1=\"NaN\"/></svg>").is_err());
        assert!(check_well_formed("<svg><line x1=\"1e999\"/></svg>").is_err());
        assert!(check_well_formed("<svg><line x1=\"1/></svg>").is_err());
        assert!(check_well_formed("<svg><text>inf</text></svg>").is_err());
        assert!(check_well_formed("<svg><g></g><line x1=\"1.5\"/><text>infinite depth, nanometre</text></svg>").is_ok());
    }

    /// Ticks: 1-2-5 steps, inside the range, labels without "-0".
    #[test]
    fn ticks_are_round() {
        let t = ticks(0.0, 1.0);
        assert_eq!(t.len(), 6);
        assert!(t.iter().enumerate().all(|(k, &x)| (x - 0.2 * k as f64).abs() < 1e-12));
        assert_eq!(ticks(-3.0, 7.0), vec![-2.0, 0.0, 2.0, 4.0, 6.0]);
        assert_eq!(nice_range((3.2, 97.0)), (0.0, 100.0));
        assert_eq!(tick_label(-0.0, 1), "0.0");
        assert_eq!(decimals(&[0.0, 0.25]), 2);
        assert_eq!(decimals(&[0.0, 20.0]), 0);
    }
}
