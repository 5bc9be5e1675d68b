//! The path system: numbered paths of frames, with the handbook's insert and
//! delete semantics, `MovePath`, and a readable, versioned file format.
//!
//! File format (`SavePathSystem`), one item per line, `--` comments allowed:
//! ```text
//! adair-paths 1
//! path 1
//! pos 1 r11 r12 r13 r14 r21 r22 r23 r24 r31 r32 r33 r34
//! end
//! ```
//! Numbers are written in Rust's shortest round-trip form, so a saved and
//! loaded frame is bit-for-bit the same.

use super::*;

fn path_of(st: &mut RobotState, service: &str, p: i64) -> R<()> {
    if !st.paths.contains_key(&p) {
        return Err(fail(
            st,
            service,
            Exc::PathNotDefined,
            format!("path {p} is not defined (CreatePath ({p}) first)"),
        ));
    }
    Ok(())
}

pub fn create_path(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let p = a[0].int();
    require_init(cx, st, "CreatePath")?;
    if st.paths.contains_key(&p) {
        return Err(fail(
            st,
            "CreatePath",
            Exc::PathAlreadyDefined,
            format!("path {p} is already defined"),
        ));
    }
    st.paths.insert(p, Vec::new());
    Ok(None)
}

pub fn delete_path(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let p = a[0].int();
    require_init(cx, st, "DeletePath")?;
    path_of(st, "DeletePath", p)?;
    st.paths.remove(&p);
    Ok(None)
}

/// Inserts before position N; an N beyond the end appends as last + 1.
pub fn insert_position(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let (p, n, f) = (a[0].int(), a[1].int(), frame_rows(&a[2]));
    require_init(cx, st, "InsertPosition")?;
    path_of(st, "InsertPosition", p)?;
    if let Err(e) = Pose::from_rows(f).check_rigid("position") {
        return Err(kin_fail(st, "InsertPosition", &e));
    }
    let path = st.paths.entry(p).or_default();
    let i = ((n - 1) as usize).min(path.len());
    path.insert(i, f);
    Ok(None)
}

fn position_index(st: &mut RobotState, service: &str, p: i64, n: i64) -> R<usize> {
    path_of(st, service, p)?;
    let len = st.paths.get(&p).map(Vec::len).unwrap_or(0);
    if n < 1 || n as usize > len {
        return Err(fail(
            st,
            service,
            Exc::PathElementNotDefined,
            format!("path {p} has {len} position(s), there is no position {n}"),
        ));
    }
    Ok(n as usize - 1)
}

pub fn delete_position(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let (p, n) = (a[0].int(), a[1].int());
    require_init(cx, st, "DeletePosition")?;
    let i = position_index(st, "DeletePosition", p, n)?;
    if let Some(path) = st.paths.get_mut(&p) {
        path.remove(i);
    }
    Ok(None)
}

pub fn value_position(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let (p, n) = (a[0].int(), a[1].int());
    require_init(cx, st, "ValuePosition")?;
    let i = position_index(st, "ValuePosition", p, n)?;
    let f = st.paths[&p][i];
    a[2] = frame_value(&Pose::from_rows(f));
    Ok(None)
}

/// Moves through every position; all are solved before the first joint moves.
pub fn move_path(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let p = a[0].int();
    let o = opts(a, 1);
    require_motion(cx, st, "MovePath", &o)?;
    path_of(st, "MovePath", p)?;
    let frames = st.paths[&p].clone();
    if frames.is_empty() {
        return Err(fail(
            st,
            "MovePath",
            Exc::PathElementNotDefined,
            format!("path {p} has no positions"),
        ));
    }
    let mut from = st.robot.joints();
    let start = from;
    let mut all: Vec<Joints> = Vec::new();
    for (k, f) in frames.iter().enumerate() {
        match frame_motion(st, &from, &Pose::from_rows(*f)) {
            Ok(pts) => {
                from = pts[pts.len() - 1];
                all.extend(pts);
            }
            Err(e) => {
                let msg = format!("position {} of path {p}: {e}", k + 1);
                return Err(fail(st, "MovePath", e.exception().into(), msg));
            }
        }
    }
    let d = path_duration(
        st,
        &start,
        &all,
        if o.time.is_some() { 100.0 } else { st.velocity },
    );
    let d = match o.time {
        Some(t) if t + 1e-9 < d => {
            return Err(fail(
                st,
                "MovePath",
                Exc::TimeInvalid,
                format!("Time => {t:.3} s is shorter than the fastest run of path {p}, {d:.3} s"),
            ));
        }
        Some(t) => t,
        None => d,
    };
    perform(cx, st, "MovePath", &all, d, &o)?;
    Ok(None)
}

fn io_error(st: &mut RobotState, service: &str, exc: Exc, msg: String) -> ServiceFault {
    fail(st, service, exc, msg)
}

pub fn save_path_system(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let name = a[0].text();
    require_init(cx, st, "SavePathSystem")?;
    let mut text = String::from("adair-paths 1\n");
    for (p, frames) in &st.paths {
        text.push_str(&format!("path {p}\n"));
        for (k, f) in frames.iter().enumerate() {
            text.push_str(&format!("pos {}", k + 1));
            for row in f {
                for x in row {
                    text.push_str(&format!(" {x:?}"));
                }
            }
            text.push('\n');
        }
        text.push_str("end\n");
    }
    // Write a temporary file, then rename: never a half-written file.
    let target = std::path::Path::new(&name);
    if name.is_empty() || target.file_name().is_none() {
        return Err(io_error(
            st,
            "SavePathSystem",
            Exc::NameError,
            format!("\"{name}\" is not a file name"),
        ));
    }
    if let Some(dir) = target.parent().filter(|d| !d.as_os_str().is_empty())
        && !dir.is_dir()
    {
        return Err(io_error(
            st,
            "SavePathSystem",
            Exc::NameError,
            format!("the directory {} does not exist", dir.display()),
        ));
    }
    let tmp = tmp_path(target);
    let res = std::fs::write(&tmp, text.as_bytes()).and_then(|_| std::fs::rename(&tmp, target));
    if let Err(e) = res {
        let _ = std::fs::remove_file(&tmp);
        return Err(io_error(
            st,
            "SavePathSystem",
            Exc::UseError,
            format!("cannot write {name}: {e}"),
        ));
    }
    Ok(None)
}

