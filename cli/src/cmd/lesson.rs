//! `aes-sim lesson`: a lesson of the page run natively, with the explanation its run supports
//! (core's output::lessons, the same words the page shows): a teacher can read what the class will
//! see at each value before class.

use crate::common::{emit, emit_json, shorten, Failure};
use aes_core::output::lessons;

// The command line of `aes-sim lesson`.
#[derive(clap::Args)]
pub struct Args {
    /// Lesson name (power, waves, turn, braking, bus, engines, sign, battery, stopping); without one, the list.
    name: Option<String>,
    /// A control's value, as the lesson's link carries it, e.g. `--value sea.sea_state=4`
    /// (repeatable).
    #[arg(long = "value")]
    values: Vec<String>,
    /// The run before a change, for the verdict on a prediction: its controls' values as
    /// `--value` takes them (repeatable), or `default` for the lesson's own values. The run
    /// before runs too, and the verdict compares the two on the question's number.
    #[arg(long = "before")]
    before: Vec<String>,
    /// The answer predicted, by its place in the lesson's list (1 for the first), for the verdict.
    #[arg(long)]
    answer: Option<usize>,
    /// The whole explanation as JSON (the facts each sentence rests on, the promise of "try
    /// this next"), not only its words.
    #[arg(long)]
    json: bool,
}

pub fn run(a: Args) -> Result<(), Failure> {
    let Some(name) = a.name else {
        // The list takes no values: a flag given without a lesson would be ignored, so it is refused.
        let given = [
            (!a.values.is_empty(), "--value"),
            (!a.before.is_empty(), "--before"),
            (a.answer.is_some(), "--answer"),
            (a.json, "--json"),
        ];
        if let Some((_, flag)) = given.iter().find(|(g, _)| *g) {
            let names: Vec<&str> = lessons::lessons().iter().map(|l| l.name).collect();
            return Err(format!("{flag} needs a lesson NAME first (one of {})", names.join(", ")).into());
        }
        let text: Vec<String> = lessons::lessons().iter().map(|l| format!("{:<8} {}", l.name, l.title)).collect();
        emit(&text.join("\n"))?;
        return Ok(());
    };
    let l = lessons::lesson(&name)?;
    let pairs = |flag: &str, list: &[String]| -> Result<Vec<(String, String)>, Failure> {
        let mut out = Vec::new();
        for v in list.iter().filter(|v| v.as_str() != "default") {
            let (p, x) = v.split_once('=').ok_or_else(|| format!("--{flag} '{}': expected PATH=VALUE", shorten(v)))?;
            // A path that is no control of this lesson would be ignored by the run: refused by name.
            if !l.controls.iter().any(|c| c.path == p) {
                let paths: Vec<&str> = l.controls.iter().map(|c| c.path).collect();
                let what = if p.is_empty() { "an empty path".to_string() } else { format!("'{}'", shorten(p)) };
                return Err(format!(
                    "--{flag} '{}': {what} is not a control of lesson {}; its controls are {}",
                    shorten(v),
                    l.name,
                    paths.join(", ")
                )
                .into());
            }
            out.push((p.to_string(), x.to_string()));
        }
        Ok(out)
    };
    if let Some(n) = a.answer {
        if n == 0 || n > l.answers.len() {
            return Err(
                format!("--answer {n}: expected 1 to {} (the lesson's answers in order)", l.answers.len()).into()
            );
        }
    }
    // One run of the lesson with the values of a flag, explained (against the run before, if any).
    let explained = |flag: &str, list: &[String], before: Option<&lessons::Before>| {
        let given = pairs(flag, list)?;
        let given: Vec<(&str, &str)> = given.iter().map(|(p, v)| (p.as_str(), v.as_str())).collect();
        let o = lessons::open(&l, &given)?;
        // A refused value is an error here (a link keeps the rest and says so; a command must
        // not run something other than what it was given).
        if !o.refused.is_empty() {
            let said: Vec<String> = o.refused.iter().map(|r| format!("--{flag}: {r}")).collect();
            return Err(said.join("; ").into());
        }
        for s in &o.snapped {
            eprintln!("moved to a stop (--{flag}): {s}");
        }
        let r = aes_core::run(&o.scenario).map_err(|e| e.to_string())?;
        let run = lessons::Run { scenario: &o.scenario, trace: &r.trace, summary: &r.summary };
        let e = lessons::explain_after(&l, &o.values, &run, before);
        Ok::<_, Failure>((o.values, e))
    };
    // The run before: its reading is what the verdict compares the run now with.
    let before = if a.before.is_empty() {
        None
    } else {
        let (values, e) = explained("before", &a.before, None)?;
        let reading = e.reading.map(|x| x.value).ok_or_else(|| {
            format!("lesson {}: its question is answered by one run, not by a change (no --before)", l.name)
        })?;
        Some(lessons::Before { values, reading, answer: a.answer.map(|n| n - 1) })
    };
    let (_, e) = explained("value", &a.values, before.as_ref())?;
    if a.json {
        return emit_json(&e);
    }
    let words: Vec<&str> = e.sentences.iter().map(|(s, _)| s.as_str()).collect();
    let verdict = match (&e.verdict, e.right) {
        (Some(v), _) => v.text.clone(),
        (None, Some(i)) => format!("The run shows: {}.", l.answers[i]),
        (None, None) if before.is_some() => "The two runs have the same values: change one and compare.".to_string(),
        (None, None) => e.verdict_note.clone(),
    };
    emit(&format!("{}\n{}\nTry this next: {}", verdict, words.join(" "), e.next.text))?;
    Ok(())
}
