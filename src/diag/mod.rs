//! The one diagnostic type of adair and its one renderer (ariadne).
//!
//! Phases build `Diagnostic`s through named constructors and never print;
//! only the CLI and the REPL call [`render`].

use std::fmt::Write as _;

pub mod codes;
pub use codes::Code;

/// Identifies one source text (a file, a stdlib unit or a REPL entry).
pub type FileId = u32;

/// Byte offsets into one source, with the source's id: the same type is used by
/// the lexer, chumsky, the checker, the interpreter and ariadne. The offsets
/// are `u32` (12 bytes a span, not 24: the syntax tree, the checked program
/// and the compiled code hold one per node); a source is at most 4 GiB.
pub type Span = chumsky::span::SimpleSpan<u32, FileId>;

pub fn span(file: FileId, start: usize, end: usize) -> Span {
    Span {
        start: offset(start),
        end: offset(end),
        context: file,
    }
}

/// A byte offset as a span keeps it (saturating past 4 GiB).
pub fn offset(i: usize) -> u32 {
    u32::try_from(i).unwrap_or(u32::MAX)
}

/// A span's offsets as indices into its text.
pub trait Offsets {
    fn lo(&self) -> usize;
    fn hi(&self) -> usize;
    fn range(&self) -> std::ops::Range<usize> {
        self.lo()..self.hi()
    }
}

