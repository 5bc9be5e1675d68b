//! Documentation whose examples run: every snippet of the tutorial is a test.
//!
//! - A fenced block ```` ```ada ```` is a script. The info string may add
//!   `trace` (print the motion trace), `rm-501` (the other robot) and
//!   `exit=N` (the exit status it must end with; default 0). The next fenced
//!   block must be ```` ```text ````: exactly what the run prints, its output
//!   (with the trace) and then its diagnostics, without colour.
//! - A fenced block ```` ```repl ```` is a REPL session: lines starting with
//!   `adair> ` are entries (a line starting with `   ...> ` continues the
//!   entry above it), every other line is what the REPL prints for the entry
//!   above it.
//!
//! `BLESS=1 cargo test --test docs` rewrites the expected text in place; read
//! the diff before committing.
#![allow(clippy::print_stderr)]

use adair::golden::SharedBuf;
use libtest_mimic::{Arguments, Failed, Trial};
use std::io::Write;
use std::path::{Path, PathBuf};

/// The documents whose snippets run.
const DOCS: &[&str] = &["docs/tutorial.md"];

const PROMPT: &str = "adair> ";
const MORE: &str = "   ...> ";

#[derive(Clone, Debug)]
enum Snippet {
    Script {
        code: String,
        robot: String,
        trace: bool,
        exit: i32,
        /// Lines (0-based) of the expected block's content, end exclusive.
        expect: (usize, usize),
    },
    Repl {
        /// Lines (0-based) of the block's content, end exclusive.
        body: (usize, usize),
    },
}

struct Block {
    info: String,
    /// Content lines, 0-based, end exclusive.
    range: (usize, usize),
}

fn blocks(lines: &[&str]) -> Result<Vec<Block>, String> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        if let Some(info) = lines[i].strip_prefix("```") {
            let start = i + 1;
            let mut end = start;
            while end < lines.len() && lines[end] != "```" {
                end += 1;
            }
            if end == lines.len() {
                return Err(format!("line {}: unclosed code block", i + 1));
            }
            out.push(Block {
                info: info.trim().to_string(),
                range: (start, end),
            });
            i = end + 1;
        } else {
            i += 1;
        }
    }
    Ok(out)
}

fn snippets(text: &str) -> Result<Vec<(usize, Snippet)>, String> {
    let lines: Vec<&str> = text.lines().collect();
    let bs = blocks(&lines)?;
    let mut out = Vec::new();
    let mut k = 0;
    while k < bs.len() {
        let b = &bs[k];
        let mut words = b.info.split_whitespace();
        match words.next() {
            Some("ada") => {
                let (mut robot, mut trace, mut exit) = ("rv-m1".to_string(), false, 0);
                for w in words {
                    match w {
                        "trace" => trace = true,
                        "rm-501" | "rv-m1" => robot = w.to_string(),
                        _ => match w.strip_prefix("exit=").and_then(|n| n.parse().ok()) {
                            Some(n) => exit = n,
                            None => {
                                return Err(format!(
                                    "line {}: unknown word {w:?} after ```ada",
                                    b.range.0
                                ));
                            }
                        },
                    }
                }
                let next = bs.get(k + 1).filter(|n| n.info == "text").ok_or_else(|| {
                    format!(
                        "line {}: an ```ada block must be followed by a ```text block with its output",
                        b.range.0
                    )
                })?;
                out.push((
                    b.range.0,
                    Snippet::Script {
                        code: lines[b.range.0..b.range.1].join("\n") + "\n",
                        robot,
                        trace,
                        exit,
                        expect: next.range,
                    },
                ));
                k += 2;
            }
            Some("repl") => {
                out.push((b.range.0, Snippet::Repl { body: b.range }));
                k += 1;
            }
            _ => k += 1,
        }
    }
    Ok(out)
}

/// The lines (0-based, end exclusive) of an expected text, and what was printed there.
type Printed = ((usize, usize), String);

