//! The golden-output runner behind `adair test` and the project's own tests:
//! each `X.air` runs and its output is compared with `X.out` beside it.
//!
//! The expected text is the program's standard output, then, if anything went
//! to standard error (diagnostics, without colour), a line `-- stderr --` and
//! that text, then, for a non-zero exit status, a line `-- exit: N`.

use crate::session::{Outcome, Session};
use std::cell::RefCell;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::rc::Rc;

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

/// Options a script asks for in a first-lines comment `-- adair: --robot rm-501 --trace`
/// (the robot is `default_robot` when the script names none).
fn directives(text: &str, default_robot: &str) -> (String, bool) {
    let mut robot = default_robot.to_string();
    let mut trace = false;
    for line in text.lines().take_while(|l| l.starts_with("--")) {
        if let Some(rest) = line.strip_prefix("-- adair:") {
            let words: Vec<&str> = rest.split_whitespace().collect();
            for (i, w) in words.iter().enumerate() {
                match *w {
                    "--trace" => trace = true,
                    "--robot" => robot = words.get(i + 1).unwrap_or(&"rv-m1").to_string(),
                    _ => {}
                }
            }
        }
    }
    (robot, trace)
}

/// The device file a script asks for (`-- adair: --devices FILE.toml`, a
/// path relative to the script's directory).
fn devices_directive(text: &str) -> Option<String> {
    text.lines()
        .take_while(|l| l.starts_with("--"))
        .filter_map(|l| l.strip_prefix("-- adair:"))
        .find_map(|rest| {
            let words: Vec<&str> = rest.split_whitespace().collect();
            let i = words.iter().position(|w| *w == "--devices")?;
            words.get(i + 1).map(|w| w.to_string())
        })
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
    /// The engine to run in (None: the session's default, `ADAIR_ENGINE`
    /// or the compiled one); the tests run every script in both.
    pub engine: Option<crate::interp::vm::Engine>,
    /// The simulated devices (a script's `--devices` directive).
    pub devices: Option<crate::devices::Devices>,
    /// The robot of scripts that name none (`adair test --robot`; None: rv-m1).
    pub robot: Option<String>,
    /// Every script's motion trace in its output (`adair test --trace`).
    pub trace: bool,
}

/// [`run_case`] on `target`.
pub fn run_case_on(path: &Path, target: &Target) -> String {
    let name = path.to_string_lossy().replace('\\', "/");
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) => return format!("-- stderr --\nerror: cannot read {name}: {e}\n-- exit: 2\n"),
    };
    let (robot, trace) = directives(&text, target.robot.as_deref().unwrap_or("rv-m1"));
    let trace = trace || target.trace;
    let devices = match devices_directive(&text) {
        None => None,
        Some(f) => {
            let p = path.parent().unwrap_or(Path::new(".")).join(f);
            match crate::devices::Devices::load(&p) {
                Ok(d) => Some(d),
                Err(e) => return format!("-- stderr --\n{e}\n-- exit: 2\n"),
            }
        }
    };
    let target = Target {
        devices: devices.or_else(|| target.devices.clone()),
        ..target.clone()
    };
    let r = run_text_on(&name, &text, &robot, trace, &target);
    let mut out = r.output;
    if !r.diagnostics.is_empty() {
        out.push_str("-- stderr --\n");
        out.push_str(&r.diagnostics);
    }
    if r.code != 0 {
        out.push_str(&format!("-- exit: {}\n", r.code));
    }
    out
}

/// Whether a program declares tasks or protected objects: those run in the
/// compiled engine only (the reference walker cannot suspend a task), so the
/// differential tests run them once.
pub fn uses_tasks(text: &str) -> bool {
    use crate::syntax::token::{Kw, Token};
    crate::syntax::lexer::lex(text, 0)
        .0
        .iter()
        .any(|t| matches!(t.0, Token::Kw(Kw::Task | Kw::Protected)))
}

/// What a run printed: the program's output (with the motion trace, if asked
/// for, interleaved), the diagnostics without colour, and the exit status.
pub struct RunText {
    pub output: String,
    pub diagnostics: String,
    pub code: i32,
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
    s.machine.input = Box::new(std::io::BufReader::new(std::io::empty()));
    if let Some(e) = target.engine {
        s.machine.engine = e;
    }
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
                s.checker.simulator_only = crate::services::SIMULATOR_ONLY;
                if target.rehearse
                    && let Err((diagnostics, code)) =
                        crate::session::rehearse(&desc, settings, name, text, false)
                {
                    return RunText {
                        output: String::new(),
                        diagnostics,
                        code,
                    };
                }
                let driver =
                    crate::driver::serial::Serial::new(desc.clone(), settings.clone(), None);
                s.set_driver(desc, Box::new(driver), tracer(), false);
            }
        },
        Err(e) => {
            return RunText {
                output: String::new(),
                diagnostics: format!("error: {e:?}\n"),
                code: 2,
            };
        }
    }
    let warned = SharedBuf::default();
    s.warnings_to = Some((Box::new(warned.clone()), false));
    let outcome = s.run_source(name, text);
    let diagnostics = warned.take()
        + &match &outcome {
            Outcome::Ok => String::new(),
            Outcome::CheckFailed(d) => crate::diag::render(d, &s.sources, false),
            Outcome::Raised(d) => crate::diag::render(std::slice::from_ref(d), &s.sources, false),
        };
    RunText {
        output: buf.take(),
        diagnostics,
        code: outcome.exit_code(),
    }
}