impl Offsets for Span {
    fn lo(&self) -> usize {
        self.start as usize
    }
    fn hi(&self) -> usize {
        self.end as usize
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    Lexical,
    Syntax,
    Name,
    Type,
    Unsupported,
    Runtime,
    /// Not an error: the program still runs (unless `--strict`).
    Warning,
}

impl Phase {
    /// The phase a code belongs to (see [`codes`] for the ranges).
    pub fn of(code: Code) -> Phase {
        let c = code.0.as_bytes();
        match (c.first(), c.get(2)) {
            (Some(b'W'), _) => Phase::Warning,
            (_, Some(b'0')) => Phase::Lexical,
            (_, Some(b'1')) => Phase::Syntax,
            (_, Some(b'2')) => Phase::Name,
            (_, Some(b'7')) => Phase::Unsupported,
            (_, Some(b'9')) => Phase::Runtime,
            _ => Phase::Type,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    /// What kind of fault this is, stable across versions (`adair explain`).
    pub code: Code,
    pub phase: Phase,
    pub message: String,
    pub span: Span,
    pub label: String,
    pub hint: Option<String>,
    /// Secondary places (for example the call chain of an exception).
    pub notes: Vec<(Span, String)>,
    /// The names the message is about, for tools (E0201: the name, then
    /// the package it was looked up in, if any).
    pub names: Vec<String>,
    /// Whether the hint is a guess from the spelling (`did you mean`),
    /// which a better hint replaces.
    pub guessed: bool,
}

impl Diagnostic {
    /// A diagnostic of kind `code`; its phase follows from the code.
    pub fn new(code: Code, span: Span, message: impl Into<String>) -> Self {
        Diagnostic {
            code,
            phase: Phase::of(code),
            message: message.into(),
            span,
            label: String::new(),
            hint: None,
            notes: Vec::new(),
            names: Vec::new(),
            guessed: false,
        }
    }
    /// The names the message is about (see [`Diagnostic::names`]).
    pub fn about(mut self, names: &[&str]) -> Self {
        self.names = names.iter().map(|n| n.to_string()).collect();
        self
    }
    /// A hint guessed from the spelling (see [`Diagnostic::guessed`]).
    pub fn with_guess(mut self, hint: impl Into<String>) -> Self {
        self.hint = Some(hint.into());
        self.guessed = true;
        self
    }
    pub fn with_label(mut self, label: impl Into<String>) -> Self {
        self.label = label.into();
        self
    }
    pub fn with_hint(mut self, hint: impl Into<String>) -> Self {
        self.hint = Some(hint.into());
        self
    }
    pub fn with_note(mut self, span: Span, text: impl Into<String>) -> Self {
        self.notes.push((span, text.into()));
        self
    }

    // --- transitional: each phase's `diagnostics.rs` replaces these ---
    pub fn syntax(span: Span, message: impl Into<String>) -> Self {
        Self::new(codes::E0101, span, message)
    }
    pub fn unsupported(span: Span, what: &str) -> Self {
        Self::new(
            codes::E0701,
            span,
            format!("{what} is not supported by AdaIR"),
        )
        .with_label("outside the AdaIR subset")
        .with_hint("see docs/differences.md for the supported subset of Ada 2012")
    }
    pub fn name(span: Span, message: impl Into<String>) -> Self {
        Self::new(codes::E0201, span, message)
    }
    pub fn ty(span: Span, message: impl Into<String>) -> Self {
        Self::new(codes::E0301, span, message)
    }

    /// True for errors that happen before anything runs.
    pub fn is_static(&self) -> bool {
        self.phase != Phase::Runtime
    }

    pub fn is_warning(&self) -> bool {
        self.phase == Phase::Warning
    }

    /// `error[E0201]` or `warning[W0001]`, and the message as the first
    /// line shows it.
    fn severity_and_message(&self) -> (String, String) {
        let severity = if self.is_warning() {
            "warning"
        } else {
            "error"
        };
        let severity = format!("{severity}[{}]", self.code);
        match self.code {
            codes::E0901 => (severity, format!("unhandled exception: {}", self.message)),
            _ => (severity, self.message.clone()),
        }
    }
}

/// All source texts of one run, indexed by [`FileId`].
#[derive(Default, Clone, Debug)]
pub struct Sources {
    /// Name and text; the text is shared with the checker (`shared`).
    files: Vec<(String, std::rc::Rc<str>)>,
    /// The byte offset where each line of each file starts (`u32`, as
    /// spans keep offsets: half the memory of a long program's table).
    line_starts: Vec<Vec<u32>>,
}

impl Sources {
    pub fn add(&mut self, name: impl Into<String>, text: &str) -> FileId {
        self.add_shared(name, text.into())
    }
    /// [`Self::add`] of a text already shared (no copy).
    pub fn add_shared(&mut self, name: impl Into<String>, text: std::rc::Rc<str>) -> FileId {
        self.line_starts.push(line_starts(&text));
        self.files.push((name.into(), text));
        (self.files.len() - 1) as FileId
    }
    /// The id the next source added gets.
    pub fn next_id(&self) -> FileId {
        self.files.len() as FileId
    }
    pub fn name(&self, id: FileId) -> &str {
        self.files
            .get(id as usize)
            .map(|f| f.0.as_str())
            .unwrap_or("?")
    }
    pub fn text(&self, id: FileId) -> &str {
        self.files.get(id as usize).map(|f| &*f.1).unwrap_or("")
    }
    /// The text of a file, shared (the checker keeps it for its messages
    /// without a copy of its own).
    pub fn shared(&self, id: FileId) -> std::rc::Rc<str> {
        self.files
            .get(id as usize)
            .map_or_else(|| "".into(), |f| f.1.clone())
    }
    /// 1-based line and column (in characters) of a byte offset.
    pub fn line_col(&self, id: FileId, offset: usize) -> (usize, usize) {
        let text = self.text(id);
        let offset = offset.min(text.len());
        let offset = floor_char_boundary(text, offset);
        // Found by binary search in the line index, so that reporting many
        // diagnostics stays linear in their number.
        match self.line_starts.get(id as usize) {
            Some(starts) => {
                let line = starts.partition_point(|&x| x as usize <= offset);
                let start = match starts.get(line.saturating_sub(1)) {
                    Some(&x) if (x as usize) <= offset && text.is_char_boundary(x as usize) => {
                        x as usize
                    }
                    _ => text[..offset].rfind('\n').map_or(0, |i| i + 1),
                };
                let col = text[start..offset].chars().count() + 1;
                (line, col)
            }
            None => line_col_in(text, offset),
        }
    }
}

/// Where each line of `text` starts (past 4 GiB: saturated, see [`offset`]).
pub fn line_starts(text: &str) -> Vec<u32> {
    let mut starts = vec![0];
    starts.extend(text.match_indices('\n').map(|(i, _)| offset(i + 1)));
    starts.shrink_to_fit();
    starts
}

/// 1-based line and column (in characters) of a byte offset in `text`,
/// counted from its start (for a text that is not in [`Sources`]).
pub fn line_col_in(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..floor_char_boundary(text, offset.min(text.len()))];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

fn floor_char_boundary(s: &str, mut i: usize) -> usize {
    while i > 0 && !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// ariadne's view of the sources, each indexed only when a report shows it
/// (a REPL session has one source per entry: indexing them all for every
/// diagnostic made a long session quadratic).
struct Cache<'a>(
    &'a Sources,
    std::collections::HashMap<FileId, ariadne::Source<&'a str>>,
);

impl<'a> ariadne::Cache<FileId> for Cache<'a> {
    type Storage = &'a str;
    fn fetch(&mut self, id: &FileId) -> Result<&ariadne::Source<&'a str>, impl std::fmt::Debug> {
        if (*id as usize) >= self.0.files.len() {
            return Err("unknown source");
        }
        let text: &'a str = self.0.text(*id);
        Ok::<_, &str>(
            self.1
                .entry(*id)
                .or_insert_with(|| ariadne::Source::from(text)),
        )
    }
    fn display<'b>(&self, id: &'b FileId) -> Option<impl std::fmt::Display + 'b> {
        Some(self.0.name(*id).to_string())
    }
}

