//! The terminal front end of the REPL (rustyline) and its piped mode.
//! With `teach.rs`, this is the only REPL code that touches a terminal;
//! the session logic in `super` needs none.

use super::Repl;
use crate::diag::Offsets as _;
use crate::syntax::lexer::lex;
use crate::syntax::token::Token;
use rustyline::completion::{Completer, Pair};
use rustyline::error::ReadlineError;
use rustyline::highlight::{CmdKind, Highlighter};
use rustyline::hint::Hinter;
use rustyline::validate::Validator;
use rustyline::{Context, Editor, Helper};
use std::borrow::Cow;
use std::collections::HashMap;
use std::io::{BufRead, Write};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// Completion, hints, highlighting and the multi-line decision.
pub struct AdaHelper {
    pub names: Vec<String>,
    /// Record components by variable name (lower case), for `Var.` completion.
    pub fields: HashMap<String, Vec<String>>,
    pub signatures: HashMap<String, String>,
    pub color: bool,
}

impl AdaHelper {
    fn refresh(&mut self, repl: &Repl) {
        self.names = repl.completions();
        let c = &repl.session.front.checker;
        self.fields.clear();
        for n in c.completion_names() {
            let f = c.record_fields_of(&n);
            if !f.is_empty() {
                self.fields.insert(n, f);
            }
        }
        self.signatures.clear();
        for f in 0..c.tables.funcs.len() as u32 {
            let key = c.tables.funcs[f as usize].name.to_ascii_lowercase();
            self.signatures.entry(key).or_insert_with(|| c.signature(f));
        }
    }
}

impl Completer for AdaHelper {
    type Candidate = Pair;
    fn complete(
        &self,
        line: &str,
        pos: usize,
        _ctx: &Context<'_>,
    ) -> rustyline::Result<(usize, Vec<Pair>)> {
        if let Some((start, sources_only)) = file_argument(line, pos) {
            return Ok((start, complete_file(&line[start..pos], sources_only)));
        }
        let start = line[..pos]
            .rfind(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':' || c == '.'))
            .map(|i| i + 1)
            .unwrap_or(0);
        let word = &line[start..pos];
        // After `Var.`, complete the record's components; after another
        // `.`, the part after the last dot.
        let (start, word, pool) = match word.rfind('.') {
            Some(i) => {
                let prefix = word[..i]
                    .rsplit('.')
                    .next()
                    .unwrap_or("")
                    .to_ascii_lowercase();
                match self.fields.get(&prefix) {
                    Some(f) => (start + i + 1, &word[i + 1..], f),
                    None => (start + i + 1, &word[i + 1..], &self.names),
                }
            }
            None => (start, word, &self.names),
        };
        let low = word.to_ascii_lowercase();
        let from_fields = !std::ptr::eq(pool, &self.names);
        let cands = pool
            .iter()
            .filter(|n| {
                n.to_ascii_lowercase().starts_with(&low) && (from_fields || !low.is_empty())
            })
            .map(|n| Pair {
                display: n.clone(),
                replacement: n.clone(),
            })
            .collect();
        Ok((start, cands))
    }
}

/// Where the file name argument of `:load`, `:record`, `:plot` or `:view`
/// starts when the cursor is in it, and whether only Ada sources (and
/// folders) are offered (`:load`).
fn file_argument(line: &str, pos: usize) -> Option<(usize, bool)> {
    let before = &line[..pos];
    let rest = before.trim_start();
    let lead = before.len() - rest.len();
    let cmd_len = rest.find(char::is_whitespace)?;
    let sources_only = match &rest[..cmd_len] {
        ":load" => true,
        ":record" | ":plot" | ":view" => false,
        _ => return None,
    };
    let after = &rest[cmd_len..];
    let arg = after.trim_start();
    // One argument: past a second word, nothing is completed as a file.
    if arg.contains(char::is_whitespace) {
        return None;
    }
    Some((lead + cmd_len + (after.len() - arg.len()), sources_only))
}

