//! One checked text: the checker's state after checking it (with its side
//! tables), its syntax tree as far as it parses, and its diagnostics. Built
//! fresh for each version of a document from a checker that has checked the
//! embedded stdlib once ([`Base`]).

use crate::check::Checker;
use crate::diag::Offsets as _;
use crate::diag::{Diagnostic, FileId, Sources, Span};
use crate::session::{Disk, Frontend, Loader, Mode, NoHost};
use crate::syntax::ast;
use std::path::{Path, PathBuf};
use std::rc::Rc;

/// The checker after the embedded stdlib, cloned for every analysis, and
/// where the stdlib texts are readable by an editor.
#[derive(Clone)]
pub struct Base {
    /// The pipeline after the stdlib (its sources and checker).
    pub front: Frontend,
    /// The file each stdlib source is written to, by source id, so that
    /// "go to definition" can open the AdaIR package (see docs/editors.md).
    pub stdlib_files: Vec<(FileId, PathBuf)>,
    /// The `adair explain` page of each code, written for the editor.
    pub error_pages: std::collections::HashMap<&'static str, PathBuf>,
}

/// Writes `text` to `path` in `dir` unless it holds it already (an editor
/// may have it open); whether the file holds it now.
fn write_if_changed(dir: &Path, path: &Path, text: &str) -> bool {
    std::fs::read_to_string(path).is_ok_and(|t| t == text)
        || (std::fs::create_dir_all(dir).is_ok() && std::fs::write(path, text.as_bytes()).is_ok())
}

impl Base {
    /// Checks the stdlib as every session does. `stdlib_dir`: where its
    /// texts (as checked: with the service declarations generated from the
    /// table) are written for the editor; `None` writes nothing.
    pub fn new(stdlib_dir: Option<&Path>) -> Base {
        let mut front = Frontend::new(Rc::new(Disk), &mut NoHost);
        front.load_stdlib(&mut NoHost);
        let mut stdlib_files = Vec::new();
        for (id, u) in crate::session::STDLIB.iter().enumerate() {
            let Some(dir) = stdlib_dir else { break };
            let file = Path::new(u.name).file_name().unwrap_or_default();
            let path = dir.join(file);
            if write_if_changed(dir, &path, &crate::session::stdlib_text(u.text)) {
                stdlib_files.push((id as FileId, path));
            }
        }
        // The pages of `adair explain`, beside it: a diagnostic's code links
        // to its page.
        let mut error_pages = std::collections::HashMap::new();
        if let Some(dir) = stdlib_dir.and_then(Path::parent).map(|d| d.join("errors")) {
            for e in crate::diag::codes::ALL {
                let path = dir.join(format!("{}.md", e.code));
                if write_if_changed(&dir, &path, e.page) {
                    error_pages.insert(e.code.0, path);
                }
            }
        }
        Base {
            front,
            stdlib_files,
            error_pages,
        }
    }

    /// Where the stdlib files go by default: a directory per adair version
    /// in a folder of the user's own, `adair` under the user's cache
    /// directory (`$XDG_CACHE_HOME`, `~/.cache`), else `adair-UID` under the
    /// temporary directory; each must be a directory (not a link) owned by
    /// this user, and is made private (0700). When neither is, a fresh
    /// private folder under the temporary directory (a name nobody had:
    /// `mkdir` never follows a link); `None` when that fails too (the
    /// stdlib is then served from memory only, and "go to definition" into
    /// it finds nothing).
    pub fn default_stdlib_dir() -> Option<PathBuf> {
        let version = env!("CARGO_PKG_VERSION");
        let absolute = |v: std::ffi::OsString| Some(PathBuf::from(v)).filter(|p| p.is_absolute());
        let cache = std::env::var_os("XDG_CACHE_HOME")
            .and_then(absolute)
            .or_else(|| {
                std::env::var_os("HOME")
                    .and_then(absolute)
                    .map(|h| h.join(".cache"))
            });
        if let Some(dir) = cache.and_then(|c| private_dir(&c.join("adair"), true)) {
            return Some(dir.join(version).join("stdlib"));
        }
        let tmp = std::env::temp_dir();
        let uid = nix::unistd::geteuid();
        if let Some(dir) = private_dir(&tmp.join(format!("adair-{uid}")), false) {
            return Some(dir.join(version).join("stdlib"));
        }
        fresh_private_dir(&tmp).map(|d| d.join("stdlib"))
    }
}

/// `path` as a private folder of this user: created 0700 if missing (and
/// its parents, when `make_parents`: the user's own cache directory); an
/// existing one must be a directory, not a symbolic link, and owned by
/// this user, and loses any permission for others. `None` otherwise: it
/// may be another user's, planted where a shared folder is expected.
fn private_dir(path: &Path, make_parents: bool) -> Option<PathBuf> {
    use std::os::unix::fs::{DirBuilderExt as _, MetadataExt as _, PermissionsExt as _};
    if make_parents && let Some(parent) = path.parent() {
        let _ = std::fs::create_dir_all(parent);
    }
    match std::fs::DirBuilder::new().mode(0o700).create(path) {
        Ok(()) => {}
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {}
        Err(_) => return None,
    }
    let m = std::fs::symlink_metadata(path).ok()?;
    if !m.file_type().is_dir() || m.uid() != nix::unistd::geteuid().as_raw() {
        return None;
    }
    if m.mode() & 0o077 != 0 {
        std::fs::set_permissions(path, std::fs::Permissions::from_mode(0o700)).ok()?;
    }
    Some(path.to_path_buf())
}

