//! Syntax: tokens, lexer, AST and parser. Knows nothing of robots or types.

pub mod ast;
pub mod compact;
pub mod diagnostics;
pub mod lexer;
pub mod parser;
pub mod token;

use crate::diag::{Diagnostic, FileId, Offsets as _, Span};

/// Lexes and parses one source. Returns the AST (if the parser got through)
/// and all lexical and syntax diagnostics.
pub fn parse_source(src: &str, file: FileId) -> (Option<ast::CompilationUnit>, Vec<Diagnostic>) {
    crate::work::text_parsed();
    let (tokens, mut diags) = lexer::lex(src, file);
    let (unit, mut pd) = parser::parse(&tokens, file, src.len());
    // Name the line and column of the `if`/`case`/`loop` an `end` left open.
    for d in &mut pd {
        if d.code == crate::diag::codes::E0102
            && let Some((at, _)) = d.notes.first()
        {
            let (line, col) = crate::diag::line_col_in(src, at.start as usize);
            d.message = d
                .message
                .replace(parser::OPENER_AT, &format!("{line}:{col}"));
        }
    }
    diags.extend(pd);
    diags.sort_by_key(|d| d.span.start);
    (unit, diags)
}

/// A source from this size on is parsed with lazy bodies by
/// [`parse_source_lazy`] (a smaller one gains nothing).
pub const LAZY_FROM: usize = 64 * 1024;

/// [`parse_source`] for `adair check` and `run`: the statements of
/// subprogram bodies are recognised but not built (the checker builds them
/// a part at a time with [`lazy_stmts`]), so a long program's syntax tree
/// is never held whole (issue 14: memory per source byte). The parser
/// reads a skeleton: the source's tokens, a window at a time, with the
/// statements of each long body left out (one [`token::Token::Statements`]
/// in their place), so that no list of all the tokens is held either. Those
/// statements are then parsed a part at a time and dropped, to find any
/// syntax error now. A skeleton that does not parse (a long body the
/// [`parser::Nesting`] misjudged, or a package's or task's long statements,
/// which are not left out) is parsed from the list of all the tokens, with
/// the subprograms' statements recognised but not built. A source with any
/// error is parsed again the usual way, whose diagnostics are the ones
/// reported.
pub fn parse_source_lazy(
    src: &str,
    file: FileId,
) -> (Option<ast::CompilationUnit>, Vec<Diagnostic>) {
    if src.len() < LAZY_FROM {
        return parse_source(src, file);
    }
    crate::work::text_parsed();
    let unit = skeleton(src, file).and_then(|(tokens, long)| {
        let (unit, diags) = parser::parse_with(&tokens, file, src.len(), true);
        drop(tokens);
        let valid = |at: &Span| lazy_stmts(src, file, *at, |_, _| {}).is_empty();
        unit.filter(|_| diags.is_empty() && long.iter().all(valid))
    });
    if let Some(u) = unit {
        return (Some(u), Vec::new());
    }
    let (unit, diags) = {
        let (tokens, diags) = lexer::lex(src, file);
        if !diags.is_empty() {
            return parse_source(src, file);
        }
        parser::parse_with(&tokens, file, src.len(), true)
    };
    match unit {
        Some(u) if diags.is_empty() => (Some(u), diags),
        _ => parse_source(src, file),
    }
}

/// Tokens a window of [`lex_windows`] holds, about (bytes of source).
const WINDOW: usize = 256 * 1024;

