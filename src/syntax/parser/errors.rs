//! Error recovery and the syntax diagnostics: what is reported and
//! skipped when the text does not parse (a missing `;`, `then` or `loop`,
//! an unclosed `if`, `case`, loop, block or body), where a skip stops, and
//! how chumsky's errors become [`Diagnostic`]s.

use super::{Ex, PErr, TokIn, semi};
use crate::diag::codes;
use crate::diag::{Diagnostic, Span};
use crate::syntax::diagnostics as D;
use crate::syntax::token::{Kw, Token};
use chumsky::prelude::*;

/// A reserved word that may be missing (`then`, `loop`): reported, and
/// parsing goes on as if it were there when a statement follows.
pub(super) fn soft_kw<'t, I: TokIn<'t>>(k: Kw) -> impl Parser<'t, I, (), Ex<'t>> + Clone {
    let starts_stmt = select! {
        Token::Ident(_) => (),
        Token::Kw(Kw::If | Kw::For | Kw::While | Kw::Loop | Kw::Case | Kw::Return | Kw::Null | Kw::Raise | Kw::Exit | Kw::Declare | Kw::Begin | Kw::Delay) => (),
    };
    just(Token::Kw(k))
        .ignored()
        .or(starts_stmt.rewind().validate(move |_, e, emitter| {
            let sp: Span = e.span();
            emitter.emit(PErr::custom(
                Span {
                    start: sp.start,
                    end: sp.start,
                    context: sp.context,
                },
                D::custom(
                    codes::E0103,
                    format!("missing `{}`", k.as_str()) + &D::about(&[k.as_str()]),
                ),
            ));
        }))
}

/// The end of an `if`, `case` or `loop`: `end <word> <tail>;` (the tail's
/// output and None), or the place of a wrong end: a bare `end;` (taken as
/// this construct's end), or `end Name` (the end of the enclosing body, left
/// for it). Either way the statement is reported unclosed ([`UNCLOSED`])
/// and parsing goes on as if `end <word>;` had been there.
pub(super) fn closing<'t, I: TokIn<'t>, O: Clone + Default + 't>(
    k: Kw,
    tail: impl Parser<'t, I, O, Ex<'t>> + Clone,
) -> impl Parser<'t, I, (O, Option<Span>), Ex<'t>> + Clone {
    let label = match k {
        Kw::Loop => "`end loop`",
        Kw::If => "`end if`",
        _ => "`end case`",
    };
    choice((
        just(Token::Kw(Kw::End))
            .ignore_then(just(Token::Kw(k)))
            .ignore_then(tail)
            .then_ignore(soft_semi())
            .map(|o| (o, None)),
        // A bare `end;` was meant for this construct: it is taken as its end.
        just(Token::Kw(Kw::End))
            .then(semi())
            .map_with(|_, e| (O::default(), Some(e.span()))),
        just(Token::Kw(Kw::End))
            .then_ignore(just(Token::Kw(k)).not())
            .map_with(|_, e| (O::default(), Some(e.span())))
            .rewind(),
        // The text ends first (an editor's unfinished text): the construct
        // is reported as unclosed and taken as ended. Failing instead made
        // the statement around it skip the rest of the text, level after
        // level: time quadratic in the nesting.
        end().map_with(|_, e| (O::default(), Some(e.span()))),
        // Another word that ends a statement sequence (`else`, `when`,
        // `exception`, ...): it belongs to what encloses the construct,
        // which is reported unclosed and taken as ended there, as for
        // `end Name` (failing made each enclosing level parse the rest again).
        seq_end()
            .and_is(just(Token::Kw(Kw::End)).not())
            .map_with(|_, e| (O::default(), Some(e.span())))
            .rewind(),
    ))
    .labelled(label)
}

/// The marker of the error [`closing`] leads to: `\u{1}WORD OFFSET` (the
/// construct's keyword and where its statement starts); `rich_to_diag`
/// turns it into the diagnostic.
pub(super) const UNCLOSED: char = '\u{1}';

/// The `validate` step after [`closing`]: reports an unclosed `WORD`.
macro_rules! unclosed {
    ($word:literal) => {
        |(x, missing): (_, Option<Span>), e, emitter| {
            if let Some(at) = missing {
                let whole: Span = e.span();
                emitter.emit(PErr::custom(
                    at,
                    format!("{UNCLOSED}{} {}", $word, whole.start),
                ));
            }
            x
        }
    };
}
pub(super) use unclosed;