/// A new folder under `tmp`, private (0700) from its creation, by a name
/// that did not exist (`adair-UID-PID-N`).
fn fresh_private_dir(tmp: &Path) -> Option<PathBuf> {
    use std::os::unix::fs::DirBuilderExt as _;
    let uid = nix::unistd::geteuid();
    let pid = std::process::id();
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    (0..100u32).find_map(|k| {
        let path = tmp.join(format!("adair-{uid}-{pid}-{nanos:x}{k}"));
        std::fs::DirBuilder::new()
            .mode(0o700)
            .create(&path)
            .ok()
            .map(|()| path)
    })
}

/// A document as checked.
pub struct Analysis {
    pub text: String,
    pub file: FileId,
    pub sources: Sources,
    pub checker: Checker,
    pub unit: Option<ast::CompilationUnit>,
    /// As `adair check` would show them.
    pub diags: Vec<Diagnostic>,
    pub lines: LineIndex,
    /// Whether the checker panicked (a bug; reported as a diagnostic).
    pub crashed: Option<String>,
    /// The files of the `with`ed packages it checked, by source id.
    pub with_files: Vec<(FileId, PathBuf)>,
}

impl Analysis {
    /// Checks `text` (named `name` in messages, at `path` on disk) through
    /// the one pipeline (`Session::check_source`'s), on a copy of the base:
    /// `with`ed units are read through `loader` (the editor's open
    /// documents before the disk).
    pub fn new(
        base: &Base,
        name: &str,
        path: Option<&Path>,
        text: &str,
        loader: Rc<dyn Loader>,
    ) -> Analysis {
        let mut front = base.front.clone();
        front.set_loader(loader);
        let id = front.sources.next_id();
        let checked = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            front.check(name, text.into(), false, Mode::Editor, path, &mut NoHost)
        }));
        let (file, unit, diags, crashed) = match checked {
            Ok(c) => (c.file, c.unit, c.diags, None),
            Err(p) => {
                let msg = p
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_else(|| "panic".into());
                (id, None, Vec::new(), Some(msg))
            }
        };
        let with_files = front.with_files().to_vec();
        Analysis {
            text: text.to_string(),
            file,
            sources: front.sources,
            checker: front.checker,
            unit,
            diags,
            lines: LineIndex::new(text),
            crashed,
            with_files,
        }
    }

    /// The text of a span of any source (the document or the stdlib).
    pub fn span_text(&self, s: Span) -> &str {
        self.sources.text(s.context).get(s.range()).unwrap_or("")
    }
}

/// The editor's open documents, by path, before the disk.
pub struct Open(pub std::collections::HashMap<PathBuf, String>);

impl Loader for Open {
    fn read(&self, path: &Path) -> Option<std::io::Result<String>> {
        match self.0.get(path) {
            Some(t) => Some(Ok(t.clone())),
            None => Disk.read(path),
        }
    }
}

/// Byte offsets <-> LSP positions (line, UTF-16 code units).
#[derive(Clone, Debug)]
pub struct LineIndex {
    starts: Vec<usize>,
}

impl LineIndex {
    pub fn new(text: &str) -> LineIndex {
        let mut starts = vec![0];
        starts.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        LineIndex { starts }
    }

    /// The position of byte `offset` of `text` (clamped to the text).
    pub fn position(&self, text: &str, offset: usize) -> lsp_types::Position {
        let mut offset = offset.min(text.len());
        while !text.is_char_boundary(offset) {
            offset -= 1;
        }
        let line = self.starts.partition_point(|&s| s <= offset) - 1;
        let start = self.starts[line];
        let character: usize = text[start..offset].chars().map(char::len_utf16).sum();
        lsp_types::Position::new(line as u32, character as u32)
    }

    /// The byte offset of a position (clamped to its line and the text).
    pub fn offset(&self, text: &str, p: lsp_types::Position) -> usize {
        let Some(&start) = self.starts.get(p.line as usize) else {
            return text.len();
        };
        let end = self
            .starts
            .get(p.line as usize + 1)
            .map_or(text.len(), |e| e - 1);
        let mut units = 0usize;
        for (i, c) in text[start..end].char_indices() {
            if units >= p.character as usize {
                return start + i;
            }
            units += c.len_utf16();
        }
        end
    }

    pub fn range(&self, text: &str, s: Span) -> lsp_types::Range {
        lsp_types::Range::new(self.position(text, s.lo()), self.position(text, s.hi()))
    }
}
