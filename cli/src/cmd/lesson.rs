//! `aes-sim lesson`: a lesson of the page run natively, with the explanation its run supports
//! (core's output::lessons, the same words the page shows): a teacher can read what the class will
//! see at each value before class.

use crate::common::{emit, emit_json, shorten, Failure};
use aes_core::output::lessons;

// The command line of `aes-sim lesson`.
#[derive(clap::Args)]
pub struct Args {
    /// Lesson name (power, waves, turn, braking, bus, engines, sign, battery); without one, the list.
    name: Option<String>,
    /// A control's value, as the lesson's link carries it, e.g. `--value sea.sea_state=4`
    /// (repeatable).
    #[arg(long = "value")]
    values: Vec<String>,
    /// The whole explanation as JSON (the facts each sentence rests on, the promise of "try
    /// this next"), not only its words.
    #[arg(long)]
    json: bool,
}

pub fn run(a: Args) -> Result<(), Failure> {
    let Some(name) = a.name else {
        let text: Vec<String> = lessons::lessons().iter().map(|l| format!("{:<8} {}", l.name, l.title)).collect();
        emit(&text.join("\n"))?;
        return Ok(());
    };
    let l = lessons::lesson(&name)?;
    let mut given = Vec::new();
    for v in &a.values {
        given.push(v.split_once('=').ok_or_else(|| format!("--value '{}': expected PATH=VALUE", shorten(v)))?);
    }
    let o = lessons::open(&l, &given)?;
    for r in &o.refused {
        eprintln!("refused: {r}");
    }
    for s in &o.snapped {
        eprintln!("moved to a stop: {s}");
    }
    let r = aes_core::run(&o.scenario).map_err(|e| e.to_string())?;
    let e =
        lessons::explain(&l, &o.values, &lessons::Run { scenario: &o.scenario, trace: &r.trace, summary: &r.summary });
    if a.json {
        return emit_json(&e);
    }
    let words: Vec<&str> = e.sentences.iter().map(|(s, _)| s.as_str()).collect();
    let verdict = match e.right {
        Some(i) => format!("The run shows: {}.", l.answers[i]),
        None => e.verdict_note.clone(),
    };
    emit(&format!("{}\n{}\nTry this next: {}", verdict, words.join(" "), e.next.text))?;
    Ok(())
}