/// A `;` that may be missing: reports it, and parsing goes on as if it were
/// there, when the next token starts a new statement or declaration.
pub(super) fn soft_semi<'t, I: TokIn<'t>>() -> impl Parser<'t, I, (), Ex<'t>> + Clone {
    let starts_next = select! {
        Token::Ident(_) => (),
        Token::Kw(Kw::Procedure | Kw::Function | Kw::Type | Kw::Subtype | Kw::Begin | Kw::End | Kw::If | Kw::For | Kw::While | Kw::Loop
            | Kw::Case | Kw::Return | Kw::Null | Kw::Raise | Kw::Exit | Kw::Declare | Kw::Package | Kw::Exception | Kw::Delay) => (),
    };
    just(Token::Semi)
        .ignored()
        .or(starts_next.rewind().validate(|_, e, emitter| {
            let sp: Span = e.span();
            emitter.emit(PErr::custom(
                Span {
                    start: sp.start,
                    end: sp.start,
                    context: sp.context,
                },
                D::custom(codes::E0103, format!("missing `;`{}", D::about(&[";"]))),
            ));
        }))
}

/// `:=` before an initial value or a default; `=` there is a beginner's
/// slip, reported once and read as `:=`.
pub(super) fn assign_or_eq<'t, I: TokIn<'t>>() -> impl Parser<'t, I, (), Ex<'t>> + Clone {
    just(Token::Assign)
        .ignored()
        .or(just(Token::Eq).validate(|_, e, emitter| {
            emitter.emit(PErr::custom(
                e.span(),
                D::custom(
                    codes::E0104,
                    "`=` compares; an initial value is given with `:=` (`V : Float := 50.0;`)",
                ),
            ));
        }))
}

/// The recovery of a statement or declaration that does not parse: the
/// tokens up to and with its `;`, or up to (without) a word that ends a
/// statement sequence or a declarative part.
pub(super) fn skip_to_semi<'t, I: TokIn<'t>>() -> impl Parser<'t, I, (), Ex<'t>> + Clone {
    any()
        .and_is(choice((just(Token::Semi).ignored(), seq_end(), decls_end())).not())
        .repeated()
        .at_least(1)
        .then(just(Token::Semi).or_not())
        .ignored()
}

/// Tokens that end a statement sequence (never the start of a statement).
pub(super) fn seq_end<'t, I: TokIn<'t>>() -> impl Parser<'t, I, (), Ex<'t>> + Clone {
    choice((
        select! {
            Token::Kw(Kw::End) => (), Token::Kw(Kw::Elsif) => (), Token::Kw(Kw::Else) => (),
            Token::Kw(Kw::When) => (), Token::Kw(Kw::Exception) => (), Token::Kw(Kw::Or) => (),
        },
        // `select ... then abort` (a lone `then` is a broken `if`'s: the
        // statement's recovery skips it).
        just(Token::Kw(Kw::Then))
            .then(just(Token::Kw(Kw::Abort)))
            .ignored(),
    ))
}

/// Tokens that end a declarative part.
pub(super) fn decls_end<'t, I: TokIn<'t>>() -> impl Parser<'t, I, (), Ex<'t>> + Clone {
    select! {
        Token::Kw(Kw::End) => (), Token::Kw(Kw::Begin) => (), Token::Kw(Kw::Private) => (),
    }
}

/// Reports a missing `;` (`then`, `loop`, ...) at the end of the token it
/// should follow.
pub(super) fn missing_after(diags: &mut [Diagnostic], tokens: &[(Token, Span)]) {
    for d in diags.iter_mut() {
        if d.code == codes::E0103
            && let Some((_, p)) = tokens.iter().rev().find(|(_, s)| s.end <= d.span.start)
        {
            d.span = Span {
                start: p.end,
                end: p.end,
                context: p.context,
            };
            // The word that is missing (`;`, `then`, `loop`, ...).
            let word = d.names.first().map_or(";", String::as_str);
            d.label = format!("expected `{word}` here");
        }
    }
}

