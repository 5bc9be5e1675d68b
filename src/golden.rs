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
    /// The engine to run in (None: the session's default, `ADAIR_ENGINE`
    /// or the compiled one); the tests run every script in both.
    pub engine: Option<crate::interp::vm::Engine>,
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

/// Seconds a program gets, after its time limit interrupted it, to end and
/// print what it printed; then its process is killed (a child whose parent
/// is gone ends itself one more grace later).
pub const GRACE: Duration = Duration::from_secs(2);

/// The exit status of a child run stopped by its time limit (as `timeout(1)`).
pub const TIMED_OUT_STATUS: i32 = 124;

/// The exit status of a child run that met a configuration error.
pub const CONFIG_STATUS: i32 = 2;

/// Runs scripts as `adair test` does: each in a child process of the
/// `adair` binary (`adair test --child FILE`), in the script's folder, with
/// a time limit.
///
/// A process per script is what makes the folder and the limit dependable:
/// the current directory belongs to a process (scripts in parallel threads
/// would share one), and a script that loops in a way nothing interrupts
/// (a handler that swallows the interrupt, a blocked read) is ended by
/// killing its process. The child stops the program itself at the limit
/// (as Ctrl-C does: a motion on a real arm is stopped, not cut), prints
/// what it printed and exits [`TIMED_OUT_STATUS`]; the parent kills it
/// [`GRACE`] later if it is still there.
#[derive(Clone, Debug)]
pub struct Isolated {
    /// The `adair` binary.
    pub exe: PathBuf,
    /// Global options, before `test` (`--devices /abs/file.toml`).
    pub global: Vec<OsString>,
    /// Options of `test --child` (`--robot R`, `--trace`, `--port ...`).
    pub args: Vec<OsString>,
    /// Environment of the child (`ADAIR_ENGINE=walker` in the project's tests).
    pub env: Vec<(OsString, OsString)>,
    /// The time limit of scripts that set none (seconds, wall clock; 0: none).
    pub timeout: f64,
}

impl Isolated {
    /// Runs the script and compares or blesses its output.
    pub fn check(&self, script: &Path, bless: bool) -> Verdict {
        let text = match std::fs::read_to_string(script) {
            Ok(t) => t,
            Err(e) => {
                return Verdict::Config(format!("adair: cannot read {}: {e}", script.display()));
            }
        };
        let limit = match directives(&text) {
            Ok(d) => d.timeout.unwrap_or(self.timeout),
            Err(e) => return Verdict::Config(format!("adair: {}: {e}", shown_name(script))),
        };
        match self.run(script, limit) {
            Ok(actual) => judge(script, actual, bless),
            Err(v) => v,
        }
    }

