//! The diagnostics of the run: an exception that left the program
//! (E0901), a deadlock (E0902), a run the user stopped (E0903), each with
//! its places as notes.

use super::{Ending, Occurrence};
use crate::diag::codes;
use crate::diag::{Diagnostic, Span};

/// The diagnostic for an occurrence that left the program; `name` is its
/// exception's name.
pub fn left_the_program(o: &Occurrence, name: &str) -> Diagnostic {
    match o.ending {
        Ending::Deadlock => deadlock(o),
        Ending::Stopped => stopped(o),
        Ending::Exception => unhandled(o, name),
    }
}

/// Every task blocked: one note per task, what it waits for, where.
fn deadlock(o: &Occurrence) -> Diagnostic {
    let mut d = Diagnostic::new(codes::E0902, o.span, super::tasking::DEADLOCK)
        .with_label("blocked here")
        .with_hint("a task waits forever when nobody calls the entry it accepts, or calls an entry nobody accepts: check that every call has its accept");
    for (line, s) in o.message.lines().skip(1).zip(&o.chain) {
        d = d.with_note(*s, line.to_string());
    }
    d
}

/// Ctrl-C while tasks ran: where the main program was, then one note per
/// task.
fn stopped(o: &Occurrence) -> Diagnostic {
    let mut d = Diagnostic::new(codes::E0903, o.span, super::STOPPED_TASKS)
        .with_label("the main program was here");
    for (line, s) in o.message.lines().skip(1).zip(&o.chain) {
        d = d.with_note(*s, line.to_string());
    }
    d
}

/// An exception no handler caught, with where it was re-raised and the
/// calls it came through.
fn unhandled(o: &Occurrence, name: &str) -> Diagnostic {
    let msg = if o.message.is_empty() {
        format!("raised {name}")
    } else {
        format!("raised {name} : {}", o.message)
    };
    let mut d =
        Diagnostic::new(codes::E0901, o.span, msg).with_label(format!("{name} raised here"));
    for s in &o.reraised {
        d = d.with_note(*s, "re-raised here by `raise;`");
    }
    let real = |s: &Span| !(s.start == 0 && s.end == 0);
    // Consecutive calls from one place (recursion) are one note.
    let mut runs: Vec<(Span, usize)> = Vec::new();
    for s in o.chain.iter().filter(|s| real(s) && **s != o.span) {
        match runs.last_mut() {
            Some((last, n)) if last == s => *n += 1,
            _ => runs.push((*s, 1)),
        }
    }
    let note = |(s, n): (Span, usize), more: usize| {
        let mut text = if n == 1 {
            "called from here".to_string()
        } else {
            format!("called from here {n} times in a row")
        };
        if more > 0 {
            text.push_str(&format!(", and {more} more calls not shown"));
        }
        (s, text)
    };
    // A deep chain shows its innermost and outermost places only (an
    // exception 20,000 calls deep is one screen, built in linear time).
    const INNER: usize = 6;
    const OUTER: usize = 3;
    let notes: Vec<(Span, String)> = if runs.len() > INNER + OUTER + 1 {
        let hidden: usize = runs[INNER + 1..runs.len() - OUTER]
            .iter()
            .map(|r| r.1)
            .sum();
        let mut v: Vec<(Span, String)> = runs[..INNER].iter().map(|r| note(*r, 0)).collect();
        v.push(note(runs[INNER], hidden));
        v.extend(runs[runs.len() - OUTER..].iter().map(|r| note(*r, 0)));
        v
    } else {
        runs.iter().map(|r| note(*r, 0)).collect()
    };
    for (s, text) in notes {
        d = d.with_note(s, text);
    }
    d
}