/// Parses a path file completely; nothing is loaded unless all of it is good.
/// Paths read from a file: number and frames (rows).
type PathList = Vec<(i64, Vec<[[f64; 4]; 3]>)>;

fn parse(text: &str) -> Result<PathList, (usize, String)> {
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.split("--").next().unwrap_or("").trim()))
        .filter(|(_, l)| !l.is_empty());
    match lines.next() {
        Some((_, "adair-paths 1")) => {}
        Some((n, l)) => {
            return Err((
                n,
                format!("expected the version line `adair-paths 1`, found `{l}`"),
            ));
        }
        None => return Err((1, "the file is empty; expected `adair-paths 1`".into())),
    }
    let mut out: PathList = Vec::new();
    let mut current: Option<(i64, Vec<[[f64; 4]; 3]>)> = None;
    for (n, l) in lines {
        let words: Vec<&str> = l.split_whitespace().collect();
        match words.as_slice() {
            ["path", num] => {
                if current.is_some() {
                    return Err((
                        n,
                        "`path` inside a path: close the previous one with `end`".into(),
                    ));
                }
                let p: i64 = num
                    .parse()
                    .map_err(|_| (n, format!("`{num}` is not a path number")))?;
                if !(1..=65000).contains(&p) {
                    return Err((n, format!("path number {p} is outside 1 .. 65000")));
                }
                if out.iter().any(|(q, _)| *q == p) {
                    return Err((n, format!("path {p} appears twice")));
                }
                current = Some((p, Vec::new()));
            }
            ["pos", num, rest @ ..] => {
                let Some((_, frames)) = current.as_mut() else {
                    return Err((n, "`pos` outside a path".into()));
                };
                let k: usize = num
                    .parse()
                    .map_err(|_| (n, format!("`{num}` is not a position number")))?;
                if k != frames.len() + 1 {
                    return Err((
                        n,
                        format!("position {k} out of order (expected {})", frames.len() + 1),
                    ));
                }
                if rest.len() != 12 {
                    return Err((
                        n,
                        format!(
                            "a position has 12 numbers (3 rows of 4), this one has {}",
                            rest.len()
                        ),
                    ));
                }
                let mut f = [[0.0; 4]; 3];
                for (i, w) in rest.iter().enumerate() {
                    let x: f64 = w
                        .parse()
                        .map_err(|_| (n, format!("`{w}` is not a number")))?;
                    if !x.is_finite() {
                        return Err((n, format!("`{w}` is not a finite number")));
                    }
                    f[i / 4][i % 4] = x;
                }
                if let Err(e) = Pose::from_rows(f).check_rigid("position") {
                    return Err((n, format!("position {k}: {e}")));
                }
                frames.push(f);
            }
            ["end"] => match current.take() {
                Some(p) => out.push(p),
                None => return Err((n, "`end` without `path`".into())),
            },
            _ => return Err((n, format!("cannot read `{l}`"))),
        }
    }
    if let Some((p, _)) = current {
        return Err((text.lines().count(), format!("path {p} has no `end`")));
    }
    Ok(out)
}

pub fn load_path_system(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let name = a[0].text();
    require_init(cx, st, "LoadPathSystem")?;
    let text = match std::fs::read(&name) {
        Ok(bytes) => match String::from_utf8(bytes) {
            Ok(t) => t,
            Err(e) => {
                // Malformed content: Data_Error, naming the line.
                let good = &e.as_bytes()[..e.utf8_error().valid_up_to()];
                let line = good.iter().filter(|b| **b == b'\n').count() + 1;
                return Err(io_error(
                    st,
                    "LoadPathSystem",
                    Exc::DataError,
                    format!("{name}:{line}: not UTF-8 text (a path file is text)"),
                ));
            }
        },
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Err(io_error(
                st,
                "LoadPathSystem",
                Exc::NameError,
                format!("no file {name}"),
            ));
        }
        Err(e) => {
            return Err(io_error(
                st,
                "LoadPathSystem",
                Exc::UseError,
                format!("cannot read {name}: {e}"),
            ));
        }
    };
    let paths = match parse(&text) {
        Ok(p) => p,
        Err((line, msg)) => {
            return Err(io_error(
                st,
                "LoadPathSystem",
                Exc::DataError,
                format!("{name}:{line}: {msg}"),
            ));
        }
    };
    if let Some((p, _)) = paths.iter().find(|(p, _)| st.paths.contains_key(p)) {
        let p = *p;
        return Err(fail(
            st,
            "LoadPathSystem",
            Exc::PathAlreadyDefined,
            format!("{name} defines path {p}, which is already defined; nothing was loaded"),
        ));
    }
    for (p, frames) in paths {
        st.paths.insert(p, frames);
    }
    Ok(None)
}

/// The file a save writes before renaming it over `target`: the target's
/// whole name plus `.adair-tmp`, so two targets never share one, and a save
/// killed half-way leaves a file that the next save of that target
/// overwrites and renames away.
pub(crate) fn tmp_path(target: &std::path::Path) -> std::path::PathBuf {
    let mut name = target.as_os_str().to_owned();
    name.push(".adair-tmp");
    std::path::PathBuf::from(name)
}