fn clamp(sources: &Sources, s: Span) -> (FileId, std::ops::Range<usize>) {
    let len = sources.text(s.context).len();
    let start = s.lo().min(len);
    let end = s.hi().clamp(start, len);
    (s.context, start..end)
}

/// Renders diagnostics as ariadne reports, in colour only when asked.
/// How many diagnostics [`render`] shows with their source snippet.
pub const SHOWN_IN_FULL: usize = 100;
/// How many it shows at all (the rest are counted).
pub const SHOWN: usize = 1000;

pub fn render(diags: &[Diagnostic], sources: &Sources, color: bool) -> String {
    use ariadne::{Color, Config, IndexType, Label, Report, ReportKind};
    let mut out = String::new();
    let mut cache = Cache(sources, std::collections::HashMap::new());
    for (i, d) in diags.iter().enumerate() {
        // Past the first [`SHOWN_IN_FULL`], a diagnostic is its first line
        // only, and past [`SHOWN`] a count: mistyped text of any length is
        // reported in time and output linear in it.
        if i >= SHOWN {
            let _ = writeln!(
                out,
                "adair: {} more diagnostics not shown (fix the first ones: later ones often follow from them)",
                diags.len() - SHOWN
            );
            break;
        }
        if i >= SHOWN_IN_FULL {
            let _ = writeln!(out, "{}", one_line(d, sources));
            continue;
        }
        let primary = clamp(sources, d.span);
        let (line, col) = sources.line_col(d.span.context, d.span.lo());
        // The first line is `FILE:LINE:COL: error: message`, the form editors
        // and grep understand; ariadne's snippet follows.
        let (severity, message) = d.severity_and_message();
        let mut report = Report::build(ReportKind::Error, primary.clone()).with_config(
            Config::default()
                .with_color(color)
                .with_index_type(IndexType::Byte),
        );
        let mut label = Label::new(primary).with_order(0);
        // ariadne underlines only a label with a message: an error always
        // shows where it is.
        label = label.with_message(if d.label.is_empty() { "here" } else { &d.label });
        if color {
            label = label.with_color(Color::Red);
        }
        report.add_label(label);
        for (i, (s, text)) in d.notes.iter().enumerate() {
            let mut l = Label::new(clamp(sources, *s))
                .with_message(text)
                .with_order(i as i32 + 1);
            if color {
                l = l.with_color(Color::Blue);
            }
            report.add_label(l);
        }
        if let Some(h) = &d.hint {
            report.set_help(h);
        }
        // The first line is `FILE:LINE:COL: error: message`, the form editors
        // and grep understand; it replaces ariadne's header, and the snippet
        // follows.
        let head = format!("{}:{line}:{col}: ", sources.name(d.span.context));
        let (on, off) = match (color, d.is_warning()) {
            (false, _) => ("", ""),
            (true, false) => ("\x1b[1;31m", "\x1b[0m"),
            (true, true) => ("\x1b[1;33m", "\x1b[0m"),
        };
        let _ = writeln!(out, "{head}{on}{severity}:{off} {message}");
        let mut body = Vec::new();
        let _ = report.finish().write(&mut cache, &mut body);
        let body = String::from_utf8_lossy(&body);
        out.push_str(body.split_once('\n').map_or("", |(_, rest)| rest));
    }
    out
}

