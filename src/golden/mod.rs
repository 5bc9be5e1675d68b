//! The golden-output runner behind `adair test` and the project's own tests:
//! each `X.air` runs and its output is compared with `X.out` beside it.
//!
//! The expected text is the program's standard output, then, if anything went
//! to standard error (diagnostics, without colour), a line `-- stderr --` and
//! that text, then, for a non-zero exit status, a line `-- exit: N`.
//!
//! A script's run does not depend on how it was named: it is shown under its
//! file name (`ex4.air:2:25`, not `./ex4.air` or `tests/golden/ex4.air`), its
//! standard input is `X.in` beside it (none: an empty input), and `adair
//! test` runs it as a child process of the `adair` binary ([`Isolated`]) in
//! the script's own folder, with a wall-clock time limit. The in-process
//! runner ([`run_case`], [`check_case`]) is the same run without the folder
//! and the limit (the library's own tests use it).

use crate::session::{Outcome, Session};
use std::cell::RefCell;
use std::ffi::OsString;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::rc::Rc;
use std::time::{Duration, Instant};

mod isolated;
mod report;
pub use isolated::*;
pub use report::*;

/// A `Write` that appends to a shared buffer.
#[derive(Clone, Default)]
pub struct SharedBuf(pub Rc<RefCell<Vec<u8>>>);

impl Write for SharedBuf {
    fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
        self.0.borrow_mut().extend_from_slice(b);
        Ok(b.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

impl SharedBuf {
    pub fn take(&self) -> String {
        String::from_utf8_lossy(&std::mem::take(&mut *self.0.borrow_mut())).into_owned()
    }
}

/// The time limit of a script that sets none, in seconds of wall clock.
pub const DEFAULT_TIMEOUT: f64 = 10.0;

/// What a script asks for in its first-lines comments, `-- adair: --robot
/// rm-501 --trace`, `-- adair: --devices belt.toml`, `-- adair: --timeout 30`
/// (the leading comment lines only; several such lines add up).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Directives {
    /// `--robot R`: the simulated robot.
    pub robot: Option<String>,
    /// `--trace`: the motion trace in the output.
    pub trace: bool,
    /// `--devices FILE.toml`: a device file, relative to the script's folder.
    pub devices: Option<String>,
    /// `--timeout SECONDS`: the script's time limit (0: none).
    pub timeout: Option<f64>,
}

/// The options a `-- adair:` line may give, for messages.
const KNOWN: &str = "--robot R, --trace, --devices FILE.toml, --timeout SECONDS";

/// Reads the `-- adair:` lines of a script; an unknown option or a missing
/// or bad value is an error (a configuration error of the test, never
/// blessed).
pub fn directives(text: &str) -> Result<Directives, String> {
    let mut d = Directives::default();
    for line in text.lines().take_while(|l| l.starts_with("--")) {
        let Some(rest) = line.strip_prefix("-- adair:") else {
            continue;
        };
        let mut words = rest.split_whitespace();
        while let Some(w) = words.next() {
            let mut value = |what: &str| {
                words
                    .next()
                    .map(str::to_string)
                    .ok_or_else(|| format!("`-- adair: {w}` needs {what}"))
            };
            match w {
                "--trace" => d.trace = true,
                "--robot" => d.robot = Some(value("a robot (rv-m1 or rm-501)")?),
                "--devices" => d.devices = Some(value("a device file")?),
                "--timeout" => {
                    let v = value("a number of seconds")?;
                    d.timeout = Some(timeout_seconds(&v).map_err(|e| format!("--timeout {e}"))?);
                }
                _ => {
                    return Err(format!(
                        "unknown option `{w}` in `-- adair:` (known: {KNOWN})"
                    ));
                }
            }
        }
    }
    Ok(d)
}

/// A time limit in seconds: finite, 0 (no limit) to a day.
pub fn timeout_seconds(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(x) if x.is_finite() && (0.0..=86400.0).contains(&x) => Ok(x),
        _ => Err(format!(
            "`{text}`: a number of seconds from 0 (no limit) to 86400"
        )),
    }
}

/// Runs a script as `adair run` would (no colour) and returns its golden text.
/// A trace asked for by the script is interleaved with its output.
pub fn run_case(path: &Path) -> String {
    run_case_on(path, &Target::default())
}

