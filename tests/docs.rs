//! Documentation whose examples run: every snippet of the tutorial is a test.
//!
//! - A fenced block ```` ```ada ```` is a script. The info string may add
//!   `trace` (print the motion trace), `rm-501` (the other robot) and
//!   `exit=N` (the exit status it must end with; default 0). The next fenced
//!   block must be ```` ```text ````: the command that runs the snippet
//!   (`$ adair run --trace snippet.air`, so a reader sees the options the
//!   info string, which a rendered page hides, asks for), then exactly what
//!   the run prints, its output (with the trace) and then its diagnostics,
//!   without colour.
//! - A fenced block ```` ```repl ```` is a REPL session: lines starting with
//!   `adair> ` are entries (a line starting with `   ...> ` continues the
//!   entry above it), every other line is what the REPL prints for the entry
//!   above it.
//!
//! `BLESS=1 cargo test --test docs` rewrites the expected text in place; read
//! the diff before committing.
//!
//! README.md is checked too (never blessed): its example (a ```` ```ada ````
//! block whose first line is `-- NAME.air`) is written to `NAME.air` and the
//! ```` ```text ```` transcript after it is replayed: each `$ adair ...` line
//! runs the binary there (standard output and error together, as a
//! terminal shows them), `$ echo $?` prints its exit status, and every
//! other line is what they printed. Every command of its ```` ```sh ````
//! blocks runs as well: one whose files all exist (the examples) for real,
//! to exit status 0; one with a placeholder (`FILE.air`, `DIR`, a port)
//! with `--help` added, so that clap accepts its subcommand and options.
//! `cargo run --release -- X` is `adair X`; `cargo test` is this suite.
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
            Ok(vec![(
                *expect,
                command_line(robot, *trace) + &r.output + &r.diagnostics,
            )])
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

/// The command a snippet's output is shown under.
fn command_line(robot: &str, trace: bool) -> String {
    format!(
        "$ adair run{}{} snippet.air\n",
        if robot == "rv-m1" {
            String::new()
        } else {
            format!(" --robot {robot}")
        },
        if trace { " --trace" } else { "" }
    )
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
    trials.extend(readme_trials());
    libtest_mimic::run(&Arguments::from_args(), trials).exit();
}

/// A scratch folder of this test run.
fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("adair-docs-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).expect("scratch folder");
    d
}

