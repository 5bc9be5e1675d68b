//! The one check pipeline of adair: a source text in, its checked program
//! and its diagnostics out, for the command line, the REPL and the language
//! server alike. It lexes and parses, finds the units a `with` names (the
//! predefined library, or a file beside the program through a [`Loader`]),
//! checks, adds the "declared in package P" hints, sorts the diagnostics and
//! applies `--strict`.
//!
//! Architecture invariant: the pipeline does no I/O of its own. Files come
//! through the [`Loader`] (the disk for the command line; the editor's open
//! documents first, then the disk, for the language server), and what the
//! engine must do with a checked unit (its source, the predefined library's
//! elaboration) goes to a [`Host`] (a session's machine; nothing in the
//! editor).

use super::{SCRIPT_USES, STDLIB, stdlib_text};
use crate::check::Checker;
use crate::check::ir::{FuncId, Stmt};
use crate::diag::{Diagnostic, FileId, Sources, Span, codes};
use crate::syntax::ast;
use std::path::{Path, PathBuf};
use std::rc::Rc;

/// Where the pipeline reads the files of the packages a program names.
pub trait Loader {
    /// The text of the file at `path`; `None` when there is no such file.
    fn read(&self, path: &Path) -> Option<std::io::Result<String>>;
}

/// The files on disk (`adair run`, `check`, `test`, the REPL).
pub struct Disk;

impl Loader for Disk {
    fn read(&self, path: &Path) -> Option<std::io::Result<String>> {
        path.is_file().then(|| std::fs::read_to_string(path))
    }
}

/// What the engine is told while the pipeline works.
pub trait Host {
    /// A source text was added (the engine shows its lines in messages).
    fn source_added(&mut self, _id: FileId, _name: &str, _text: &str) {}
    /// A unit of the predefined library was checked: its statements
    /// elaborate it (they run once, before anything that uses it).
    fn stdlib_checked(&mut self, _checker: &Checker, _stmts: &[Stmt], _provides: &[&str]) {}
}

/// A host that runs nothing (the language server).
pub struct NoHost;
impl Host for NoHost {}

/// How a text is checked.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Mode {
    /// A program that runs: a long program's bodies are parsed as they are
    /// checked, and its syntax tree is not kept.
    #[default]
    Run,
    /// An editor's document: the syntax tree is kept (hover, completion),
    /// and a text that does not parse whole still gives the names of what
    /// parses before its first error.
    Editor,
}

/// A checked text, whatever its diagnostics.
pub struct Checked {
    pub file: FileId,
    /// The syntax tree (kept in [`Mode::Editor`] only).
    pub unit: Option<ast::CompilationUnit>,
    pub stmts: Vec<Stmt>,
    /// The main subprogram (none for a script).
    pub main: Option<FuncId>,
    /// Sorted by place; with errors, no "never read" warning (often their echo).
    pub diags: Vec<Diagnostic>,
}

impl Checked {
    /// Whether the program may run: no error (and, under `strict`, no warning).
    pub fn passes(&self, strict: bool) -> bool {
        !self.diags.iter().any(|d| !d.is_warning() || strict)
    }
}

/// The sources, the checker's state and the units already loaded. Cloning
/// it snapshots all of them (the language server checks each version of a
/// document on a copy of one that has checked the predefined library).
#[derive(Clone)]
pub struct Frontend {
    pub sources: Sources,
    pub checker: Checker,
    loader: Rc<dyn Loader>,
    /// Which stdlib files are checked (see [`STDLIB`]).
    loaded: Vec<bool>,
    /// A stdlib file is being checked.
    in_stdlib: bool,
    /// Files of packages named by `with` that are loaded (or being loaded).
    with_files: Vec<PathBuf>,
    /// Such a file is being checked (a library unit: never a script).
    in_with_file: bool,
    /// The source ids of those checked.
    with_ids: Vec<(FileId, PathBuf)>,
    /// Their elaboration, to run before the program that names them.
    elaboration: Vec<Stmt>,
}

impl Frontend {
    /// A pipeline with package `Ada` and `Ada.Text_IO` checked.
    pub fn new(loader: Rc<dyn Loader>, host: &mut dyn Host) -> Frontend {
        let mut f = Frontend {
            sources: Sources::default(),
            checker: Checker::new(super::known),
            loader,
            loaded: Vec::new(),
            in_stdlib: false,
            with_files: Vec::new(),
            in_with_file: false,
            with_ids: Vec::new(),
            elaboration: Vec::new(),
        };
        f.checker
            .set_import_profiles(crate::services::import_profile);
        f.load_unit(0, host);
        f
    }