    /// The golden text of `script`, or why there is none.
    pub fn run(&self, script: &Path, limit: f64) -> Result<String, Verdict> {
        let dir = match script.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        let mut cmd = std::process::Command::new(&self.exe);
        cmd.args(&self.global)
            .arg("test")
            .arg("--child")
            .args(&self.args)
            .arg("--timeout")
            .arg(limit.to_string())
            .arg("--")
            .arg(script.file_name().unwrap_or(script.as_os_str()))
            .current_dir(dir)
            .stdin(std::process::Stdio::null())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped());
        for (k, v) in &self.env {
            cmd.env(k, v);
        }
        let mut child = cmd
            .spawn()
            .map_err(|e| Verdict::Crashed(format!("cannot start {}: {e}", self.exe.display())))?;
        // Read both pipes while waiting (a full pipe would block the child).
        let drain = |r: Option<Box<dyn std::io::Read + Send>>| {
            std::thread::spawn(move || {
                let mut v = Vec::new();
                if let Some(mut r) = r {
                    let _ = r.read_to_end(&mut v);
                }
                v
            })
        };
        let out = drain(child.stdout.take().map(|r| Box::new(r) as _));
        let err = drain(child.stderr.take().map(|r| Box::new(r) as _));
        let start = Instant::now();
        let hard = (limit > 0.0).then(|| Duration::from_secs_f64(limit) + GRACE);
        let mut nap = Duration::from_millis(1);
        let status = loop {
            match child.try_wait() {
                Ok(Some(s)) => break Some(s),
                Ok(None) if hard.is_some_and(|h| start.elapsed() >= h) => {
                    let _ = child.kill();
                    let _ = child.wait();
                    break None;
                }
                Ok(None) => {
                    std::thread::sleep(nap);
                    nap = (nap * 2).min(Duration::from_millis(20));
                }
                Err(e) => return Err(Verdict::Crashed(format!("waiting for the run: {e}"))),
            }
        };
        let text = |h: std::thread::JoinHandle<Vec<u8>>| {
            String::from_utf8_lossy(&h.join().unwrap_or_default()).into_owned()
        };
        let (out, err) = (text(out), text(err));
        match status.and_then(|s| s.code()) {
            None if status.is_none() => Err(Verdict::TimedOut {
                limit,
                partial: None,
            }),
            Some(0) => Ok(out),
            Some(TIMED_OUT_STATUS) => Err(Verdict::TimedOut {
                limit,
                partial: Some(out),
            }),
            Some(CONFIG_STATUS) => Err(Verdict::Config(err.trim_end().to_string())),
            code => Err(Verdict::Crashed(format!(
                "adair test --child {} ended with {}{}{}",
                shown_name(script),
                code.map_or("a signal".to_string(), |c| format!("exit status {c}")),
                if err.is_empty() { "" } else { ":\n" },
                err.trim_end()
            ))),
        }
    }
}

/// One script's result, for the report.
#[derive(Clone, Debug)]
pub struct CaseResult {
    pub script: PathBuf,
    pub verdict: Verdict,
    /// Wall-clock seconds of its run.
    pub seconds: f64,
}

/// Runs `check` on every script, `jobs` at a time, and gives each result
/// to `report` in the order of `scripts` (a result waits for those before
/// it), as soon as it can.
pub fn run_all(
    scripts: &[PathBuf],
    jobs: usize,
    check: impl Fn(&Path) -> Verdict + Sync,
    mut report: impl FnMut(&CaseResult),
) -> Vec<CaseResult> {
    let jobs = jobs.clamp(1, scripts.len().max(1));
    let next = std::sync::atomic::AtomicUsize::new(0);
    let (tx, rx) = std::sync::mpsc::channel::<(usize, CaseResult)>();
    let mut done: Vec<Option<CaseResult>> = scripts.iter().map(|_| None).collect();
    std::thread::scope(|scope| {
        for _ in 0..jobs {
            let tx = tx.clone();
            let (next, check) = (&next, &check);
            scope.spawn(move || {
                loop {
                    let i = next.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
                    let Some(script) = scripts.get(i) else { break };
                    let start = Instant::now();
                    let verdict = check(script);
                    let r = CaseResult {
                        script: script.clone(),
                        verdict,
                        seconds: start.elapsed().as_secs_f64(),
                    };
                    if tx.send((i, r)).is_err() {
                        break;
                    }
                }
            });
        }
        drop(tx);
        let mut shown = 0;
        for (i, r) in rx {
            done[i] = Some(r);
            while let Some(Some(r)) = done.get(shown) {
                report(r);
                shown += 1;
            }
        }
    });
    done.into_iter().flatten().collect()
}

/// The number of scripts run at once by default: the machine's cores.
pub fn default_jobs() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// ANSI colours of a report on a terminal.
struct Paint(bool);

impl Paint {
    fn wrap(&self, code: &str, text: &str) -> String {
        if self.0 {
            format!("\x1b[{code}m{text}\x1b[0m")
        } else {
            text.to_string()
        }
    }
}