/// Runs adair with `args` in `dir`, standard output and error in one pipe
/// (as a terminal shows them, in the order written): its exit status and
/// what it printed.
fn adair_in(dir: &Path, args: &[&str]) -> (i32, String) {
    let out = std::process::Command::new("sh")
        .arg("-c")
        .arg("exec \"$0\" \"$@\" 2>&1")
        .arg(env!("CARGO_BIN_EXE_adair"))
        .args(args)
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .stdin(std::process::Stdio::null())
        .output()
        .expect("adair runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

/// README's example: the ```ada block named by its first line
/// (`-- NAME.air`) and the ```text transcript after it.
fn readme_example(text: &str) -> Result<(String, String, Vec<String>), String> {
    let lines: Vec<&str> = text.lines().collect();
    let bs = blocks(&lines)?;
    for (k, b) in bs.iter().enumerate() {
        if b.info != "ada" {
            continue;
        }
        let code = &lines[b.range.0..b.range.1];
        let Some(name) = code.first().and_then(|l| l.strip_prefix("-- ")) else {
            continue;
        };
        let next = bs
            .get(k + 1)
            .filter(|n| n.info == "text")
            .ok_or("README's example has no ```text block after it")?;
        let transcript = lines[next.range.0..next.range.1]
            .iter()
            .map(|l| l.to_string())
            .collect();
        return Ok((name.trim().to_string(), code.join("\n") + "\n", transcript));
    }
    Err("README has no ```ada example whose first line is `-- NAME.air`".into())
}

/// Replays the transcript in `dir`: what each command printed, against
/// what the transcript shows.
fn replay(dir: &Path, transcript: &[String]) -> Result<(), String> {
    let mut i = 0;
    let mut status = None;
    let mut commands = 0;
    while i < transcript.len() {
        let Some(cmd) = transcript[i].strip_prefix("$ ") else {
            return Err(format!(
                "transcript line {}: `{}` is not a `$ ` command",
                i + 1,
                transcript[i]
            ));
        };
        let mut end = i + 1;
        while end < transcript.len() && !transcript[end].starts_with("$ ") {
            end += 1;
        }
        let want: String = transcript[i + 1..end]
            .iter()
            .map(|l| format!("{l}\n"))
            .collect();
        let got = if cmd.trim() == "echo $?" {
            format!("{}\n", status.ok_or("`echo $?` before any command")?)
        } else {
            let args: Vec<&str> = cmd.split_whitespace().collect();
            if args.first() != Some(&"adair") {
                return Err(format!("`{cmd}`: only adair runs in a transcript"));
            }
            let (code, out) = adair_in(dir, &args[1..]);
            status = Some(code);
            out
        };
        if got != want {
            return Err(format!(
                "README: `{cmd}` printed other than shown (- README, + actual):\n{}",
                adair::golden::diff(&want, &got)
            ));
        }
        commands += 1;
        i = end;
    }
    if commands == 0 {
        return Err("README's example transcript has no command".into());
    }
    Ok(())
}

/// The adair arguments of each command line of README's ```sh blocks
/// (`cargo run --release -- X` is `adair X`; `cargo test` is left out: it
/// is this test suite), with the line it came from.
fn readme_commands(text: &str) -> Result<Vec<(String, Vec<String>)>, String> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for b in blocks(&lines)?.iter().filter(|b| b.info == "sh") {
        for line in &lines[b.range.0..b.range.1] {
            let cmd = line.split(" #").next().unwrap_or("").trim();
            if cmd.is_empty() || cmd == "cargo test" {
                continue;
            }
            let args = if let Some(rest) = cmd.strip_prefix("cargo run --release -- ") {
                rest
            } else if let Some(rest) = cmd.strip_prefix("adair") {
                rest
            } else {
                return Err(format!("README: `{cmd}` is neither adair nor cargo"));
            };
            out.push((
                cmd.to_string(),
                args.split_whitespace().map(str::to_string).collect(),
            ));
        }
    }
    Ok(out)
}

/// Whether a README command runs as written: every file it names (a word
/// with an extension or a path) is in the repository, it reads no terminal
/// and serves nothing (`repl`, `lsp`, `sim-controller`, a live `--view`).
fn runs_as_written(root: &Path, args: &[String]) -> bool {
    let serves = ["repl", "lsp", "sim-controller"];
    let live_view = args
        .iter()
        .enumerate()
        .any(|(k, a)| a == "--view" && args.get(k + 1).is_none_or(|n| !n.ends_with(".html")));
    if args.is_empty() || live_view || args.iter().any(|a| serves.contains(&a.as_str())) {
        return false;
    }
    // A placeholder: FILE, DIR, PATH..., a port, a redirection.
    let placeholder = |a: &str| {
        a.contains('<')
            || a.starts_with("/dev/")
            || a.as_bytes()
                .windows(3)
                .any(|w| w.iter().all(u8::is_ascii_uppercase))
    };
    args.iter().all(|a| !placeholder(a))
        && args
            .iter()
            .filter(|a| !a.starts_with('-') && (a.contains('.') || a.contains('/')))
            .all(|a| root.join(a).is_file())
}

fn readme_trials() -> Vec<Trial> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let text = match std::fs::read_to_string(root.join("README.md")) {
        Ok(t) => t,
        Err(e) => {
            let e = e.to_string();
            return vec![Trial::test("README::read", move || Err(Failed::from(e)))];
        }
    };
    let mut trials = Vec::new();
    let example = readme_example(&text);
    trials.push(Trial::test(
        "README::example_prints_what_it_shows",
        move || {
            let (name, code, transcript) = example?;
            let dir = scratch("readme");
            std::fs::write(dir.join(&name), code).map_err(|e| e.to_string())?;
            replay(&dir, &transcript)?;
            let _ = std::fs::remove_dir_all(&dir);
            Ok(())
        },
    ));
    let commands = match readme_commands(&text) {
        Ok(c) => c,
        Err(e) => {
            trials.push(Trial::test("README::commands", move || {
                Err(Failed::from(e))
            }));
            return trials;
        }
    };
    trials.push(Trial::test("README::has_commands", {
        let n = commands.len();
        move || {
            if n < 10 {
                return Err(Failed::from(format!("only {n} commands found in README")));
            }
            Ok(())
        }
    }));
    for (k, (line, args)) in commands.into_iter().enumerate() {
        let root = root.clone();
        let real = runs_as_written(&root, &args);
        let name = format!(
            "README::command_{k:02}_{}",
            if real { "runs" } else { "help" }
        );
        trials.push(Trial::test(name, move || {
            let mut args: Vec<&str> = args.iter().map(String::as_str).collect();
            if !real && !args.contains(&"--help") {
                args.push("--help");
            }
            let (code, out) = adair_in(&root, &args);
            if code != 0 || out.is_empty() {
                return Err(Failed::from(format!(
                    "README's `{line}` ({}): exit {code}, printed:\n{out}",
                    if real {
                        "run as written"
                    } else {
                        "with --help"
                    }
                )));
            }
            Ok(())
        }));
    }
    trials
}
