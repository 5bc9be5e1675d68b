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

/// One position of a path: the frame's three rows.
pub type Frame = [[f64; 4]; 3];

/// The most positions one path holds: `PosNo'Last` (handbook: `subtype
/// PosNo is POSITIVE range 1..65000`), so every position has a number.
pub const MAX_POSITIONS: usize = 65_000;

/// The most positions all paths hold together (the handbook gives no
/// figure for its path memory; this one is ours, about 96 MB of frames,
/// see docs/differences.md). Past either limit a service raises
/// `PathMemOverflow` and changes nothing.
pub const MAX_TOTAL_POSITIONS: usize = 1_000_000;

/// Frames per block of a [`Positions`] list before it is split in two.
const BLOCK: usize = 512;

/// The positions of one path, in order: a list of blocks of at most
/// `2 * BLOCK` frames, so inserting or deleting anywhere moves at most one
/// block and walks the block lengths (65,000 positions: about 130 blocks),
/// never the whole path.
#[derive(Clone, Debug, Default)]
pub struct Positions {
    blocks: Vec<Vec<Frame>>,
    len: usize,
}

impl Positions {
    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The block and the place in it of position index `i` (`i < len`),
    /// or of the end for `i == len`.
    fn locate(&self, mut i: usize) -> (usize, usize) {
        for (b, block) in self.blocks.iter().enumerate() {
            if i < block.len() {
                return (b, i);
            }
            i -= block.len();
        }
        let last = self.blocks.len().saturating_sub(1);
        (last, self.blocks.get(last).map_or(0, Vec::len) + i)
    }

    pub fn get(&self, i: usize) -> Option<&Frame> {
        if i >= self.len {
            return None;
        }
        let (b, k) = self.locate(i);
        Some(&self.blocks[b][k])
    }

    /// Inserts `f` before index `i`; `i >= len` appends.
    pub fn insert(&mut self, i: usize, f: Frame) {
        let i = i.min(self.len);
        if self.blocks.is_empty() {
            self.blocks.push(Vec::with_capacity(BLOCK));
        }
        let (b, k) = self.locate(i);
        let block = &mut self.blocks[b];
        block.insert(k, f);
        if block.len() > 2 * BLOCK {
            let tail = block.split_off(BLOCK);
            self.blocks.insert(b + 1, tail);
        }
        self.len += 1;
    }

    pub fn push(&mut self, f: Frame) {
        self.insert(self.len, f);
    }

    /// Removes and returns the frame at index `i` (`i < len`).
    pub fn remove(&mut self, i: usize) -> Frame {
        let (b, k) = self.locate(i);
        let f = self.blocks[b].remove(k);
        self.len -= 1;
        // A small block joins its neighbour, so the blocks stay few.
        if self.blocks[b].is_empty() {
            self.blocks.remove(b);
        } else if self.blocks[b].len() < BLOCK / 2
            && b + 1 < self.blocks.len()
            && self.blocks[b].len() + self.blocks[b + 1].len() <= 2 * BLOCK
        {
            let next = self.blocks.remove(b + 1);
            self.blocks[b].extend(next);
        }
        f
    }

    pub fn iter(&self) -> impl Iterator<Item = &Frame> {
        self.blocks.iter().flatten()
    }
}

impl FromIterator<Frame> for Positions {
    fn from_iter<I: IntoIterator<Item = Frame>>(it: I) -> Positions {
        let mut p = Positions::default();
        for f in it {
            p.push(f);
        }
        p
    }
}

/// All paths, by number, and how many positions they hold together.
#[derive(Clone, Debug, Default)]
pub struct PathMem {
    paths: BTreeMap<i64, Positions>,
    total: usize,
}

/// Why a position cannot be stored: the message of `PathMemOverflow`.
pub type Overflow = String;

impl PathMem {
    pub fn contains_key(&self, p: &i64) -> bool {
        self.paths.contains_key(p)
    }

    pub fn get(&self, p: &i64) -> Option<&Positions> {
        self.paths.get(p)
    }

    /// Positions over all paths.
    pub fn total(&self) -> usize {
        self.total
    }