/// The file ended inside a `loop`, `if` or `case`: name the construct and
/// point at it rather than at the end of the file.
pub(super) fn explain_unclosed(diags: &mut [Diagnostic], tokens: &[(Token, Span)], src_len: u32) {
    let Some(d) = diags.iter_mut().find(|d| d.span.start >= src_len) else {
        return;
    };
    // Open constructs at parenthesis depth 0 (an `if` or `case` inside
    // parentheses is an expression and has no `end`).
    let mut open: Vec<(Kw, Span)> = Vec::new();
    let mut depth = 0usize;
    let mut prev_end = false;
    for (t, sp) in tokens {
        match t {
            Token::LParen => depth += 1,
            Token::RParen => depth = depth.saturating_sub(1),
            Token::Kw(k @ (Kw::Loop | Kw::If | Kw::Case)) if depth == 0 => {
                if prev_end {
                    if let Some(i) = open.iter().rposition(|(o, _)| o == k) {
                        open.truncate(i);
                    }
                } else {
                    open.push((*k, *sp));
                }
            }
            _ => {}
        }
        prev_end = matches!(t, Token::Kw(Kw::End));
    }
    let Some((k, at)) = open.last().copied() else {
        return;
    };
    let word = match k {
        Kw::Loop => "loop",
        Kw::If => "if",
        _ => "case",
    };
    let end_of_input = d.span;
    d.message = format!("this `{word}` has no `end {word};`");
    d.span = at;
    d.label = format!("this `{word}` is never closed");
    d.hint = Some(format!(
        "end it with `end {word};` after its last statement"
    ));
    d.notes.push((end_of_input, UNFINISHED_NOTE.to_string()));
}

/// Where an unclosed construct's line and column go in its message; filled
/// in by `syntax::parse_source`, which has the text.
pub const OPENER_AT: &str = "{opener}";

/// The note at the end of the input of an unclosed construct.
const UNFINISHED_NOTE: &str = "the text ends here";

/// True if the error list only says the input ended too early (for the REPL's
/// continuation prompt).
pub fn is_unfinished(diags: &[Diagnostic], src_len: usize) -> bool {
    let src_len = crate::diag::offset(src_len);
    // The input ran out inside a construct; other errors it caused on the
    // way (after recovery) do not make it finished.
    diags.iter().any(|d| {
        d.phase == crate::diag::Phase::Syntax
            && (d.span.start >= src_len
                || d.notes
                    .iter()
                    .any(|(s, n)| s.start >= src_len && n == UNFINISHED_NOTE))
    })
}