/// Where `adair test` runs its scripts: the simulator (no port), or a real
/// arm over `port`, each script rehearsed on the simulator first when
/// `rehearse` asks.
#[derive(Clone, Debug, Default)]
pub struct Target {
    pub port: Option<crate::driver::serial::PortSettings>,
    pub rehearse: bool,
    /// The simulated devices (a script's `--devices` directive).
    pub devices: Option<crate::devices::Devices>,
    /// The robot of scripts that name none (`adair test --robot`; None: rv-m1).
    pub robot: Option<String>,
    /// Every script's motion trace in its output (`adair test --trace`).
    pub trace: bool,
    /// The program's standard input (a script's `X.in`; none: empty).
    pub input: Vec<u8>,
    /// Set to stop the program as Ctrl-C does (the time limit of a child run).
    pub interrupt: Option<std::sync::Arc<std::sync::atomic::AtomicBool>>,
    /// Write the run's replay page there (`adair test --view`; see
    /// [`view_page`]).
    pub view: Option<PathBuf>,
}

/// The replay page `adair test --view` writes for `script`: `X.view.html`
/// for `X.air`, beside it (`folder` None) or in `folder`.
pub fn view_page(script: &Path, folder: Option<&Path>) -> PathBuf {
    let stem = script
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let name = format!("{stem}.view.html");
    match folder {
        Some(f) => f.join(name),
        None => script.with_file_name(name),
    }
}

/// Scripts whose pages would go to one file in `adair test --view=FOLDER`
/// (scripts of one name in different folders): the first such pair.
pub fn same_page(scripts: &[PathBuf]) -> Option<(&Path, &Path)> {
    let mut seen: std::collections::HashMap<PathBuf, &Path> = Default::default();
    for s in scripts {
        let page = view_page(s, Some(Path::new("")));
        if let Some(first) = seen.insert(page, s) {
            return Some((first, s));
        }
    }
    None
}

/// The name a script is shown under: its file name (a run happens in the
/// script's folder, so that its diagnostics and the paths it prints are the
/// same however the script was named).
pub fn shown_name(path: &Path) -> String {
    path.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| path.to_string_lossy().into_owned())
}

/// The standard input file of a script: `X.in` beside `X.air`.
pub fn input_path(script: &Path) -> PathBuf {
    script.with_extension("in")
}

/// [`run_case`] on `target`; a configuration error (a bad `-- adair:`
/// line, an unknown robot, a device file that does not load) is shown as in
/// the golden text, with exit status 2.
pub fn run_case_on(path: &Path, target: &Target) -> String {
    run_case_checked(path, target).unwrap_or_else(|e| format!("-- stderr --\n{e}\n-- exit: 2\n"))
}

/// [`run_case_on`], a configuration error apart: `Err` is that error as
/// `adair run` prints it (never an expected output).
pub fn run_case_checked(path: &Path, target: &Target) -> Result<String, String> {
    let name = shown_name(path);
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("adair: cannot read {}: {e}", path.display()))?;
    let d = directives(&text).map_err(|e| format!("adair: {name}: {e}"))?;
    let robot = d
        .robot
        .clone()
        .or_else(|| target.robot.clone())
        .unwrap_or_else(|| "rv-m1".into());
    if let Err(e) = crate::kinematics::RobotDescription::builtin(&robot) {
        return Err(format!(
            "adair: {name}: --robot: {}: {}",
            e.source,
            e.problems.join("; ")
        ));
    }
    let trace = d.trace || target.trace;
    let devices = match &d.devices {
        None => target.devices.clone(),
        Some(f) => {
            let p = path.parent().unwrap_or(Path::new("")).join(f);
            Some(crate::devices::Devices::load(&p).map_err(|e| e.to_string())?)
        }
    };
    let input = match std::fs::read(input_path(path)) {
        Ok(bytes) => bytes,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => target.input.clone(),
        Err(e) => {
            return Err(format!(
                "adair: cannot read {}: {e}",
                shown_name(&input_path(path))
            ));
        }
    };
    let target = Target {
        devices,
        input,
        ..target.clone()
    };
    let r = run_text_on(&name, &text, &robot, trace, &target);
    if let (Some(e), Some(p)) = (r.view_error, &target.view) {
        return Err(format!("adair: --view {}: {e}", p.display()));
    }
    let mut out = r.output;
    if !r.diagnostics.is_empty() {
        out.push_str("-- stderr --\n");
        out.push_str(&r.diagnostics);
    }
    if r.code != 0 {
        out.push_str(&format!("-- exit: {}\n", r.code));
    }
    Ok(out)
}