/// File names that start with `word` (a path relative to the current
/// folder, absolute, or under `~/`), as a shell completes them: folders
/// with a trailing `/`, hidden entries only when `word`'s last part starts
/// with `.`; with `sources_only`, files other than `.air`, `.adb` and
/// `.ads` are left out.
fn complete_file(word: &str, sources_only: bool) -> Vec<Pair> {
    let (dir_part, prefix) = match word.rfind('/') {
        Some(i) => (&word[..=i], &word[i + 1..]),
        None => ("", word),
    };
    let dir = match dir_part.strip_prefix("~/") {
        Some(rest) => match std::env::var_os("HOME") {
            Some(h) => std::path::PathBuf::from(h).join(rest),
            None => return Vec::new(),
        },
        None if dir_part.is_empty() => std::path::PathBuf::from("."),
        None => std::path::PathBuf::from(dir_part),
    };
    let Ok(entries) = std::fs::read_dir(&dir) else {
        return Vec::new();
    };
    let mut found: Vec<Pair> = entries
        .filter_map(|e| {
            let e = e.ok()?;
            let name = e.file_name().into_string().ok()?;
            if !name.starts_with(prefix) || (name.starts_with('.') && !prefix.starts_with('.')) {
                return None;
            }
            // Follows symbolic links, as a shell does.
            let is_dir = std::fs::metadata(e.path()).is_ok_and(|m| m.is_dir());
            let shown = if is_dir {
                format!("{name}/")
            } else {
                let source = std::path::Path::new(&name)
                    .extension()
                    .and_then(|x| x.to_str())
                    .is_some_and(|x| matches!(x, "air" | "adb" | "ads"));
                if sources_only && !source {
                    return None;
                }
                name
            };
            Some(Pair {
                replacement: format!("{dir_part}{shown}"),
                display: shown,
            })
        })
        .collect();
    found.sort_by(|a, b| a.display.cmp(&b.display));
    found
}

impl Hinter for AdaHelper {
    type Hint = String;
    fn hint(&self, line: &str, pos: usize, _ctx: &Context<'_>) -> Option<String> {
        if pos < line.len() {
            return None;
        }
        let word: String = line
            .trim_end()
            .trim_end_matches('(')
            .trim_end()
            .rsplit(|c: char| !(c.is_alphanumeric() || c == '_'))
            .next()?
            .to_string();
        let sig = self.signatures.get(&word.to_ascii_lowercase())?;
        Some(format!("   -- {sig}"))
    }
}

impl Highlighter for AdaHelper {
    fn highlight<'l>(&self, line: &'l str, _pos: usize) -> Cow<'l, str> {
        if !self.color {
            return Cow::Borrowed(line);
        }
        let (tokens, _) = lex(line, 0);
        let mut out = String::new();
        let mut last = 0;
        for (t, s) in tokens {
            if s.lo() < last || s.hi() > line.len() {
                continue;
            }
            out.push_str(&line[last..s.lo()]);
            let text = &line[s.range()];
            let color = match t {
                Token::Kw(_) => Some("1;34"),
                Token::Str(_) | Token::Char(_) => Some("32"),
                Token::Int(_) | Token::Real(_) => Some("33"),
                Token::Error => Some("31"),
                _ => None,
            };
            match color {
                Some(c) => out.push_str(&format!("\x1b[{c}m{text}\x1b[0m")),
                None => out.push_str(text),
            }
            last = s.hi();
        }
        out.push_str(&line[last..]);
        Cow::Owned(out)
    }
    fn highlight_hint<'h>(&self, hint: &'h str) -> Cow<'h, str> {
        if self.color {
            Cow::Owned(format!("\x1b[2m{hint}\x1b[0m"))
        } else {
            Cow::Borrowed(hint)
        }
    }
    fn highlight_char(&self, _line: &str, _pos: usize, _kind: CmdKind) -> bool {
        self.color
    }
}

/// Every line is taken as typed: an unfinished entry goes on at the
/// continuation prompt (`interactive_on`), not inside rustyline's buffer.
impl Validator for AdaHelper {}