    /// Reads later `with`ed files through `loader` (an editor's documents).
    pub fn set_loader(&mut self, loader: Rc<dyn Loader>) {
        self.loader = loader;
    }

    /// The files of `with`ed packages checked so far, by source id.
    pub fn with_files(&self) -> &[(FileId, PathBuf)] {
        &self.with_ids
    }

    /// Checks the stdlib file `i` (once); the host elaborates it.
    fn load_unit(&mut self, i: usize, host: &mut dyn Host) {
        if self.loaded.len() <= i {
            self.loaded.resize(STDLIB.len(), false);
        }
        if self.loaded[i] {
            return;
        }
        self.loaded[i] = true;
        let u = &STDLIB[i];
        let outer = std::mem::replace(&mut self.in_stdlib, true);
        let text: Rc<str> = stdlib_text(u.text).into();
        // Read in its parsed form (see `syntax::compact`), or parsed if
        // that form does not fit this adair (the test that keeps it fresh
        // says so).
        let checked = self.check_parsed(u.name, text, Some(u.parsed), Mode::Run, host);
        self.in_stdlib = outer;
        if !checked.passes(false) {
            // The embedded library is tested: it checks in a fresh session.
            // Checked later in a session whose program clashes with it, it
            // may not; the program then meets the missing names.
            if i == 0 {
                panic!("stdlib does not check: {:?}", checked.diags);
            }
            return;
        }
        host.stdlib_checked(&self.checker, &checked.stmts, u.provides);
        for pkg in u.provides {
            if matches!(*pkg, "AdaIR" | "Ada.Text_IO") {
                for e in ["Name_Error", "Use_Error", "Data_Error", "End_Error"] {
                    self.checker.export(pkg, e, "Ada.IO_Exceptions");
                }
            }
        }
    }

    /// Whether the stdlib file that declares package `name` is checked.
    pub fn stdlib_loaded(&self, name: &str) -> bool {
        STDLIB
            .iter()
            .position(|u| u.provides.iter().any(|p| p.eq_ignore_ascii_case(name)))
            .is_some_and(|i| self.loaded.get(i).copied().unwrap_or(false))
    }

    /// Makes the package `name` of the stdlib visible to later checks
    /// (nothing when no stdlib file declares it); whether one does.
    pub fn need_package(&mut self, name: &str, host: &mut dyn Host) -> bool {
        let Some(i) = STDLIB
            .iter()
            .position(|u| u.provides.iter().any(|p| p.eq_ignore_ascii_case(name)))
        else {
            return false;
        };
        self.load_unit(i, host);
        true
    }

    /// Checks every stdlib file (scripts, the REPL and the language server
    /// offer all of them).
    pub fn load_stdlib(&mut self, host: &mut dyn Host) {
        for i in 0..STDLIB.len() {
            self.load_unit(i, host);
        }
    }

    /// Checks `text`, shown in messages as `name`. `script`: statements at
    /// the top whatever the text looks like (a REPL entry). `path`: where
    /// the text is, to find the files of the packages it names (`None`:
    /// beside `name`). The statements of the `with`ed files' elaboration
    /// come first in [`Checked::stmts`].
    pub fn check(
        &mut self,
        name: &str,
        text: Rc<str>,
        script: bool,
        mode: Mode,
        path: Option<&Path>,
        host: &mut dyn Host,
    ) -> Checked {
        self.check_with(name, text, script, None, mode, path, host)
    }

    /// [`Frontend::check`] of a stdlib file, whose syntax tree `parsed`
    /// holds (in `syntax::compact`'s form) unless it is `None` or does not
    /// read.
    fn check_parsed(
        &mut self,
        name: &str,
        text: Rc<str>,
        parsed: Option<&[u8]>,
        mode: Mode,
        host: &mut dyn Host,
    ) -> Checked {
        self.check_with(name, text, false, parsed, mode, None, host)
    }

