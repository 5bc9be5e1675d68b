//! Syntax: tokens, lexer, AST and parser. Knows nothing of robots or types.

pub mod ast;
pub mod lexer;
pub mod parser;
pub mod token;

use crate::diag::{Diagnostic, FileId, Offsets as _, Span};

/// Lexes and parses one source. Returns the AST (if the parser got through)
/// and all lexical and syntax diagnostics.
pub fn parse_source(src: &str, file: FileId) -> (Option<ast::CompilationUnit>, Vec<Diagnostic>) {
    let (tokens, mut diags) = lexer::lex(src, file);
    let (unit, mut pd) = parser::parse(&tokens, file, src.len());
    // Name the line and column of the `if`/`case`/`loop` an `end` left open.
    for d in &mut pd {
        if d.message.contains(parser::OPENER_AT)
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
/// is never held whole (issue 14: memory per source byte). A source with
/// any error is parsed again the usual way, whose diagnostics are the ones
/// reported.
pub fn parse_source_lazy(
    src: &str,
    file: FileId,
) -> (Option<ast::CompilationUnit>, Vec<Diagnostic>) {
    if src.len() < LAZY_FROM {
        return parse_source(src, file);
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

/// The tokens of `src[at]`, with their offsets in `src`.
fn lex_part(src: &str, file: FileId, at: std::ops::Range<usize>) -> Vec<(token::Token, Span)> {
    let base = crate::diag::offset(at.start);
    let (mut tokens, _) = lexer::lex(&src[at], file);
    for (_, s) in &mut tokens {
        s.start += base;
        s.end += base;
    }
    tokens
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
    let (cuts, count) = parser::statement_cuts(&lex_part(src, file, at.range()), PART_TOKENS);
    bounds.extend(cuts);
    bounds.push(at.end);
    let last = bounds.len() - 1;
    let mut i = 0;
    while i < last {
        // A part that does not parse alone (a misjudged cut) is joined
        // with the next ones, twice as many each time.
        let mut j = i + 1;
        loop {
            let tokens = lex_part(src, file, bounds[i] as usize..bounds[j] as usize);
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