/// The prompt of a line that continues an unfinished entry.
pub const CONTINUE: &str = "   ...> ";

impl Helper for AdaHelper {}

/// Only "unexpected end of input" means an entry goes on.
/// Openers and `end`s of the block constructs on one line, counted from its
/// tokens (keywords inside parentheses, like an `if` expression, do not
/// count). While the openers of an entry outnumber its `end`s the entry is
/// certainly unfinished, and the piped REPL need not parse it again: a long
/// open entry costs one parse, not one per line.
#[derive(Default, Clone, Copy)]
pub struct Balance {
    opens: i64,
    ends: i64,
    parens: i64,
    after_end: bool,
    after_null: bool,
}

impl Balance {
    pub fn add_line(&mut self, line: &str) {
        use crate::syntax::token::Kw;
        let (tokens, _) = lex(line, 0);
        for (t, _) in tokens {
            let (was_end, was_null) = (self.after_end, self.after_null);
            self.after_end = false;
            self.after_null = false;
            match t {
                Token::LParen => self.parens += 1,
                Token::RParen => self.parens -= 1,
                Token::Kw(Kw::End) => {
                    self.ends += 1;
                    self.after_end = true;
                }
                Token::Kw(Kw::Null) => self.after_null = true,
                Token::Kw(Kw::Record) if was_null => {}
                Token::Kw(Kw::Begin | Kw::Loop | Kw::If | Kw::Case | Kw::Record | Kw::Select)
                    if !was_end && self.parens <= 0 =>
                {
                    self.opens += 1
                }
                _ => {}
            }
        }
    }

    /// More openers than `end`s so far.
    pub fn surely_open(&self) -> bool {
        self.opens > self.ends
    }
}

pub fn unfinished(text: &str) -> bool {
    if text.trim_start().starts_with(':') || text.trim().is_empty() {
        return false;
    }
    let (tokens, lexd) = lex(text, 0);
    if !lexd.is_empty() {
        return false;
    }
    // A complete expression is a finished entry (its value is printed).
    if crate::syntax::parser::parse_expr_entry(&tokens, 0, text.len()).is_some() {
        return false;
    }
    let (_, diags) = crate::syntax::parser::parse(&tokens, 0, text.len());
    crate::syntax::parser::is_unfinished(&diags, text.len())
}

/// A one-line entry that is complete but for its final `;`
/// (`X : Integer := 3`): it runs, with the `;` added, instead of waiting
/// for more lines and gluing the next entry to it.
pub fn missing_only_semicolon(text: &str) -> bool {
    let t = text.trim();
    if t.is_empty() || t.contains('\n') || t.ends_with(';') || t.starts_with(':') {
        return false;
    }
    let with = format!("{t};");
    let (tokens, lexd) = lex(&with, 0);
    if !lexd.is_empty() {
        return false;
    }
    let (_, diags) = crate::syntax::parser::parse(&tokens, 0, with.len());
    diags.is_empty()
}

/// An unfinished entry that no further line can mend: the parser finds an
/// error before the end of its text (`W : Integer := 1 begin`, a `;`
/// missing in the middle). An empty line ends such a continuation.
pub fn cannot_finish(text: &str) -> bool {
    let (tokens, lexd) = lex(text, 0);
    if !lexd.is_empty() {
        return true;
    }
    let (_, diags) = crate::syntax::parser::parse(&tokens, 0, text.len());
    let end = text.trim_end().len();
    diags.iter().any(|d| (d.span.end as usize) < end)
}

fn history_path() -> Option<std::path::PathBuf> {
    let base = std::env::var_os("XDG_DATA_HOME")
        .map(std::path::PathBuf::from)
        .or_else(|| {
            std::env::var_os("HOME").map(|h| std::path::PathBuf::from(h).join(".local/share"))
        })?;
    let dir = base.join("adair");
    std::fs::create_dir_all(&dir).ok()?;
    Some(dir.join("history"))
}