    #[allow(clippy::too_many_arguments)]
    fn check_with(
        &mut self,
        name: &str,
        text: Rc<str>,
        script: bool,
        parsed: Option<&[u8]>,
        mode: Mode,
        path: Option<&Path>,
        host: &mut dyn Host,
    ) -> Checked {
        let id = self.sources.add_shared(name, text.clone());
        let text: &str = &text;
        host.source_added(id, name, text);
        self.checker.add_text(id, self.sources.shared(id));
        let library = self.in_stdlib || self.in_with_file;
        // A long program's bodies are parsed as they are checked (the
        // stdlib's are short; an editor keeps the whole tree).
        let parsed = parsed.and_then(|p| crate::syntax::compact::decode(p, id));
        let (unit, mut diags) = if let Some(unit) = parsed {
            (Some(unit), Vec::new())
        } else if self.in_stdlib || mode == Mode::Editor {
            crate::syntax::parse_source(text, id)
        } else {
            crate::syntax::parse_source_lazy(text, id)
        };
        let mut checked = Checked {
            file: id,
            unit: None,
            stmts: Vec::new(),
            main: None,
            diags: Vec::new(),
        };
        // A text that does not parse as a whole (an editor's, being typed):
        // its names come from what parses before the first error, and the
        // check of that cut has errors of the cut, not the user's.
        let (unit, partial) = match unit {
            Some(u) => (u, false),
            None if mode == Mode::Editor => match parse_what_parses(text, id, &diags) {
                Some(u) => (u, true),
                None => {
                    checked.diags = diags;
                    return checked;
                }
            },
            None => {
                checked.diags = diags;
                return checked;
            }
        };
        use crate::syntax::ast::TopItem;
        let is_script = script || super::is_script_unit(&unit, library);
        // The stdlib files this unit names, and the files of the other
        // packages it names (beside it, unless the unit declares them).
        let dir = path
            .unwrap_or(Path::new(name))
            .parent()
            .unwrap_or(Path::new(""))
            .to_path_buf();
        for item in &unit.items {
            if let TopItem::With(names, _) = item {
                for n in names {
                    let pkg = crate::syntax::parser::expr_text(n);
                    if !self.need_package(&pkg, host)
                        && !self.in_stdlib
                        && !declares_package(&unit, &pkg)
                        && let Err(d) = self.load_with_file(&dir, &pkg, n.span, host)
                    {
                        diags.extend(d);
                    }
                }
            }
        }
        if is_script {
            // A script names any stdlib package without `with`.
            self.load_stdlib(host);
            for p in SCRIPT_USES {
                self.checker.use_everywhere(p);
            }
        }
        // Only the program being run is compiled as it is checked: a unit
        // it names is compiled whole on its first call, from its checked
        // statements.
        let parts = if library {
            self.checker.options.compile_parts.take()
        } else {
            None
        };
        let (stmts, main) = if mode == Mode::Editor {
            self.checker.check_unit(&unit)
        } else {
            self.checker.check_unit_consuming(&unit)
        };
        if parts.is_some() {
            self.checker.options.compile_parts = parts;
        }
        let own = self.checker.take_diags();
        if !partial {
            diags.extend(own);
        }
        if !self.in_stdlib {
            self.hint_packages(&mut diags);
        }
        diags.sort_by_key(|d| (d.span.context, d.span.start));
        // With errors, every diagnostic but a variable "never read": that
        // one is often their echo (its use did not check).
        if diags.iter().any(|d| !d.is_warning()) {
            diags.retain(|d| d.code != codes::W0001);
        }
        checked.diags = diags;
        checked.main = if is_script { None } else { main };
        checked.stmts = stmts;
        // The packages this unit names elaborate first. (A stdlib file
        // elaborates when loaded: not theirs.) In place: the program's
        // statements may be many, theirs are few.
        if !self.in_stdlib && !self.elaboration.is_empty() && checked.passes(false) {
            checked
                .stmts
                .splice(0..0, std::mem::take(&mut self.elaboration));
        }
        if mode == Mode::Editor {
            checked.unit = Some(unit);
        }
        checked
    }

    /// A name from a stdlib package that was not checked (no `with`):
    /// checks the rest of the stdlib on the side to say where it is declared.
    fn hint_packages(&self, diags: &mut [Diagnostic]) {
        // (`X` is not declared; `X` is not declared in `P`: name X, prefix P.)
        let undeclared = |d: &Diagnostic| {
            // A guess from the names in view gives way to the package that
            // declares the name.
            if d.code != codes::E0201 || (d.hint.is_some() && !d.guessed) {
                return None;
            }
            match d.names.as_slice() {
                [n] => Some((n.clone(), None)),
                [n, p] => Some((n.clone(), Some(p.clone()))),
                _ => None,
            }
        };
        if !self.loaded.iter().any(|l| !l) || !diags.iter().any(|d| undeclared(d).is_some()) {
            return;
        }
        // In a fresh pipeline: this one's scope now holds the program's
        // declarations, which the stdlib must not see.
        let mut full = Frontend::new(Rc::new(Disk), &mut NoHost);
        full.load_stdlib(&mut NoHost);
        for d in diags.iter_mut() {
            let hint = match undeclared(d) {
                Some((n, None)) => full.checker.with_hint(&n),
                Some((n, Some(p))) => full.checker.qualified_with_hint(&p, &n),
                None => None,
            };
            if hint.is_some() {
                d.hint = hint;
            }
        }
    }