pub(super) fn rich_to_diag(e: Rich<'_, Token, Span>, tokens: &[(Token, Span)]) -> Diagnostic {
    use chumsky::error::RichReason;
    let span = *e.span();
    let found = match e.found() {
        Some(t) => t.to_string(),
        None => "end of input".to_string(),
    };
    let label = if e.found().is_none() {
        "end of input".to_string()
    } else {
        format!("unexpected {found}")
    };
    match e.reason() {
        // An `if`, `case` or `loop` closed by the `end` of what encloses it.
        RichReason::Custom(msg) if msg.starts_with(UNCLOSED) => {
            let mut words = msg[UNCLOSED.len_utf8()..].split(' ');
            let word = words.next().unwrap_or("loop").to_string();
            let start: u32 = words.next().and_then(|w| w.parse().ok()).unwrap_or(0);
            // The construct's own keyword (after a label, `for ... `, `while ...`).
            // (Tokens are in order: binary searches, not scans, as there
            // may be one such error per level of a deep nest.)
            let at = tokens.partition_point(|(_, s)| s.start < span.start);
            let opener = tokens[tokens.partition_point(|(_, s)| s.start < start)..]
                .iter()
                .take_while(|(_, s)| s.start < span.start)
                .find(|(t, _)| match word.as_str() {
                    "if" => *t == Token::Kw(Kw::If),
                    "case" => *t == Token::Kw(Kw::Case),
                    "block" => matches!(t, Token::Kw(Kw::Declare | Kw::Begin)),
                    "body" => matches!(t, Token::Kw(Kw::Procedure | Kw::Function)),
                    _ => matches!(t, Token::Kw(Kw::Loop | Kw::For | Kw::While)),
                })
                .map(|(_, s)| *s)
                .unwrap_or(Span {
                    start,
                    end: start,
                    context: span.context,
                });
            // A block or a body that the text ends inside (taken as ended).
            let ended = match word.as_str() {
                "body" => Some((
                    "the text ends inside the body of the subprogram",
                    "end the body with `end NAME;` after its last statement",
                    "this subprogram's body is not closed",
                )),
                "block" => Some((
                    "`end;` expected to close the block",
                    "end the block with `end;` after its last statement",
                    "this block is not closed",
                )),
                _ => None,
            };
            // The text ends before the construct's `end`: one diagnostic at
            // the end of the input, which `explain_unclosed` words.
            if ended.is_none() && at == tokens.len() {
                return D::unclosed(span, format!("the text ends inside the `{word}`"))
                    .with_label("end of input");
            }
            if let Some((message, hint, note)) = ended {
                let mut d = D::unclosed(span, format!("{message} at {OPENER_AT}"))
                    .with_label("end of input")
                    .with_hint(hint);
                d.notes.push((opener, note.to_string()));
                return d;
            }
            // A bare `end;` was taken as the construct's end; `end Name`
            // belongs to the body around it.
            let bare = tokens.get(at + 1).is_some_and(|(t, _)| *t == Token::Semi);
            let other = tokens
                .get(at)
                .filter(|(t, _)| *t != Token::Kw(Kw::End))
                .map(|(t, _)| t.to_string());
            let (label, hint) = if let Some(other) = other {
                (
                    format!("{other} comes before the `{word}` is closed"),
                    format!("add `end {word};` before this line"),
                )
            } else if bare {
                (
                    format!("this should be `end {word};`"),
                    format!("write `end {word};`"),
                )
            } else {
                (
                    format!("this `end` closes what encloses the `{word}`"),
                    format!("add `end {word};` before this line"),
                )
            };
            let mut d = D::unclosed(
                span,
                format!("`end {word};` expected to close the `{word}` at {OPENER_AT}"),
            )
            .with_label(label)
            .with_hint(hint);
            d.notes
                .push((opener, format!("this `{word}` is not closed")));
            d
        }
        // A custom error explains itself; it has no token of its own to show.
        RichReason::Custom(msg) => D::worded(span, msg),
        _ => {
            let mut expected: Vec<String> = e
                .expected()
                .map(|p| match p {
                    chumsky::error::RichPattern::Token(t) => t.to_string(),
                    chumsky::error::RichPattern::Label(l) => l.to_string(),
                    chumsky::error::RichPattern::EndOfInput => "end of input".to_string(),
                    other => other.to_string(),
                })
                .collect();
            expected.sort();
            expected.dedup();
            // A missing `;` is the most common slip: say so, at the end of
            // the token it should follow.
            // A `)` that closes no `(` (counted back to the statement's
            // start) is the slip, not a missing `;`.
            if matches!(e.found(), Some(Token::RParen)) {
                let mut depth = 0i64;
                for (t, _) in tokens
                    .iter()
                    .rev()
                    .skip_while(|(_, s)| s.start >= span.start)
                {
                    match t {
                        Token::Semi
                        | Token::Kw(Kw::Begin | Kw::Is | Kw::Then | Kw::Else | Kw::Loop) => break,
                        Token::RParen => depth += 1,
                        Token::LParen => depth -= 1,
                        _ => {}
                    }
                }
                if depth >= 0 {
                    return D::unmatched_paren(span);
                }
            }
            if expected.iter().any(|x| x == "`;`") && e.found().is_some() {
                let prev = tokens
                    .iter()
                    .rev()
                    .find(|(_, s)| s.end <= span.start)
                    .map(|(_, s)| *s);
                let at = prev
                    .map(|p| Span {
                        start: p.end,
                        end: p.end,
                        context: p.context,
                    })
                    .unwrap_or(span);
                return D::missing_semicolon(at, &found);
            }
            // Operators that could continue an expression are rarely what was meant.
            const CONT: &[&str] = &[
                "`**`",
                "`and`",
                "`in`",
                "`not`",
                "`or`",
                "`xor`",
                "`..`",
                "`mod`",
                "`rem`",
                "something else",
                "`limited`",
                "`with`",
            ];
            let filtered: Vec<String> = expected
                .iter()
                .filter(|x| !CONT.contains(&x.as_str()))
                .cloned()
                .collect();
            if !filtered.is_empty() {
                expected = filtered;
            }
            let exp = match expected.len() {
                0 => String::new(),
                1 => format!(", expected {}", expected[0]),
                _ => format!(", expected one of {}", expected.join(", ")),
            };
            // A handler at the top of a script (as in Python's `try` or
            // RAPID's ERROR section): a block gives statements a handler.
            if matches!(e.found(), Some(Token::Kw(Kw::Exception)))
                && expected.iter().any(|x| x == "end of input")
            {
                return D::handler_outside_a_block(span, format!("unexpected {found}{exp}"));
            }
            let d = D::unexpected(span, format!("unexpected {found}{exp}")).with_label(label);
            // `...` (`..` then `.`): a placeholder copied from a text, as in
            // the handbook's demo (`F := ... -- Hier Code zur
            // Stellungsanpassung`).
            let placeholder = matches!(e.found(), Some(Token::DotDot))
                && tokens
                    .iter()
                    .skip_while(|(_, s)| s.start < span.start)
                    .nth(1)
                    .is_some_and(|(t, s)| *t == Token::Dot && s.start == span.end);
            if placeholder {
                return d.with_hint(
                    "`...` is a placeholder, not Ada: write the expression (the handbook's demo adapts a frame the arm cannot reach with `ValidFrame (F);`)",
                );
            }
            d
        }
    }
}