/// The interactive REPL on a terminal. Returns the exit status.
pub fn interactive(color: bool) -> i32 {
    interactive_on(color, super::Drive::default())
}

/// [`interactive`], with the robot chosen and driven as `drive` says.
pub fn interactive_on(color: bool, drive: super::Drive) -> i32 {
    let mut repl = Repl::new(
        Box::new(|| Box::new(std::io::stdout()) as Box<dyn Write>),
        color,
    );
    let flag = Arc::new(AtomicBool::new(false));
    repl.session.machine.interrupted = Some(flag.clone());
    if let Err(e) = repl.drive(drive) {
        let _ = writeln!(std::io::stderr(), "adair: --robot: {e}");
        return 2;
    }
    repl.use_terminal();
    repl.session.machine.input = Box::new(std::io::BufReader::new(std::io::stdin()));
    // Tab completes what is common to all candidates; a second Tab lists them.
    let config = rustyline::Config::builder()
        .completion_type(rustyline::CompletionType::List)
        .build();
    let mut editor: Editor<AdaHelper, rustyline::history::DefaultHistory> =
        match Editor::with_config(config) {
            Ok(e) => e,
            Err(e) => {
                let _ = writeln!(
                    std::io::stderr(),
                    "adair: cannot start the line editor: {e}"
                );
                return 2;
            }
        };
    // After the editor: rustyline installs its own SIGINT handler when it
    // opens the terminal; while an entry runs, Ctrl-C must reach ours.
    // Ctrl-C always wins: a second one while the same entry still runs
    // (its program caught the first) ends the REPL at once, exit 130.
    let seen = Arc::new(AtomicBool::new(false));
    {
        let (f, seen) = (flag.clone(), seen.clone());
        let _ = ctrlc::set_handler(move || {
            if seen.swap(true, Ordering::SeqCst) {
                let _ = writeln!(
                    std::io::stderr(),
                    "\nadair: Ctrl-C twice: the entry did not stop at the first; leaving the REPL"
                );
                std::process::exit(130);
            }
            f.store(true, Ordering::SeqCst)
        });
    }
    let mut helper = AdaHelper {
        names: Vec::new(),
        fields: HashMap::new(),
        signatures: HashMap::new(),
        color,
    };
    helper.refresh(&repl);
    editor.set_helper(Some(helper));
    let history = history_path();
    if let Some(h) = &history {
        let _ = editor.load_history(h);
    }
    let mut out = std::io::stdout();
    let _ = writeln!(out, "{}", repl.banner());
    // The lines of an entry that is not finished yet (an open `loop`, `if`,
    // `declare`, subprogram or package).
    let mut pending = String::new();
    loop {
        let prompt = if pending.is_empty() {
            "adair> "
        } else {
            CONTINUE
        };
        match editor.readline(prompt) {
            Ok(line) => {
                if !pending.is_empty() {
                    pending.push('\n');
                }
                pending.push_str(&line);
                let ends = line.trim().is_empty() && cannot_finish(&pending);
                if unfinished(&pending) && !missing_only_semicolon(&pending) && !ends {
                    continue;
                }
                let line = std::mem::take(&mut pending);
                let _ = editor.add_history_entry(line.as_str());
                flag.store(false, Ordering::SeqCst);
                seen.store(false, Ordering::SeqCst);
                let reply = repl.entry(&line);
                // End an unfinished output line, or the prompt would overwrite it.
                if repl.session.machine.col != 0 {
                    repl.session.machine.write_str("\n");
                }
                let _ = repl.session.machine.out.flush();
                let _ = out.flush();
                let _ = write!(out, "{}", reply.text);
                if reply.quit {
                    break;
                }
                if let Some(h) = editor.helper_mut() {
                    h.refresh(&repl);
                }
            }
            // Ctrl-C drops an unfinished entry.
            Err(ReadlineError::Interrupted) => pending.clear(),
            Err(ReadlineError::Eof) => break,
            Err(e) => {
                let _ = writeln!(std::io::stderr(), "adair: {e}");
                break;
            }
        }
    }
    if let Some(h) = &history {
        let _ = editor.save_history(h);
    }
    0
}

