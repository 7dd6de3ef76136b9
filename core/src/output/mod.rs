//! What a page or a report draws: SVG plots and the numbers a display needs beside a trace.

pub mod presentation;
pub mod svg_plot;