/// What a snippet prints, for each of its expected texts.
fn run(lines: &[&str], s: &Snippet) -> Result<Vec<Printed>, String> {
    match s {
        Snippet::Script {
            code,
            robot,
            trace,
            exit,
            expect,
        } => {
            let r = adair::golden::run_text("snippet.air", code, robot, *trace);
            if r.code != *exit {
                return Err(format!(
                    "exit status {} expected, {} found; it printed:\n{}{}",
                    exit, r.code, r.output, r.diagnostics
                ));
            }
            Ok(vec![(*expect, r.output + &r.diagnostics)])
        }
        Snippet::Repl { body } => {
            let buf = SharedBuf::default();
            let b2 = buf.clone();
            let mut repl = adair::repl::Repl::new(
                Box::new(move || Box::new(b2.clone()) as Box<dyn Write>),
                false,
            );
            let mut out = Vec::new();
            let mut i = body.0;
            while i < body.1 {
                let Some(first) = lines[i].strip_prefix(PROMPT) else {
                    return Err(format!("line {}: expected an `{PROMPT}` entry", i + 1));
                };
                let mut entry = format!("{first}\n");
                i += 1;
                while i < body.1 {
                    match lines[i].strip_prefix(MORE) {
                        Some(more) => {
                            entry.push_str(more);
                            entry.push('\n');
                            i += 1;
                        }
                        None => break,
                    }
                }
                let start = i;
                while i < body.1 && !lines[i].starts_with(PROMPT) {
                    i += 1;
                }
                let reply = repl.entry(&entry);
                out.push(((start, i), buf.take() + &reply.text));
            }
            Ok(out)
        }
    }
}

fn expected(lines: &[&str], range: (usize, usize)) -> String {
    lines[range.0..range.1]
        .iter()
        .map(|l| format!("{l}\n"))
        .collect()
}

fn check(path: &Path, at: usize, s: &Snippet) -> Result<(), Failed> {
    let text = std::fs::read_to_string(path).map_err(|e| e.to_string())?;
    let lines: Vec<&str> = text.lines().collect();
    for (range, got) in run(&lines, s)? {
        let want = expected(&lines, range);
        if want != got {
            return Err(Failed::from(format!(
                "{}:{}: output differs (- expected, + actual):\n{}",
                path.display(),
                at,
                adair::golden::diff(&want, &got)
            )));
        }
    }
    Ok(())
}

/// Rewrites every expected text of a document with what its snippets print.
fn bless(path: &Path) -> Result<(), String> {
    let text = std::fs::read_to_string(path).map_err(|e| e.to_string())?;
    let lines: Vec<&str> = text.lines().collect();
    let mut replacements = Vec::new();
    for (_, s) in snippets(&text)? {
        replacements.extend(run(&lines, &s)?);
    }
    let mut out = String::new();
    let mut i = 0;
    for ((start, end), got) in replacements {
        for l in &lines[i..start] {
            out.push_str(l);
            out.push('\n');
        }
        out.push_str(&got);
        i = end;
    }
    for l in &lines[i..] {
        out.push_str(l);
        out.push('\n');
    }
    std::fs::write(path, out).map_err(|e| e.to_string())
}

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    std::env::set_current_dir(&root).expect("crate root");
    let blessing = std::env::var_os("BLESS").is_some();
    let mut trials = Vec::new();
    for doc in DOCS {
        let path = PathBuf::from(doc);
        if blessing && let Err(e) = bless(&path) {
            eprintln!("{doc}: {e}");
            std::process::exit(1);
        }
        let text = std::fs::read_to_string(&path).expect("document");
        let found = match snippets(&text) {
            Ok(s) => s,
            Err(e) => {
                trials.push(Trial::test(format!("{doc}::structure"), move || {
                    Err(Failed::from(e.clone()))
                }));
                continue;
            }
        };
        if found.is_empty() {
            trials.push(Trial::test(format!("{doc}::has_snippets"), || {
                Err(Failed::from("no ```ada or ```repl snippet found"))
            }));
        }
        for (at, s) in found {
            let path = path.clone();
            trials.push(Trial::test(
                format!("{}::line_{}", doc.replace('/', "::"), at),
                move || check(&path, at, &s),
            ));
        }
    }
    libtest_mimic::run(&Arguments::from_args(), trials).exit();
}