/// Lexes `src[at]` a window at a time, giving each window's tokens (with
/// their offsets in `src`) to `each`. A window ends after a line end (no
/// token goes on past one) before a line that does not begin with `'` (a
/// window's first `'` has no token before it to tell an attribute mark).
/// Stops at the first window with a lexical error, and returns its
/// diagnostics.
fn lex_windows(
    src: &str,
    file: FileId,
    at: std::ops::Range<usize>,
    mut each: impl FnMut(Vec<(token::Token, Span)>),
) -> Result<(), Vec<Diagnostic>> {
    let mut start = at.start;
    while start < at.end {
        let mut end = at.end;
        if start + WINDOW < at.end {
            // Line ends are single bytes: the window is searched as bytes
            // (its edge may fall inside a character).
            let window = &src.as_bytes()[start..start + WINDOW];
            let mut cut = window.len();
            while let Some(nl) = window[..cut].iter().rposition(|&b| b == b'\n') {
                // The next token must not be a `'` (nor hide behind a
                // comment line, which may be followed by one).
                let next = src[start + nl + 1..].trim_start();
                if !next.starts_with('\'') && !next.starts_with("--") {
                    end = start + nl + 1;
                    break;
                }
                cut = nl;
            }
        }
        let base = crate::diag::offset(start);
        let (mut tokens, mut diags) = lexer::lex(&src[start..end], file);
        let spans =
            tokens
                .iter_mut()
                .map(|(_, s)| s)
                .chain(diags.iter_mut().flat_map(|d| {
                    std::iter::once(&mut d.span).chain(d.notes.iter_mut().map(|(s, _)| s))
                }));
        for s in spans {
            s.start += base;
            s.end += base;
        }
        if !diags.is_empty() {
            return Err(diags);
        }
        each(tokens);
        start = end;
    }
    Ok(())
}

/// Statements of a body from this many tokens on are left out of the
/// skeleton.
const LONG_BODY: usize = 2 * PART_TOKENS;

/// The skeleton of `src` for [`parse_source_lazy`]: its tokens, with the
/// statements of each body of at least [`LONG_BODY`] tokens replaced by one
/// `Statements` token spanning them; and those spans. None at a lexical
/// error. Outside statements, every `begin` is a body's; the statements
/// end at the `exception` or `end` that closes them (see
/// [`parser::Nesting`]), the handlers at their body's `end`.
fn skeleton(src: &str, file: FileId) -> Option<(Vec<parser::Tok>, Vec<Span>)> {
    use token::{Kw, Token};
    enum Mode {
        Decls,
        /// In a body's statements: their first token in `out`, or (past
        /// `LONG_BODY`) their span so far.
        Stmts(parser::Nesting, usize, Option<Span>),
        Handlers(parser::Nesting),
    }
    let mut out: Vec<(Token, Span)> = Vec::new();
    let mut long = Vec::new();
    let mut mode = Mode::Decls;
    let lexed = lex_windows(src, file, 0..src.len(), |tokens| {
        for (t, s) in tokens {
            match &mut mode {
                Mode::Decls => {
                    if t == Token::Kw(Kw::Begin) {
                        mode = Mode::Stmts(parser::Nesting::default(), out.len() + 1, None);
                    }
                    out.push((t, s));
                }
                Mode::Stmts(n, first, left_out) => {
                    if n.step(&t) == parser::At::Close {
                        if let Some(at) = left_out.take() {
                            out.push((Token::Statements, at));
                            long.push(at);
                        }
                        mode = if t == Token::Kw(Kw::Exception) {
                            Mode::Handlers(parser::Nesting::default())
                        } else {
                            Mode::Decls
                        };
                        out.push((t, s));
                        continue;
                    }
                    if let Some(at) = left_out {
                        at.end = s.end;
                        continue;
                    }
                    out.push((t, s));
                    if out.len() - *first >= LONG_BODY {
                        *left_out = Some(Span {
                            end: s.end,
                            ..out[*first].1
                        });
                        out.truncate(*first);
                    }
                }
                Mode::Handlers(n) => {
                    if n.step(&t) == parser::At::Close {
                        mode = Mode::Decls;
                    }
                    out.push((t, s));
                }
            }
        }
    });
    lexed.ok().map(|()| (out, long))
}

/// The tokens of `src[at]`, with their offsets in `src`.
#[cfg(test)]
fn lex_part(src: &str, file: FileId, at: std::ops::Range<usize>) -> Vec<(token::Token, Span)> {
    let mut all = Vec::new();
    let _ = lex_windows(src, file, at, |t| all.extend(t));
    all
}

/// Tokens between two cuts of a lazy body, about.
const PART_TOKENS: usize = 8192;