/// The line (and, for a failure, the explanation) `adair test` prints for
/// one script; `paint` colours it for a terminal.
pub fn progress(r: &CaseResult, paint: bool) -> String {
    let p = Paint(paint);
    let shown = r.script.display();
    let time = if r.seconds >= 0.5 {
        format!(" ({:.1} s)", r.seconds)
    } else {
        String::new()
    };
    let exp = expected_path(&r.script);
    let exp_name = shown_name(&exp);
    match &r.verdict {
        Verdict::Pass => format!("{} {shown}{time}\n", p.wrap("32", "ok  ")),
        Verdict::Blessed => format!("{} {shown}{time}\n", p.wrap("33", "blessed")),
        Verdict::Missing { actual } => format!(
            "{} {shown}: no {} (run with --bless to create it); it printed{}",
            p.wrap("1;31", "FAIL"),
            exp.display(),
            if actual.is_empty() {
                " nothing\n".to_string()
            } else {
                format!(":\n{}", indent(actual))
            }
        ),
        Verdict::Differs { expected, actual } => format!(
            "{} {shown}{time}: the output differs from {exp_name}\n{}",
            p.wrap("1;31", "FAIL"),
            diff_with(
                expected,
                actual,
                &exp_name,
                &format!("{}'s output", shown_name(&r.script)),
                paint
            )
        ),
        Verdict::Config(e) => format!(
            "{} {shown}: a configuration error (nothing ran; --bless does not write it):\n{}\n",
            p.wrap("1;31", "FAIL"),
            indent(e).trim_end()
        ),
        Verdict::TimedOut { limit, partial } => format!(
            "{} {shown}: still running after {} s (wall clock), stopped (as Ctrl-C stops a \
             run); a longer limit: --timeout SECONDS, or a first line \
             `-- adair: --timeout SECONDS`{}",
            p.wrap("1;31", "FAIL"),
            limit,
            match partial {
                Some(t) if !t.is_empty() => format!("; it printed:\n{}", indent(t)),
                _ => "\n".into(),
            }
        ),
        Verdict::Crashed(e) => format!("{} {shown}: {}\n", p.wrap("1;31", "FAIL"), e.trim_end()),
    }
}

/// `text` with each line indented by four spaces.
fn indent(text: &str) -> String {
    text.lines().map(|l| format!("    {l}\n")).collect()
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

/// Lines of context around each change in a diff.
const CONTEXT: usize = 3;

/// One line of a diff: in both texts (expected and actual line indices),
/// only in the expected text, or only in the actual one.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Edit {
    Same(usize, usize),
    Gone(usize),
    New(usize),
}

/// The edits from `e` to `a`: a longest common subsequence of lines (the
/// changed middle only, after the common start and end; past about four
/// million line pairs, the middle is shown as removed and added whole).
fn edits(e: &[&str], a: &[&str]) -> Vec<Edit> {
    let pre = e.iter().zip(a).take_while(|(x, y)| x == y).count();
    let suf = e[pre..]
        .iter()
        .rev()
        .zip(a[pre..].iter().rev())
        .take_while(|(x, y)| x == y)
        .count();
    let (em, am) = (&e[pre..e.len() - suf], &a[pre..a.len() - suf]);
    let mut out: Vec<Edit> = (0..pre).map(|i| Edit::Same(i, i)).collect();
    let (n, m) = (em.len(), am.len());
    if n.saturating_mul(m) <= 4_000_000 {
        // lcs[i][j]: the longest common subsequence of em[i..] and am[j..].
        let w = m + 1;
        let mut lcs = vec![0u32; (n + 1) * w];
        for i in (0..n).rev() {
            for j in (0..m).rev() {
                lcs[i * w + j] = if em[i] == am[j] {
                    lcs[(i + 1) * w + j + 1] + 1
                } else {
                    lcs[(i + 1) * w + j].max(lcs[i * w + j + 1])
                };
            }
        }
        let (mut i, mut j) = (0, 0);
        while i < n || j < m {
            if i < n && j < m && em[i] == am[j] {
                out.push(Edit::Same(pre + i, pre + j));
                i += 1;
                j += 1;
            } else if j == m || (i < n && lcs[(i + 1) * w + j] >= lcs[i * w + j + 1]) {
                out.push(Edit::Gone(pre + i));
                i += 1;
            } else {
                out.push(Edit::New(pre + j));
                j += 1;
            }
        }
    } else {
        out.extend((0..n).map(|i| Edit::Gone(pre + i)));
        out.extend((0..m).map(|j| Edit::New(pre + j)));
    }
    out.extend((0..suf).map(|k| Edit::Same(e.len() - suf + k, a.len() - suf + k)));
    out
}

