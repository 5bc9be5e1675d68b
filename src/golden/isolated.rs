//! `adair test`'s way of running scripts: each in a child process in its
//! own folder with a time limit ([`Isolated`]), `-j` at a time
//! ([`run_all`]), found by walking folders without loops ([`collect`]).

use super::*;

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
    /// Extra environment of the child.
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