    /// Checks the file of package `pkg` named by `with` in a program in
    /// `dir`: `pkg.air` (lower case, `-` for `.` as GNAT names files), else
    /// GNAT's `pkg.ads` and `pkg.adb`. Its elaboration joins
    /// [`Frontend::elaboration`]. No file: nothing (the checker says that
    /// no such unit exists).
    fn load_with_file(
        &mut self,
        dir: &Path,
        pkg: &str,
        at: Span,
        host: &mut dyn Host,
    ) -> Result<(), Vec<Diagnostic>> {
        let stem = pkg.to_lowercase().replace('.', "-");
        let loader = self.loader.clone();
        let air = dir.join(format!("{stem}.air"));
        let texts: Vec<(PathBuf, std::io::Result<String>)> = match loader.read(&air) {
            Some(t) => vec![(air, t)],
            None => ["ads", "adb"]
                .iter()
                .map(|e| dir.join(format!("{stem}.{e}")))
                .filter_map(|p| loader.read(&p).map(|t| (p, t)))
                .collect(),
        };
        for (f, text) in texts {
            if self.with_files.contains(&f) {
                continue;
            }
            self.with_files.push(f.clone());
            let shown = shown_path(&f);
            let text = text.map_err(|e| {
                vec![Diagnostic::new(
                    crate::diag::codes::E0203,
                    at,
                    format!("cannot read {shown} (the file of package {pkg}): {e}"),
                )]
            })?;
            let outer = std::mem::replace(&mut self.in_with_file, true);
            let checked = self.check(&shown, text.into(), false, Mode::Run, Some(&f), host);
            self.in_with_file = outer;
            self.with_ids.push((checked.file, f));
            if !checked.passes(false) {
                return Err(checked.diags);
            }
            self.elaboration = checked.stmts;
        }
        Ok(())
    }
}

/// A path as messages show it (`/` between its parts).
fn shown_path(p: &Path) -> String {
    p.to_string_lossy().replace('\\', "/")
}

/// Whether `unit` declares the package `name` itself.
fn declares_package(unit: &ast::CompilationUnit, name: &str) -> bool {
    use crate::syntax::ast::{DeclKind, TopItem};
    unit.items.iter().any(|i| match i {
        TopItem::Decl(d) => match &d.kind {
            DeclKind::PackageSpec(p) => {
                crate::syntax::parser::expr_text(&p.name).eq_ignore_ascii_case(name)
            }
            _ => false,
        },
        _ => false,
    })
}

/// The unit of the longest text before the first syntax error that parses:
/// cut after one of the last `;` before it and, if the cut leaves a body
/// open, closed by a few words (`begin null; end;`, `end;`). Only its names
/// are used (hover, completion, definition); None when no cut parses.
fn parse_what_parses(
    text: &str,
    file: FileId,
    diags: &[Diagnostic],
) -> Option<ast::CompilationUnit> {
    use crate::diag::Offsets as _;
    use crate::syntax::token::Token;
    let first = diags
        .iter()
        .filter(|d| !d.is_warning())
        .map(|d| d.span.start)
        .min()?;
    let (tokens, _) = crate::syntax::lexer::lex(text, file);
    let cuts: Vec<usize> = tokens
        .iter()
        .filter(|(t, s)| *t == Token::Semi && s.end <= first)
        .map(|(_, s)| s.hi())
        .collect();
    const CLOSERS: [&str; 5] = [
        "",
        "\nbegin null; end;",
        "\nnull; end;",
        "\nend;",
        "\nnull; end; end;",
    ];
    for &cut in cuts.iter().rev().take(4) {
        for closer in CLOSERS {
            let t = format!("{}{closer}", &text[..cut]);
            if let (Some(u), _) = crate::syntax::parse_source(&t, file) {
                return Some(u);
            }
        }
    }
    None
}