/// A line diff of expected and actual text, for failure reports, without
/// colour: see [`diff_with`].
pub fn diff(expected: &str, actual: &str) -> String {
    diff_with(expected, actual, "", "", false)
}

/// A line diff with a legend (`-` lines are the expected text, named
/// `expected_name`, `+` lines the actual one) and three lines of context
/// around each change, each line with its number in its own text (names
/// left empty: the legend is `--- expected` and `+++ actual`); coloured
/// for a terminal when `paint` (expected red, actual green).
pub fn diff_with(
    expected: &str,
    actual: &str,
    expected_name: &str,
    actual_name: &str,
    paint: bool,
) -> String {
    let p = Paint(paint);
    let (e, a): (Vec<&str>, Vec<&str>) = (expected.lines().collect(), actual.lines().collect());
    let named = |side: &str, name: &str| {
        if name.is_empty() {
            side.to_string()
        } else {
            format!("{side}: {name}")
        }
    };
    let mut out = format!(
        "{}\n{}\n",
        p.wrap("31", &named("--- expected", expected_name)),
        p.wrap("32", &named("+++ actual", actual_name))
    );
    if e != a && e.len() == a.len() && e.iter().zip(&a).all(|(x, y)| x.trim_end() == y.trim_end()) {
        out.push_str("  (the lines differ only in spaces or tabs at their ends)\n");
    }
    let ed = edits(&e, &a);
    // The edits to show: each change with its context.
    let changed: Vec<usize> = (0..ed.len())
        .filter(|&k| !matches!(ed[k], Edit::Same(..)))
        .collect();
    if changed.is_empty() {
        let why = if expected.ends_with('\n') != actual.ends_with('\n') {
            if actual.ends_with('\n') {
                "the expected text has no line end at its end; the output has one"
            } else {
                "the output has no line end at its end; the expected text has one"
            }
        } else {
            "the texts differ in line ends (\\r\\n against \\n)"
        };
        out.push_str(&format!("  (the lines are the same: {why})\n"));
        return out;
    }
    let mut k = 0;
    while k < changed.len() {
        // A hunk: changes closer than twice the context join.
        let first = changed[k];
        let mut last = first;
        while k + 1 < changed.len() && changed[k + 1] - last <= 2 * CONTEXT + 1 {
            k += 1;
            last = changed[k];
        }
        k += 1;
        let (from, to) = (
            first.saturating_sub(CONTEXT),
            (last + CONTEXT + 1).min(ed.len()),
        );
        let (el, al) = ed[from..to]
            .iter()
            .fold((None, None), |(el, al), x| match *x {
                Edit::Same(i, j) => (el.or(Some(i)), al.or(Some(j))),
                Edit::Gone(i) => (el.or(Some(i)), al),
                Edit::New(j) => (el, al.or(Some(j))),
            });
        let at = |x: Option<usize>| x.map_or("-".into(), |x| (x + 1).to_string());
        out.push_str(&p.wrap(
            "36",
            &format!("@@ expected line {}, actual line {} @@", at(el), at(al)),
        ));
        out.push('\n');
        for x in &ed[from..to] {
            match *x {
                Edit::Same(i, _) => out.push_str(&format!("  {:>4} | {}\n", i + 1, e[i])),
                Edit::Gone(i) => {
                    out.push_str(&p.wrap("31", &format!("- {:>4} | {}", i + 1, e[i])));
                    out.push('\n');
                }
                Edit::New(j) => {
                    out.push_str(&p.wrap("32", &format!("+ {:>4} | {}", j + 1, a[j])));
                    out.push('\n');
                }
            }
        }
    }
    out
}