    /// Creates path `p` empty (it must not exist).
    pub fn create(&mut self, p: i64) {
        self.paths.entry(p).or_default();
    }

    pub fn remove(&mut self, p: &i64) {
        if let Some(old) = self.paths.remove(p) {
            self.total -= old.len();
        }
    }

    pub fn iter(&self) -> impl Iterator<Item = (&i64, &Positions)> {
        self.paths.iter()
    }

    /// Whether `more` positions fit into path `p` (now `len` long) and the
    /// whole memory; the message of `PathMemOverflow` when not.
    fn room(&self, p: i64, len: usize, more: usize) -> Result<(), Overflow> {
        if len + more > MAX_POSITIONS {
            return Err(format!(
                "path {p} is full: it holds {len} positions, PosNo'Last"
            ));
        }
        if self.total + more > MAX_TOTAL_POSITIONS {
            return Err(format!(
                "the path memory holds {} position(s) over all paths, its limit is {MAX_TOTAL_POSITIONS}",
                self.total
            ));
        }
        Ok(())
    }

    /// Inserts `f` into path `p` (created when missing) before index `i`;
    /// `i` beyond the end appends. The index it got, or why it did not fit
    /// (then nothing changed).
    pub fn insert(&mut self, p: i64, i: usize, f: Frame) -> Result<usize, Overflow> {
        let len = self.paths.get(&p).map_or(0, Positions::len);
        self.room(p, len, 1)?;
        let path = self.paths.entry(p).or_default();
        let i = i.min(path.len());
        path.insert(i, f);
        self.total += 1;
        Ok(i)
    }

    /// Removes index `i` of path `p` (both must exist).
    pub fn delete(&mut self, p: i64, i: usize) {
        if let Some(path) = self.paths.get_mut(&p)
            && i < path.len()
        {
            path.remove(i);
            self.total -= 1;
        }
    }

    /// Adds the paths read from a file (none of them defined here), all
    /// or, when they do not fit, none.
    pub fn load(&mut self, paths: PathList) -> Result<(), Overflow> {
        let more: usize = paths.iter().map(|(_, f)| f.len()).sum();
        if self.total + more > MAX_TOTAL_POSITIONS {
            return Err(format!(
                "the file holds {more} position(s) and the path memory {} over all paths, its limit is {MAX_TOTAL_POSITIONS}",
                self.total
            ));
        }
        for (p, frames) in paths {
            self.total += frames.len();
            self.paths.insert(p, frames.into_iter().collect());
        }
        Ok(())
    }
}

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
    st.paths.create(p);
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
    if let Err(msg) = st.paths.insert(p, (n - 1) as usize, f) {
        return Err(fail(st, "InsertPosition", Exc::PathMemOverflow, msg));
    }
    Ok(None)
}

fn position_index(st: &mut RobotState, service: &str, p: i64, n: i64) -> R<usize> {
    path_of(st, service, p)?;
    let len = st.paths.get(&p).map_or(0, Positions::len);
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
    st.paths.delete(p, i);
    Ok(None)
}

pub fn value_position(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let (p, n) = (a[0].int(), a[1].int());
    require_init(cx, st, "ValuePosition")?;
    let i = position_index(st, "ValuePosition", p, n)?;
    let Some(&f) = st.paths.get(&p).and_then(|path| path.get(i)) else {
        unreachable!("position_index checked path {p} position {n}")
    };
    a[2] = frame_value(&Pose::from_rows(f));
    Ok(None)
}