/// The first line of a diagnostic (`file:line:col: error: message`), for logs and tests.
pub fn one_line(d: &Diagnostic, sources: &Sources) -> String {
    let (line, col) = sources.line_col(d.span.context, d.span.lo());
    let (severity, message) = d.severity_and_message();
    let mut s = String::new();
    let _ = write!(
        s,
        "{}:{}:{}: {severity}: {message}",
        sources.name(d.span.context),
        line,
        col,
    );
    s
}

#[cfg(test)]
mod render_tests {
    use super::*;

    /// Thousands of diagnostics (mistyped text) are shown in output
    /// linear in their number: the first ones with their snippet, then
    /// first lines, then a count.
    #[test]
    fn many_diagnostics_are_shown_in_bounded_form() {
        let text = "x\n".repeat(3000);
        let mut sources = Sources::default();
        let id = sources.add("many.air", &text);
        let diags: Vec<Diagnostic> = (0..1500u32)
            .map(|i| {
                Diagnostic::new(
                    codes::E0001,
                    Span {
                        start: 2 * i,
                        end: 2 * i + 1,
                        context: id,
                    },
                    "unexpected character `x`",
                )
            })
            .collect();
        let out = render(&diags, &sources, false);
        let firsts = out.lines().filter(|l| l.starts_with("many.air:")).count();
        assert_eq!(firsts, SHOWN, "{}", &out[..out.len().min(400)]);
        assert_eq!(out.matches("╭─[").count(), SHOWN_IN_FULL);
        assert!(out.contains("many.air:101:1: error[E0001]: unexpected character `x`\n"));
        assert!(
            out.ends_with("adair: 500 more diagnostics not shown (fix the first ones: later ones often follow from them)\n"),
            "{}",
            &out[out.len().saturating_sub(300)..]
        );
    }
}

#[cfg(test)]
mod tests {
    use super::Sources;

    /// Lines and columns from the line index agree with counting from the
    /// start, on every offset of a text with multi-byte characters, an empty
    /// line and no final newline.
    #[test]
    fn line_col_from_the_index_matches_counting() {
        let text = "ab\n\nÄpfel := 1;\n  x\u{20ac}y";
        let mut s = Sources::default();
        let id = s.add("t.air", text);
        for off in 0..=text.len() + 2 {
            let o = off.min(text.len());
            let o = (0..=o).rev().find(|&i| text.is_char_boundary(i)).unwrap();
            let before = &text[..o];
            let line = before.matches('\n').count() + 1;
            let col = before.rsplit('\n').next().unwrap().chars().count() + 1;
            assert_eq!(s.line_col(id, off), (line, col), "offset {off}");
        }
        assert_eq!(s.line_col(id, 4), (3, 1));
        assert_eq!(s.line_col(id, text.len()), (4, 6));
    }
}