/// What a run printed: the program's output (with the motion trace, if asked
/// for, interleaved), the diagnostics without colour, and the exit status.
pub struct RunText {
    pub output: String,
    pub diagnostics: String,
    pub code: i32,
    /// Why the replay page ([`Target::view`]) could not be written.
    pub view_error: Option<String>,
}

/// Runs `text` as the script `name` on the simulated `robot`, with no input.
pub fn run_text(name: &str, text: &str, robot: &str, trace: bool) -> RunText {
    run_text_on(name, text, robot, trace, &Target::default())
}

/// [`run_text`] on `target`: over a serial port the same script drives the
/// arm (after a rehearsal, when asked; a failed one moves nothing and is the
/// run's result).
pub fn run_text_on(name: &str, text: &str, robot: &str, trace: bool, target: &Target) -> RunText {
    let buf = SharedBuf::default();
    let mut s = Session::new(Box::new(buf.clone()));
    s.machine.input = Box::new(std::io::Cursor::new(target.input.clone()));
    s.machine.interrupted = target.interrupt.clone();
    // The script runs once, as `adair run` runs it.
    s.compile_as_checked();
    let tracer = || trace.then(|| Box::new(buf.clone()) as Box<dyn Write>);
    if let Some(d) = &target.devices {
        s.set_devices(d.clone());
    }
    s.machine.trace = tracer();
    match crate::kinematics::RobotDescription::builtin(robot) {
        Ok(desc) => match &target.port {
            None => s.set_robot(desc, tracer(), false),
            Some(settings) => {
                s.front.checker.options.simulator_only = crate::services::SIMULATOR_ONLY;
                if target.rehearse
                    && let Err((diagnostics, code)) =
                        crate::session::rehearse(&desc, settings, name, text, false)
                {
                    return RunText {
                        output: String::new(),
                        diagnostics,
                        code,
                        view_error: None,
                    };
                }
                let driver = crate::driver::serial::Serial::new(
                    desc.clone(),
                    settings.clone(),
                    target.interrupt.clone(),
                );
                s.set_driver(desc, Box::new(driver), tracer(), false);
            }
        },
        Err(e) => {
            return RunText {
                output: String::new(),
                diagnostics: format!("adair: {}: {}\n", e.source, e.problems.join("; ")),
                code: 2,
                view_error: None,
            };
        }
    }
    if target.view.is_some() {
        s.start_recording();
        if let Some(w) = s.machine.world.as_mut() {
            w.keep_timeline();
        }
    }
    let warned = SharedBuf::default();
    s.warnings_to = Some((Box::new(warned.clone()), false));
    let outcome = s.run_source(name, text);
    // The page of a run (none when nothing ran: a check error).
    let view_error = match (&target.view, s.robot_state()) {
        (Some(p), Some(st)) if !matches!(outcome, Outcome::CheckFailed(_)) => {
            let ending = crate::view::ending(&s, &outcome);
            crate::view::write_replay(p, st, s.machine.world.as_ref(), name, &ending).err()
        }
        _ => None,
    };
    let diagnostics = warned.take()
        + &match &outcome {
            Outcome::Ok => String::new(),
            Outcome::CheckFailed(d) => crate::diag::render(d, &s.front.sources, false),
            Outcome::Raised(d) => {
                crate::diag::render(std::slice::from_ref(d), &s.front.sources, false)
            }
        };
    RunText {
        output: buf.take(),
        diagnostics,
        code: outcome.exit_code(),
        view_error,
    }
}

/// The expected-output file of a script.
pub fn expected_path(script: &Path) -> PathBuf {
    script.with_extension("out")
}

