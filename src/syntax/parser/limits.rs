//! The limits checked before parsing (`too_deep`): how deep parentheses,
//! blocks and runs of unary operators may nest, and how many operators an
//! expression may chain, beyond which the recursive parser, checker and
//! engine would overflow the native stack.

use crate::diag::{Diagnostic, Span};
use crate::syntax::token::{Kw, Token};

/// The deepest nesting the parser accepts, of parentheses and of block
/// constructs each. Parsing is recursive: each level costs stack and about
/// 10 KB of memory, so 10,000 levels stay near 100 MB while no program a
/// person writes comes close.
pub const MAX_NESTING: usize = 10_000;

/// The most operators one expression may chain without parentheses
/// (`1 + 1 + ...`). An operator chain is a tree as deep as it is long, which
/// the checker and the engine walk recursively: 150,000 `+` overflowed the
/// native stack.
pub const MAX_CHAIN: usize = 50_000;

/// A program nested deeper than [`MAX_NESTING`] (parentheses, blocks, or
/// parentheses and runs of unary operators together), or with an expression
/// chaining more than [`MAX_CHAIN`] operators: one error at the first token
/// past the limit, found by counting before parsing (a million nested
/// parentheses used 11 GB of memory and 14 s before this check).
pub(super) fn too_deep(tokens: &[(Token, Span)]) -> Option<Diagnostic> {
    let (mut parens, mut blocks) = (0usize, 0usize);
    let mut after_end = false;
    // Operators chained at each level of parentheses.
    let mut chain: Vec<usize> = vec![0];
    // Levels of parentheses and unary operators: the run of unary
    // operators just read (each one's operand is the rest of the run, so
    // the parser recurses once an operator), and for each open parenthesis
    // the run before it (still open until its `)`).
    let (mut levels, mut run) = (0usize, 0usize);
    let mut runs: Vec<usize> = Vec::new();
    for (t, sp) in tokens {
        let was_end = std::mem::replace(&mut after_end, false);
        let what = match t {
            Token::Plus
            | Token::Minus
            | Token::Star
            | Token::StarStar
            | Token::Slash
            | Token::Amp
            | Token::Eq
            | Token::Ne
            | Token::Lt
            | Token::Le
            | Token::Gt
            | Token::Ge
            | Token::Kw(Kw::And | Kw::Or | Kw::Xor | Kw::Mod | Kw::Rem) => {
                let n = chain.last_mut().expect("a level");
                *n += 1;
                if *n > MAX_CHAIN {
                    return Some(
                        crate::syntax::diagnostics::too_deep(
                            *sp,
                            format!(
                                "expression too long: more than {MAX_CHAIN} operators in a row"
                            ),
                        )
                        .with_label("this operator is one too many")
                        .with_hint("split the expression into several statements"),
                    );
                }
                None
            }
            Token::Semi | Token::Comma | Token::Arrow | Token::Assign | Token::DotDot => {
                *chain.last_mut().expect("a level") = 0;
                None
            }
            Token::LParen => {
                parens += 1;
                chain.push(0);
                (parens > MAX_NESTING).then_some("parentheses")
            }
            Token::RParen => {
                parens = parens.saturating_sub(1);
                if chain.len() > 1 {
                    chain.pop();
                }
                None
            }
            Token::Kw(Kw::End) => {
                blocks = blocks.saturating_sub(1);
                after_end = true;
                None
            }
            Token::Kw(Kw::Begin | Kw::Loop | Kw::If | Kw::Case | Kw::Record | Kw::Select)
                if !was_end && parens == 0 =>
            {
                blocks += 1;
                (blocks > MAX_NESTING).then_some("blocks, loops and `if`s")
            }
            _ => None,
        };
        if let Some(what) = what {
            return Some(
                crate::syntax::diagnostics::too_deep(
                    *sp,
                    format!("nesting too deep: more than {MAX_NESTING} levels of {what}"),
                )
                .with_label("this level is one too many")
                .with_hint("split the expression or the statements into subprograms"),
            );
        }
        match t {
            Token::Kw(Kw::Not | Kw::Abs) | Token::Plus | Token::Minus => run += 1,
            Token::LParen => {
                runs.push(run);
                levels += run + 1;
                run = 0;
            }
            Token::RParen => {
                levels = levels.saturating_sub(runs.pop().map_or(0, |r| r + 1));
                run = 0;
            }
            _ => run = 0,
        }
        if levels + run > MAX_NESTING {
            return Some(
                crate::syntax::diagnostics::too_deep(
                    *sp,
                    format!(
                        "nesting too deep: more than {MAX_NESTING} levels of parentheses \
                         and unary operators"
                    ),
                )
                .with_label("this level is one too many")
                .with_hint("split the expression into several statements"),
            );
        }
    }
    None
}
