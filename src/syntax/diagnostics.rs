//! The diagnostics of the lexer and the parser, each built by a named
//! constructor with its code (`E00xx` lexical, `E01xx` syntax; see
//! `diag::codes`).
//!
//! The grammar reports its own faults through chumsky's `Rich::custom`,
//! which carries a string only: [`custom`] puts the code in front of the
//! message and [`from_custom`] takes it back, so no code decides by a
//! message's words.

use crate::diag::codes::{self, Code};
use crate::diag::{Diagnostic, Span};

/// Separates a custom error's code from its message.
const CODE_MARK: char = '\u{1f}';

/// A grammar error's text for `Rich::custom`: its code, then its message.
pub fn custom(code: Code, message: impl std::fmt::Display) -> String {
    format!("{code}{CODE_MARK}{message}")
}

/// The names a [`custom`] message is about (see `Diagnostic::names`), to
/// put after its message.
pub fn about(names: &[&str]) -> String {
    names.iter().map(|n| format!("{CODE_MARK}{n}")).collect()
}

/// The code, message and names of a [`custom`] text (a text without a
/// code is a malformed construct, E0106).
pub fn from_custom(text: &str) -> (Code, &str, Vec<&str>) {
    match text.split_once(CODE_MARK) {
        Some((c, rest)) => {
            let mut parts = rest.split(CODE_MARK);
            let message = parts.next().unwrap_or("");
            let code = codes::lookup(c).map_or(codes::E0106, |e| e.code);
            (code, message, parts.collect())
        }
        None => (codes::E0106, text, Vec::new()),
    }
}

// --- lexical ---

pub fn stray_char(span: Span, c: char) -> Diagnostic {
    Diagnostic::new(codes::E0001, span, format!("unexpected character `{c}`"))
        .with_label("not part of any Ada token")
}

/// A run of `n` of the same stray character, as one diagnostic.
pub fn stray_chars(span: Span, c: char, n: usize) -> Diagnostic {
    Diagnostic::new(
        codes::E0001,
        span,
        format!("unexpected characters `{c}` ({n} of them)"),
    )
    .with_label("not part of any Ada token")
}

pub fn stray_tick(span: Span) -> Diagnostic {
    Diagnostic::new(codes::E0001, span, "stray `'`")
        .with_label("neither a character literal nor an attribute mark")
        .with_hint("a character literal is written 'c'")
}

pub fn misplaced_underscore_in_name(span: Span, text: &str) -> Diagnostic {
    Diagnostic::new(
        codes::E0001,
        span,
        format!("identifier `{text}` has a misplaced underscore"),
    )
    .with_hint("an underscore must stand between two letters or digits")
}

pub fn unterminated_string(span: Span) -> Diagnostic {
    Diagnostic::new(codes::E0002, span, "unterminated string literal")
        .with_label("this string has no closing `\"` on its line")
        .with_hint("close the string with `\"`; write `\"\"` for a quote inside it")
}

pub fn single_quoted_string(span: Span, text: &str) -> Diagnostic {
    Diagnostic::new(codes::E0003, span, "string literal in single quotes")
        .with_label("Ada strings use double quotes")
        .with_hint(format!("write \"{text}\""))
}

/// What is wrong with a numeric literal.
#[derive(Clone, Debug, PartialEq)]
pub enum NumberFault {
    /// No digits after `E`, or a misplaced `_` in them (`1.0E`, `1E_2`).
    BadExponent,
    ExponentTooLarge,
    /// A `_` not between two digits (`1__000`, `_1`).
    MisplacedUnderscore,
    /// A based literal's `_` misplaced or its digits missing (`16##`).
    UnderscoreOrDigits,
    /// `2E-3`: an integer literal cannot have one.
    NegativeExponent,
    TooLarge,
    /// `16#FF` without its closing `#`.
    NoClosingHash,
    BadBase,
    BaseOutOfRange(u32),
    NotADigit(char, u32),
    /// Anything else Rust's float parser refuses.
    Other(String),
}