/// What became of one script.
#[derive(Clone, Debug)]
pub enum Verdict {
    Pass,
    Blessed,
    /// No `.out` file (and no `--bless`): what the script printed.
    Missing {
        actual: String,
    },
    Differs {
        expected: String,
        actual: String,
    },
    /// A configuration error (a bad `-- adair:` line, an unknown robot, a
    /// device file that does not load), as `adair run` prints it: a failure,
    /// never blessed.
    Config(String),
    /// Still running at the time limit (seconds); what it printed until the
    /// program was stopped, when it could be stopped.
    TimedOut {
        limit: f64,
        partial: Option<String>,
    },
    /// The run itself failed (the child process crashed or could not start).
    Crashed(String),
}

impl Verdict {
    /// A pass, or an `.out` file written.
    pub fn passed(&self) -> bool {
        matches!(self, Verdict::Pass | Verdict::Blessed)
    }
}

pub fn check_case(script: &Path, bless: bool) -> Verdict {
    check_case_on(script, bless, &Target::default())
}

/// [`check_case`] on `target`, in this process.
pub fn check_case_on(script: &Path, bless: bool, target: &Target) -> Verdict {
    match run_case_checked(script, target) {
        Ok(actual) => judge(script, actual, bless),
        Err(e) => Verdict::Config(e),
    }
}

/// Compares the output of `script` with its `.out` file, or writes the
/// file (`bless`).
pub fn judge(script: &Path, actual: String, bless: bool) -> Verdict {
    let exp_path = expected_path(script);
    if bless {
        let tmp = exp_path.with_extension("out.tmp");
        match std::fs::write(&tmp, &actual).and_then(|_| std::fs::rename(&tmp, &exp_path)) {
            Ok(()) => return Verdict::Blessed,
            Err(e) => {
                let _ = std::fs::remove_file(&tmp);
                return Verdict::Crashed(format!("cannot write {}: {e}", exp_path.display()));
            }
        }
    }
    match std::fs::read_to_string(&exp_path) {
        Ok(expected) if expected == actual => Verdict::Pass,
        Ok(expected) => Verdict::Differs { expected, actual },
        Err(_) => Verdict::Missing { actual },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_diff_keeps_context_and_numbers_lines_in_their_own_text() {
        let e = "a\nb\nc\nd\ne\nf\ng\nh\n";
        let a = "a\nb\nc\nd\nX\ne\nf\ng\nh\n";
        let d = diff(e, a);
        assert_eq!(
            d,
            "--- expected\n+++ actual\n\
             @@ expected line 2, actual line 2 @@\n\
             \x20    2 | b\n     3 | c\n     4 | d\n\
             +    5 | X\n\
             \x20    5 | e\n     6 | f\n     7 | g\n"
        );
    }

    #[test]
    fn a_diff_of_trailing_spaces_says_so() {
        let d = diff("a\nb\n", "a \nb\n");
        assert!(
            d.contains("differ only in spaces or tabs at their ends"),
            "{d}"
        );
        assert!(!diff("a\n", "b \n").contains("only in spaces"));
    }

    #[test]
    fn a_diff_of_a_missing_final_line_end_says_so() {
        let d = diff("a\n", "a");
        assert!(d.contains("the output has no line end"), "{d}");
    }

    #[test]
    fn xml_escape_leaves_no_markup_and_no_forbidden_character() {
        assert_eq!(
            xml_escape("<a href=\"x\">&'\u{1b}[31m\r"),
            "&lt;a href=&quot;x&quot;&gt;&amp;&apos;\u{FFFD}[31m&#13;"
        );
    }

    #[test]
    fn directives_reject_what_they_do_not_know() {
        assert_eq!(
            directives("-- adair: --robot rm-501 --trace\n-- adair: --timeout 2.5\nX;\n"),
            Ok(Directives {
                robot: Some("rm-501".into()),
                trace: true,
                devices: None,
                timeout: Some(2.5),
            })
        );
        assert!(directives("-- adair: --rbot rm-501\n").is_err());
        assert!(directives("-- adair: --timeout\n").is_err());
        assert!(directives("-- adair: --timeout -1\n").is_err());
        // Only the leading comment lines count.
        assert_eq!(
            directives("X;\n-- adair: --nonsense\n"),
            Ok(Directives::default())
        );
    }
}
