//! What a page draws: the numbers a display needs beside a trace (the validation report's SVG
//! plots are drawn in crate aes-validation).

pub mod lessons;
pub mod presentation;