/// A malformed numeric literal `text`, with the fix when there is one.
pub fn bad_number(span: Span, text: &str, fault: &NumberFault) -> Diagnostic {
    use NumberFault as F;
    let why = match fault {
        F::BadExponent => format!("bad exponent in `{text}`"),
        F::ExponentTooLarge => format!("exponent too large in `{text}`"),
        F::MisplacedUnderscore => format!("misplaced `_` in `{text}`"),
        F::UnderscoreOrDigits => format!("misplaced `_` or missing digits in `{text}`"),
        F::NegativeExponent => {
            format!("an integer literal cannot have a negative exponent: `{text}`")
        }
        F::TooLarge => format!("`{text}` is too large"),
        F::NoClosingHash => format!("based literal `{text}` lacks its closing `#`"),
        F::BadBase => format!("bad base in `{text}`"),
        F::BaseOutOfRange(b) => format!("base {b} is not between 2 and 16"),
        F::NotADigit(c, b) => format!("`{c}` is not a digit of base {b} in `{text}`"),
        F::Other(e) => e.clone(),
    };
    let hint = match fault {
        F::BadExponent => Some("write an exponent like `E3` or `E-3`, or leave it out".to_string()),
        F::NegativeExponent => {
            // `2E-3` -> `2.0E-3`
            let cut = text.find(['e', 'E']).unwrap_or(text.len());
            Some(format!(
                "for a Float, write `{}.0{}`",
                &text[..cut],
                &text[cut..]
            ))
        }
        F::MisplacedUnderscore | F::UnderscoreOrDigits => {
            let mut fixed = String::new();
            for c in text.chars() {
                if c == '_' && (fixed.is_empty() || fixed.ends_with(['_', '.', '#'])) {
                    continue;
                }
                fixed.push(c);
            }
            let fixed = fixed
                .trim_end_matches('_')
                .replace("_.", ".")
                .replace("_#", "#");
            Some(format!("a `_` stands between two digits: `{fixed}`"))
        }
        F::NotADigit(_, base) => Some(if *base <= 10 {
            format!("the digits of base {base} are 0 .. {}", base - 1)
        } else {
            format!(
                "the digits of base {base} are 0 .. 9 and A .. {}",
                char::from(b'A' + (base - 11) as u8)
            )
        }),
        _ => None,
    };
    let d = Diagnostic::new(
        codes::E0004,
        span,
        format!("malformed numeric literal: {why}"),
    );
    match hint {
        Some(h) => d.with_hint(h),
        None => d,
    }
}

/// `==` or `!=` from another language; read as Ada's `=` or `/=`.
pub fn foreign_operator(span: Span, op: &str, ada: &str) -> Diagnostic {
    Diagnostic::new(codes::E0104, span, format!("`{op}` is not an Ada operator"))
        .with_label(format!("Ada writes `{ada}`"))
        .with_hint(format!(
            "write `{ada}`: in Ada, `=` compares, `/=` is \"not equal\", and `:=` assigns"
        ))
}

// --- syntax ---

/// A grammar error without a more precise word: a token the grammar does
/// not expect here.
pub fn unexpected(span: Span, message: impl Into<String>) -> Diagnostic {
    Diagnostic::new(codes::E0101, span, message)
}

/// An `if`, `case`, loop, block or body whose `end` is missing.
pub fn unclosed(span: Span, message: impl Into<String>) -> Diagnostic {
    Diagnostic::new(codes::E0102, span, message)
}

/// `missing `;` before X`, at the end of the token it should follow.
pub fn missing_semicolon(span: Span, found: &str) -> Diagnostic {
    Diagnostic::new(codes::E0103, span, format!("missing `;` before {found}"))
        .about(&[";"])
        .with_label("expected `;` here")
        .with_hint("a statement or declaration ends with `;`")
}

/// `exception` at the top of a script: a script's statements have no
/// handler of their own, a block gives them one.
pub fn handler_outside_a_block(span: Span, message: impl Into<String>) -> Diagnostic {
    Diagnostic::new(codes::E0101, span, message)
        .with_label("no `begin` that this handler could belong to")
        .with_hint(
            "put the statements and the handler in a block:\n   begin\n      ...\n   exception\n      when OutOfReach => ...\n   end;",
        )
}

/// A `)` that closes no `(`.
pub fn unmatched_paren(span: Span) -> Diagnostic {
    Diagnostic::new(codes::E0101, span, "unexpected `)` without a matching `(`")
        .with_label("this `)` closes nothing")
        .with_hint("remove it, or add the `(` it should close")
}

/// Nesting or an operator chain past the limits the parser, the checker
/// and the engine take.
pub fn too_deep(span: Span, message: impl Into<String>) -> Diagnostic {
    Diagnostic::new(codes::E0105, span, message)
}

/// A grammar error the grammar worded itself (see [`custom`]).
pub fn worded(span: Span, text: &str) -> Diagnostic {
    let (code, message, names) = from_custom(text);
    Diagnostic::new(code, span, message).about(&names)
}