/// Parses the statements of a lazy body (`at`, see [`ast::Block::lazy`]) a
/// part at a time, giving each part's statements to `each` in order, with
/// the number of the body's statements (about: to reserve room for their
/// checked form at once, not by doubling); the
/// syntax errors if some part does not parse (after
/// [`parse_source_lazy`] has read them all, none).
pub fn lazy_stmts(
    src: &str,
    file: FileId,
    at: Span,
    mut each: impl FnMut(usize, Vec<ast::Stmt>),
) -> Vec<Diagnostic> {
    let mut bounds = vec![at.start];
    let mut cuts = parser::Cuts::new(PART_TOKENS);
    if let Err(d) = lex_windows(src, file, at.range(), |tokens| cuts.feed(&tokens)) {
        return d;
    }
    let count = cuts.count;
    bounds.extend(cuts.cuts);
    bounds.push(at.end);
    let last = bounds.len() - 1;
    let mut i = 0;
    while i < last {
        // A part that does not parse alone (a misjudged cut) is joined
        // with the next ones, twice as many each time.
        let mut j = i + 1;
        loop {
            let (start, end) = (bounds[i] as usize, bounds[j] as usize);
            let mut tokens = Vec::new();
            if let Err(d) = lex_windows(src, file, start..end, |t| tokens.extend(t)) {
                return d;
            }
            match parser::parse_stmts(&tokens, file, bounds[j]) {
                (Some(ss), d) if d.is_empty() => {
                    drop(tokens);
                    each(count, ss);
                    break;
                }
                (_, d) if j == last => return d,
                _ => j = (j + (j - i)).min(last),
            }
        }
        i = j;
    }
    Vec::new()
}

#[cfg(test)]
mod lazy_tests {
    use super::*;
    use ast::{DeclKind, TopItem};

    /// A long procedure whose statements nest every way a cut could be
    /// misjudged: blocks with declarations (a task type, a procedure body
    /// whose `end` closes nothing the cut finder opened), loops, `case`,
    /// `if` expressions in parentheses, `select`, `accept ... do`.
    fn long_source(n: usize) -> String {
        let mut s = String::from(
            "procedure Big is\n   X : Integer := 0;\n   task T is entry E; end T;\n   task body T is begin null; end T;\nbegin\n",
        );
        for i in 0..n {
            s.push_str(&match i % 7 {
                0 => format!("   X := X + {i} mod 7;\n"),
                1 => "   if X > 1000 then\n      X := X - 1000;\n   elsif X < 0 then X := 0; else null; end if;\n".into(),
                2 => "   for I in 1 .. 2 loop X := (if X > 5 then X - 1 else X + 1); end loop;\n".into(),
                3 => "   declare\n      task type TT is entry E; end TT;\n      procedure P is begin X := X + 1; end P;\n      Y : Integer := 1;\n   begin\n      P; X := X + Y;\n   end;\n".into(),
                4 => "   case X mod 3 is when 0 => X := X + 1; when others => null; end case;\n".into(),
                5 => "   L : loop exit L when X >= 0; X := X + 1; end loop L;\n".into(),
                _ => "   begin X := X * 1; exception when others => null; end;\n".into(),
            });
        }
        s.push_str("end Big;\n");
        s
    }

    fn body(unit: &ast::CompilationUnit) -> &ast::Block {
        match &unit.items[..] {
            [TopItem::Decl(d)] => match &d.kind {
                DeclKind::SubprogramBody(b) => &b.body,
                k => panic!("{k:?}"),
            },
            i => panic!("{i:?}"),
        }
    }

