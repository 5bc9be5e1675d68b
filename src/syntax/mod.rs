//! Syntax: tokens, lexer, AST and parser. Knows nothing of robots or types.

pub mod ast;
pub mod lexer;
pub mod parser;
pub mod token;

use crate::diag::{Diagnostic, FileId};

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