/// Moves through every position; all are solved before the first joint moves.
pub fn move_path(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let p = a[0].int();
    let o = opts(a, 1);
    require_motion(cx, st, "MovePath", &o)?;
    path_of(st, "MovePath", p)?;
    let frames: Vec<Frame> = st
        .paths
        .get(&p)
        .into_iter()
        .flat_map(Positions::iter)
        .copied()
        .collect();
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
    for (p, frames) in st.paths.iter() {
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
    if let Err((exc, msg)) = write_whole(std::path::Path::new(&name), text.as_bytes()) {
        return Err(io_error(st, "SavePathSystem", exc, msg));
    }
    Ok(None)
}

/// Parses a path file completely; nothing is loaded unless all of it is good.
/// Paths read from a file: number and frames (rows).
pub type PathList = Vec<(i64, Vec<Frame>)>;

pub(crate) fn parse(text: &str) -> Result<PathList, (usize, String)> {
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
    let mut current: Option<(i64, Vec<Frame>)> = None;
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
                if k > MAX_POSITIONS {
                    return Err((
                        n,
                        format!("position {k} is outside PosNo 1 .. {MAX_POSITIONS}"),
                    ));
                }
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
    let bytes = match read_whole(std::path::Path::new(&name)) {
        Ok(b) => b,
        Err((exc, msg)) => return Err(io_error(st, "LoadPathSystem", exc, msg)),
    };
    let text = match String::from_utf8(bytes) {
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
    if let Err(msg) = st.paths.load(paths) {
        let msg = format!("{name}: {msg}; nothing was loaded");
        return Err(fail(st, "LoadPathSystem", Exc::PathMemOverflow, msg));
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

/// Why a file cannot be written or read: the Ada exception
/// (`Name_Error`, `Use_Error`) and the message.
pub(crate) type FileFault = (Exc, String);

/// What a file that is not a regular file is, for a message.
pub(crate) fn not_a_file(kind: &std::fs::FileType) -> Option<&'static str> {
    use std::os::unix::fs::FileTypeExt;
    Some(if kind.is_file() {
        return None;
    } else if kind.is_dir() {
        "a directory"
    } else if kind.is_fifo() {
        "a FIFO (named pipe)"
    } else if kind.is_char_device() {
        "a character device"
    } else if kind.is_block_device() {
        "a block device"
    } else if kind.is_socket() {
        "a socket"
    } else {
        "a symbolic link"
    })
}

/// The file a name stands for: the name itself, or the end of the chain of
/// symbolic links it starts (which need not exist yet).
fn resolve_links(name: &std::path::Path) -> Result<std::path::PathBuf, FileFault> {
    let mut p = name.to_path_buf();
    // Linux's own limit on links followed in one lookup.
    for _ in 0..40 {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = std::fs::read_link(&p).map_err(|e| {
                    (
                        Exc::UseError,
                        format!("cannot read the link {}: {e}", p.display()),
                    )
                })?;
                p = match p.parent() {
                    Some(dir) if to.is_relative() => dir.join(to),
                    _ => to,
                };
            }
            _ => return Ok(p),
        }
    }
    Err((
        Exc::UseError,
        format!("{}: too many levels of symbolic links", name.display()),
    ))
}

/// Writes `bytes` as the whole new content of the file `name`, never
/// leaving a half-written file: a temporary file beside it, then a rename
/// over it. Only a regular file is replaced: a symbolic link is written
/// through (its target is replaced, the link stays); a directory, FIFO,
/// device or socket is `Use_Error` before anything is written, and so is a
/// file without write permission (also for root: a file with no write bit
/// is read-only to adair). The new file keeps the old one's permissions,
/// and its owner and group where this user may give them (root may).
/// Used by `SavePathSystem`, `--record` and `--plot`.
pub(crate) fn write_whole(name: &std::path::Path, bytes: &[u8]) -> Result<(), FileFault> {
    use std::io::Write as _;
    use std::os::unix::fs::{MetadataExt as _, OpenOptionsExt as _, PermissionsExt as _};
    if name.as_os_str().is_empty() || name.file_name().is_none() {
        return Err((
            Exc::NameError,
            format!("\"{}\" is not a file name", name.display()),
        ));
    }
    let target = resolve_links(name)?;
    let shown = if target == name {
        name.display().to_string()
    } else {
        format!(
            "{} (where the link {} points)",
            target.display(),
            name.display()
        )
    };
    let old = match std::fs::symlink_metadata(&target) {
        Ok(m) => Some(m),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => None,
        Err(e) => return Err((Exc::UseError, format!("cannot write {shown}: {e}"))),
    };
    match &old {
        Some(m) => {
            if let Some(kind) = not_a_file(&m.file_type()) {
                return Err((
                    Exc::UseError,
                    format!("cannot write {shown}: it is {kind}, not a regular file"),
                ));
            }
            let no_write_bit = m.permissions().mode() & 0o222 == 0;
            if no_write_bit || nix::unistd::access(&target, nix::unistd::AccessFlags::W_OK).is_err()
            {
                return Err((
                    Exc::UseError,
                    format!("cannot write {shown}: the file is not writable (no write permission)"),
                ));
            }
        }
        None => {
            if let Some(dir) = target.parent().filter(|d| !d.as_os_str().is_empty())
                && !dir.is_dir()
            {
                return Err((
                    Exc::NameError,
                    format!(
                        "the directory {} does not exist{}",
                        dir.display(),
                        relative_note(dir)
                    ),
                ));
            }
        }
    }
    let mode = old.as_ref().map(|m| m.permissions().mode() & 0o777);
    let owner = old.as_ref().map(|m| (m.uid(), m.gid()));
    let tmp = tmp_path(&target);
    // A killed save's temporary (or anything else but a directory there)
    // is removed, never written through; the new one is created afresh.
    if std::fs::symlink_metadata(&tmp).is_ok_and(|m| !m.is_dir()) {
        let _ = std::fs::remove_file(&tmp);
    }
    let mut created = false;
    let res = (|| {
        let mut f = std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .mode(mode.unwrap_or(0o666))
            .open(&tmp)?;
        created = true;
        f.write_all(bytes)?;
        if let Some((uid, gid)) = owner {
            // The old file's owner and group, where this user may give them
            // (root may: a file of another user stays theirs).
            let _ = std::os::unix::fs::fchown(&f, Some(uid), Some(gid));
        }
        if let Some(mode) = mode {
            // Created under the umask: the old file's bits exactly.
            f.set_permissions(std::fs::Permissions::from_mode(mode))?;
        }
        f.sync_all()?;
        drop(f);
        std::fs::rename(&tmp, &target)
    })();
    if let Err(e) = res {
        if created {
            let _ = std::fs::remove_file(&tmp);
        }
        return Err((Exc::UseError, format!("cannot write {shown}: {e}")));
    }
    Ok(())
}

/// The whole content of the regular file `name` (through symbolic links).
/// Never blocks: a FIFO, device, socket or directory is `Use_Error`
/// before it is opened, and the open itself does not wait
/// (`O_NONBLOCK`). No such file: `Name_Error`.
pub(crate) fn read_whole(name: &std::path::Path) -> Result<Vec<u8>, FileFault> {
    use std::io::Read as _;
    use std::os::unix::fs::OpenOptionsExt as _;
    let refuse = |m: &std::fs::Metadata| match not_a_file(&m.file_type()) {
        Some(kind) => Err((
            Exc::UseError,
            format!(
                "cannot read {}: it is {kind}, not a regular file",
                name.display()
            ),
        )),
        None => Ok(()),
    };
    let cannot = |e: std::io::Error| match e.kind() {
        std::io::ErrorKind::NotFound => (
            Exc::NameError,
            format!("no file {}{}", name.display(), relative_note(name)),
        ),
        _ => (
            Exc::UseError,
            format!("cannot read {}: {e}", name.display()),
        ),
    };
    refuse(&std::fs::metadata(name).map_err(cannot)?)?;
    // The file may have been swapped since: the open does not wait, and
    // what was opened is looked at again.
    let mut f = std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(nix::libc::O_NONBLOCK | nix::libc::O_NOCTTY)
        .open(name)
        .map_err(cannot)?;
    refuse(&f.metadata().map_err(cannot)?)?;
    let mut bytes = Vec::new();
    f.read_to_end(&mut bytes).map_err(cannot)?;
    Ok(bytes)
}

/// For a relative name in a `Name_Error`: where it was looked up (a script
/// run from another folder looks for its files there, not beside itself).
fn relative_note(name: &std::path::Path) -> &'static str {
    if name.is_relative() {
        " (a relative name: looked up in the current directory)"
    } else {
        ""
    }
}