    #[test]
    fn a_lazy_body_parsed_a_part_at_a_time_is_the_body_parsed_whole() {
        let src = long_source(6000);
        assert!(src.len() > LAZY_FROM);
        let (eager, d) = parse_source(&src, 0);
        assert!(d.is_empty(), "{d:?}");
        let eager = eager.unwrap();
        let (lazy, d) = parse_source_lazy(&src, 0);
        assert!(d.is_empty(), "{d:?}");
        let lazy = lazy.unwrap();
        let at = body(&lazy).lazy.expect("a lazy body");
        assert!(body(&lazy).stmts.borrow().is_empty());
        // The parser read a skeleton without the body's statements (every
        // nesting above followed to the body's `end`), no list of them all.
        let (skeleton, long) = skeleton(&src, 0).expect("no lexical error");
        assert_eq!(long, [at]);
        assert!(skeleton.len() < 100, "{}", skeleton.len());
        let mut parts = 0;
        let mut got = Vec::new();
        let mut counted = 0;
        let d = lazy_stmts(&src, 0, at, |n, ss| {
            parts += 1;
            counted = n;
            got.extend(ss);
        });
        assert!(d.is_empty(), "{d:?}");
        assert!(parts > 3, "{parts} parts");
        assert_eq!(got, *body(&eager).stmts.borrow());
        // The count follows the nesting as the cuts do: here (declare blocks
        // whose task types and bodies end without opening) it counts more
        // than there are, never fewer.
        assert!(counted >= got.len(), "{counted} < {}", got.len());
        let tokens = lex_part(&src, 0, at.range());
        let (cuts, _) = parser::statement_cuts(&tokens, 100);
        assert!(cuts.len() > 100);
    }

    /// Units declared in a long body's blocks whose `end` closes an `is`
    /// (a package body without statements, a protected type and body, a
    /// generic instance, an expression function, a null record): the
    /// skeleton still leaves the body's statements out whole, and the
    /// program parses as it does the usual way.
    #[test]
    fn a_long_body_with_units_declared_in_its_blocks_is_left_out_whole() {
        let mut src = String::from("procedure Big is\n   X : Integer := 0;\nbegin\n");
        for i in 0..3000 {
            src.push_str(&match i % 3 {
                0 => format!("   X := X + {i} mod 7;\n"),
                1 => "   declare\n      package Q is procedure P; end Q;\n      package body Q is procedure P is begin null; end P; end Q;\n      protected type PT is procedure Inc; private N : Integer := 0; end PT;\n      protected body PT is procedure Inc is begin N := N + 1; end Inc; end PT;\n      type R is null record;\n      function F (A : Integer) return Integer is (A + 1);\n   begin\n      X := F (X);\n   end;\n".into(),
                _ => "   if X > 1000 then X := 0; end if;\n".into(),
            });
        }
        src.push_str("end Big;\n");
        assert!(src.len() > LAZY_FROM);
        let (_, long) = skeleton(&src, 0).expect("no lexical error");
        let (lazy, d) = parse_source_lazy(&src, 0);
        assert!(d.is_empty(), "{d:?}");
        let at = body(&lazy.unwrap()).lazy.expect("a lazy body");
        assert_eq!(long, [at]);
        let (eager, _) = parse_source(&src, 0);
        let mut got = Vec::new();
        assert!(lazy_stmts(&src, 0, at, |_, ss| got.extend(ss)).is_empty());
        assert_eq!(got, *body(&eager.unwrap()).stmts.borrow());
    }

    /// Lexing a window at a time gives the tokens of lexing the whole, with
    /// a window's edge inside a character (a comment's `ö`), and with lines
    /// where a comment line stands between a prefix and its attribute mark.
    #[test]
    fn windows_lex_as_the_whole() {
        let unit = "   X := A\n   -- Größe\n   'Length + 1;\n";
        let off = unit.find('ö').unwrap();
        // The byte at WINDOW is the second of an `ö`.
        let inside = (WINDOW + 10 * unit.len() - off - 1) % unit.len();
        for shift in [inside, 0, 1, 2, 3] {
            let src = format!(
                "{}{}",
                " ".repeat(shift),
                unit.repeat(3 * WINDOW / unit.len())
            );
            if shift == inside {
                assert!(!src.is_char_boundary(WINDOW));
            }
            let (whole, d) = lexer::lex(&src, 0);
            assert!(d.is_empty(), "{d:?}");
            let mut got = Vec::new();
            assert!(lex_windows(&src, 0, 0..src.len(), |t| got.extend(t)).is_ok());
            assert!(got == whole, "shift {shift}");
        }
    }

    #[test]
    fn a_long_source_with_an_error_is_parsed_whole_for_its_diagnostics() {
        let mut src = long_source(6000);
        src.insert_str(src.len() - 10, "   X := ;\n");
        let (_, eager) = parse_source(&src, 0);
        let (_, lazy) = parse_source_lazy(&src, 0);
        assert!(!eager.is_empty());
        assert_eq!(lazy, eager);
    }
}