/// The REPL on piped input: plain text, one entry after another. Exit status
/// 0, or 1 when `strict` and an entry failed.
pub fn piped(input: impl BufRead, out: &mut dyn Write, strict: bool) -> i32 {
    piped_with(
        input,
        Box::new(|| Box::new(std::io::stdout()) as Box<dyn Write>),
        out,
        strict,
    )
}

/// [`piped`] with the program's output going to writers from `make_out`
/// (transcript tests put both into one buffer).
pub fn piped_with(
    input: impl BufRead,
    make_out: super::WriterFactory,
    out: &mut dyn Write,
    strict: bool,
) -> i32 {
    piped_on(input, make_out, out, strict, super::Drive::default())
}

/// [`piped_with`], with the robot chosen and driven as `drive` says.
pub fn piped_on(
    input: impl BufRead,
    make_out: super::WriterFactory,
    out: &mut dyn Write,
    strict: bool,
    drive: super::Drive,
) -> i32 {
    let mut repl = Repl::new(make_out, false);
    if let Err(e) = repl.drive(drive) {
        let _ = writeln!(out, "adair: --robot: {e}");
        return 2;
    }
    let mut input = input;
    let mut failed = false;
    let mut buf = String::new();
    let mut raw = Vec::new();
    let mut number = 0usize;
    let mut balance = Balance::default();
    loop {
        raw.clear();
        match input.read_until(b'\n', &mut raw) {
            Ok(0) => break,
            Ok(_) => {}
            Err(e) => {
                let _ = writeln!(out, "<stdin>:{}: error: cannot read input: {e}", number + 1);
                failed = true;
                break;
            }
        }
        number += 1;
        if raw.ends_with(b"\n") {
            raw.pop();
            if raw.ends_with(b"\r") {
                raw.pop();
            }
        }
        // A line that is not UTF-8 is reported and skipped; the session
        // goes on (an unfinished entry it belonged to cannot be completed).
        let line = match std::str::from_utf8(&raw) {
            Ok(l) => l,
            Err(e) => {
                let col = e.valid_up_to() + 1;
                let dropped = if buf.trim().is_empty() {
                    ""
                } else {
                    "; the unfinished entry it belongs to is dropped"
                };
                let _ = writeln!(
                    out,
                    "<stdin>:{number}:{col}: error: this line is not valid UTF-8 (byte {col}); it is skipped{dropped}"
                );
                buf.clear();
                balance = Balance::default();
                failed = true;
                continue;
            }
        };
        // A `:` command is never Ada: it is taken whole on its line (its
        // words, `:record`, `:load`, were counted as openers, and a command
        // without its argument swallowed the next line).
        let command = buf.trim().is_empty() && line.trim_start().starts_with(':');
        if !command {
            buf.push_str(line);
            buf.push('\n');
            balance.add_line(line);
            // An empty line ends a continuation that no further line can
            // mend (an error before its end), or that only the count of
            // openers keeps open: the entry is reported.
            let open = if line.trim().is_empty() {
                unfinished(&buf) && !cannot_finish(&buf)
            } else {
                balance.surely_open() || unfinished(&buf)
            };
            if open && !missing_only_semicolon(&buf) {
                continue;
            }
            balance = Balance::default();
        }
        let reply = repl.entry(if command { line } else { &buf });
        buf.clear();
        let _ = std::io::stdout().flush();
        let _ = write!(out, "{}", reply.text);
        failed |= reply.failed;
        if reply.quit {
            break;
        }
    }
    if !buf.trim().is_empty() {
        let reply = repl.entry(&buf);
        let _ = write!(out, "{}", reply.text);
        failed |= reply.failed;
    }
    if failed && strict { 1 } else { 0 }
}

#[cfg(test)]
mod balance_tests {
    use super::Balance;