/// The expected-output file of a script.
pub fn expected_path(script: &Path) -> PathBuf {
    script.with_extension("out")
}

#[derive(Debug)]
pub enum Verdict {
    Pass,
    Blessed,
    Missing,
    Differs { expected: String, actual: String },
}

pub fn check_case(script: &Path, bless: bool) -> Verdict {
    check_case_on(script, bless, &Target::default())
}

/// [`check_case`] on `target`.
pub fn check_case_on(script: &Path, bless: bool, target: &Target) -> Verdict {
    let actual = run_case_on(script, target);
    let exp_path = expected_path(script);
    if bless {
        let tmp = exp_path.with_extension("out.tmp");
        if std::fs::write(&tmp, &actual)
            .and_then(|_| std::fs::rename(&tmp, &exp_path))
            .is_ok()
        {
            return Verdict::Blessed;
        }
    }
    match std::fs::read_to_string(&exp_path) {
        Ok(expected) if expected == actual => Verdict::Pass,
        Ok(expected) => Verdict::Differs { expected, actual },
        Err(_) => Verdict::Missing,
    }
}

/// All `.air` scripts under the given files and directories, sorted, each
/// once. Directories are walked without looping: one reached again (a
/// symbolic link to an ancestor, `up -> ..`, or to a folder walked
/// already) is not walked again, and a script reached by two paths (a
/// linked folder, a linked file, a folder named twice) counts once, under
/// its path without links when it has one. Links to folders outside are
/// followed, after the folders themselves.
pub fn collect(paths: &[PathBuf]) -> std::io::Result<Vec<PathBuf>> {
    // Scripts found, and whether a link led to them.
    let mut found: Vec<(bool, PathBuf)> = Vec::new();
    let mut real: Vec<PathBuf> = Vec::new();
    let mut linked: Vec<PathBuf> = Vec::new();
    for p in paths {
        if p.is_dir() {
            real.push(p.clone());
        } else if p.exists() {
            found.push((false, p.clone()));
        } else {
            return Err(std::io::Error::new(
                std::io::ErrorKind::NotFound,
                format!("{} does not exist", p.display()),
            ));
        }
    }
    let is_script = |p: &Path| p.extension().is_some_and(|x| x == "air");
    let mut walked = std::collections::HashSet::new();
    // The folders themselves first, then those reached through links.
    while let Some((via_link, d)) = real
        .pop()
        .map(|d| (false, d))
        .or_else(|| linked.pop().map(|d| (true, d)))
    {
        // A link that points nowhere is no folder.
        let Ok(canonical) = std::fs::canonicalize(&d) else {
            continue;
        };
        if !walked.insert(canonical) {
            continue;
        }
        for e in std::fs::read_dir(&d)? {
            let e = e?;
            let path = e.path();
            // The entry itself, not what a link points to.
            let kind = e.file_type()?;
            if kind.is_symlink() {
                if path.is_dir() {
                    linked.push(path);
                } else if is_script(&path) && path.exists() {
                    found.push((true, path));
                }
            } else if kind.is_dir() {
                if via_link {
                    linked.push(path);
                } else {
                    real.push(path);
                }
            } else if is_script(&path) {
                found.push((via_link, path));
            }
        }
    }
    // Each script once: the path without links first.
    found.sort();
    let mut scripts = std::collections::HashSet::new();
    let mut out: Vec<PathBuf> = found
        .into_iter()
        .filter(|(_, p)| scripts.insert(std::fs::canonicalize(p).unwrap_or_else(|_| p.clone())))
        .map(|(_, p)| p)
        .collect();
    out.sort();
    Ok(out)
}

/// A line diff of expected and actual text, for failure reports.
pub fn diff(expected: &str, actual: &str) -> String {
    let (e, a): (Vec<&str>, Vec<&str>) = (expected.lines().collect(), actual.lines().collect());
    let mut out = String::new();
    for i in 0..e.len().max(a.len()) {
        match (e.get(i), a.get(i)) {
            (Some(x), Some(y)) if x == y => {}
            (x, y) => {
                if let Some(x) = x {
                    out.push_str(&format!("{:>4} - {x}\n", i + 1));
                }
                if let Some(y) = y {
                    out.push_str(&format!("{:>4} + {y}\n", i + 1));
                }
            }
        }
    }
    out
}