/// Text for an XML document: `&`, `<`, `>`, `"` and `'` escaped, and the
/// characters XML 1.0 cannot hold at all (control characters other than
/// tab, line feed and carriage return; U+FFFE, U+FFFF) written as U+FFFD.
pub fn xml_escape(text: &str) -> String {
    let mut s = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            '\'' => s.push_str("&apos;"),
            '\t' | '\n' => s.push(c),
            '\r' => s.push_str("&#13;"),
            c if (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => s.push('\u{FFFD}'),
            c => s.push(c),
        }
    }
    s
}

/// A JUnit XML report of a run of `adair test` (one `testsuite`, a
/// `testcase` per script named by its file, its folder as `classname`): a
/// failed comparison, a missing `.out` and a time limit are `failure`s, a
/// configuration error or a crashed run an `error`; what the script printed
/// is its `system-out`.
pub fn junit(results: &[CaseResult], suite: &str) -> String {
    let failures = results
        .iter()
        .filter(|r| {
            matches!(
                r.verdict,
                Verdict::Differs { .. } | Verdict::Missing { .. } | Verdict::TimedOut { .. }
            )
        })
        .count();
    let errors = results
        .iter()
        .filter(|r| matches!(r.verdict, Verdict::Config(_) | Verdict::Crashed(_)))
        .count();
    let time: f64 = results.iter().map(|r| r.seconds).sum();
    let mut x = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    x.push_str(&format!(
        "<testsuites name=\"{0}\" tests=\"{1}\" failures=\"{failures}\" errors=\"{errors}\" \
         time=\"{time:.3}\">\n  <testsuite name=\"{0}\" tests=\"{1}\" failures=\"{failures}\" \
         errors=\"{errors}\" skipped=\"0\" time=\"{time:.3}\">\n",
        xml_escape(suite),
        results.len()
    ));
    for r in results {
        let folder = match r.script.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_string_lossy().into_owned(),
            _ => ".".into(),
        };
        x.push_str(&format!(
            "    <testcase classname=\"{}\" name=\"{}\" file=\"{}\" time=\"{:.3}\"",
            xml_escape(&folder),
            xml_escape(&shown_name(&r.script)),
            xml_escape(&r.script.to_string_lossy()),
            r.seconds
        ));
        let element = |kind: &str, ty: &str, message: &str, body: &str| {
            format!(
                "      <{kind} type=\"{ty}\" message=\"{}\">{}</{kind}>\n",
                xml_escape(message),
                xml_escape(body)
            )
        };
        let (inner, printed) = match &r.verdict {
            Verdict::Pass | Verdict::Blessed => (String::new(), None),
            Verdict::Differs { expected, actual } => (
                element(
                    "failure",
                    "differs",
                    &format!(
                        "the output differs from {}",
                        shown_name(&expected_path(&r.script))
                    ),
                    &diff(expected, actual),
                ),
                Some(actual),
            ),
            Verdict::Missing { actual } => (
                element(
                    "failure",
                    "missing",
                    &format!("no {}", shown_name(&expected_path(&r.script))),
                    "",
                ),
                Some(actual),
            ),
            Verdict::TimedOut { limit, partial } => (
                element(
                    "failure",
                    "timeout",
                    &format!("still running after {limit} s (wall clock)"),
                    "",
                ),
                partial.as_ref(),
            ),
            Verdict::Config(e) => (
                element("error", "configuration", "a configuration error", e),
                None,
            ),
            Verdict::Crashed(e) => (element("error", "crashed", "the run failed", e), None),
        };
        if inner.is_empty() && printed.is_none() {
            x.push_str("/>\n");
            continue;
        }
        x.push_str(">\n");
        x.push_str(&inner);
        if let Some(t) = printed {
            x.push_str(&format!(
                "      <system-out>{}</system-out>\n",
                xml_escape(t)
            ));
        }
        x.push_str("    </testcase>\n");
    }
    x.push_str("  </testsuite>\n</testsuites>\n");
    x
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