    fn open(lines: &[&str]) -> bool {
        let mut b = Balance::default();
        for l in lines {
            b.add_line(l);
        }
        b.surely_open()
    }

    #[test]
    fn openers_outnumbering_ends_mean_unfinished() {
        assert!(open(&["for I in 1 .. 3 loop", "Put_Line (\"x\");"]));
        assert!(open(&["declare", "   X : Integer;", "begin"]));
        assert!(open(&["type R is record", "   X : Integer;"]));
        assert!(!open(&["for I in 1 .. 3 loop", "null;", "end loop;"]));
        assert!(!open(&["if A then B; end if;"]));
        assert!(!open(&["declare X : Integer; begin X := 1; end;"]));
    }

    /// The parser's own verdict (not the balance count): a `declare` block
    /// or a body that the text ends inside is unfinished, though the parser
    /// takes it as ended to report it once.
    #[test]
    fn a_block_or_body_the_text_ends_inside_is_unfinished() {
        assert!(super::unfinished(
            "declare\n   X : Integer;\nbegin\n   X := 1;\n"
        ));
        assert!(super::unfinished(
            "procedure Q is\nbegin\n   declare\n   begin\n      null;\n"
        ));
        assert!(super::unfinished("procedure Q is\nbegin\n   null;\n"));
        assert!(!super::unfinished(
            "declare X : Integer; begin X := 1; end;"
        ));
        assert!(!super::unfinished("procedure Q is begin null; end Q;"));
    }

    #[test]
    fn keywords_in_parentheses_and_null_record_do_not_open() {
        assert!(!open(&["X := (if A then 1 else 2);"]));
        assert!(!open(&[
            "Put_Line (case N is when 1 => \"a\", when others => \"b\");"
        ]));
        assert!(!open(&["type T is null record;"]));
        assert!(!open(&["Put_Line (\"begin loop if\"); -- case record"]));
    }
}

#[cfg(test)]
mod file_completion_tests {
    use super::{complete_file, file_argument};

    fn shown(word: &str, sources_only: bool) -> Vec<String> {
        complete_file(word, sources_only)
            .into_iter()
            .map(|p| p.replacement)
            .collect()
    }

    #[test]
    fn file_commands_take_file_names_and_others_do_not() {
        assert_eq!(file_argument(":load ", 6), Some((6, true)));
        assert_eq!(file_argument("  :load  ex", 11), Some((9, true)));
        assert_eq!(file_argument(":record out", 11), Some((8, false)));
        assert_eq!(file_argument(":plot a/b", 9), Some((6, false)));
        assert_eq!(file_argument(":view v", 7), Some((6, false)));
        // The command itself, other commands, Ada text and a second word.
        assert_eq!(file_argument(":load", 5), None);
        assert_eq!(file_argument(":help Mo", 8), None);
        assert_eq!(file_argument("X := 1", 6), None);
        assert_eq!(file_argument(":load a b", 9), None);
    }

    #[test]
    fn folders_get_a_slash_and_load_offers_only_sources() {
        let dir = std::env::temp_dir().join(format!("adair-complete-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("exdir")).unwrap();
        for f in [
            "example.air",
            "extra.txt",
            "exb.adb",
            "exs.ads",
            ".exhidden.air",
        ] {
            std::fs::write(dir.join(f), "null;").unwrap();
        }
        let d = format!("{}/", dir.display());
        let ex = format!("{d}ex");
        assert_eq!(
            shown(&ex, true),
            [
                format!("{d}example.air"),
                format!("{d}exb.adb"),
                format!("{d}exdir/"),
                format!("{d}exs.ads"),
            ]
        );
        assert_eq!(shown(&ex, false).len(), 5, "{:?}", shown(&ex, false));
        assert!(shown(&ex, false).contains(&format!("{d}extra.txt")));
        assert_eq!(
            shown(&format!("{d}.ex"), true),
            [format!("{d}.exhidden.air")]
        );
        assert!(shown(&format!("{d}nothing"), true).is_empty());
        assert!(shown(&format!("{d}missing/ex"), true).is_empty());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
