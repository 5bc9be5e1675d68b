//! The lexer: logos finds the raw tokens, this module decides the tick
//! ambiguity, evaluates literals and turns lexical errors into diagnostics
//! while lexing goes on.

use super::diagnostics::{self as D, NumberFault};
use super::token::{IntLit, Kw, Token};
use crate::diag::Offsets as _;
use crate::diag::{Diagnostic, FileId, Span, span};
use logos::Logos;

#[derive(Logos, Clone, Copy, Debug, PartialEq)]
#[logos(skip r"[ \t\r\n\f\v]+")]
#[logos(skip(r"--[^\n]*", allow_greedy = true))]
enum Raw {
    // Ada 2012 identifiers (RM 2.3): letters of any script, then letters,
    // digits, marks and `_` (`Größe`, as GNAT accepts with -gnatW8).
    #[regex(r"[\p{L}\p{Nl}][\p{L}\p{Nl}\p{Mn}\p{Mc}\p{Nd}\p{Pc}]*")]
    Word,
    #[regex(r"[0-9][0-9_]*(\.[0-9][0-9_]*)?([eE][+-]?[0-9][0-9_]*)?")]
    Decimal,
    #[regex(r"[0-9][0-9_]*#[0-9A-Za-z_.]*#?([eE][+-]?[0-9][0-9_]*)?")]
    Based,
    /// An exponent mark without digits (`1.0E`, `2.5E+`).
    #[regex(r"[0-9][0-9_]*(\.[0-9][0-9_]*)?[eE][+-]?")]
    BadExponent,
    #[regex(r#""([^"\n]|"")*""#)]
    Str,
    #[regex(r#""([^"\n]|"")*"#, priority = 1)]
    UnterminatedStr,
    #[token("'")]
    Tick,
    #[token("(")]
    LParen,
    #[token(")")]
    RParen,
    #[token(",")]
    Comma,
    #[token(";")]
    Semi,
    #[token(":")]
    Colon,
    #[token(".")]
    Dot,
    #[token("..")]
    DotDot,
    #[token(":=")]
    Assign,
    #[token("=>")]
    Arrow,
    #[token("<>")]
    Box,
    #[token("|")]
    Bar,
    #[token("!")]
    Bang,
    #[token("&")]
    Amp,
    #[token("+")]
    Plus,
    #[token("-")]
    Minus,
    #[token("*")]
    Star,
    #[token("**")]
    StarStar,
    #[token("/")]
    Slash,
    #[token("=")]
    Eq,
    #[token("/=")]
    Ne,
    /// `==` and `!=` of C, Python, RAPID's neighbours: reported, read as
    /// `=` and `/=`.
    #[token("==")]
    EqEq,
    #[token("!=")]
    BangEq,
    #[token("<")]
    Lt,
    #[token("<=")]
    Le,
    #[token(">")]
    Gt,
    #[token(">=")]
    Ge,
}

pub type Spanned = (Token, Span);

/// Lexes a whole source. Always returns a token list (erroneous parts become
/// [`Token::Error`] or a best guess) together with every lexical diagnostic.
pub fn lex(src: &str, file: FileId) -> (Vec<Spanned>, Vec<Diagnostic>) {
    // A big source's tokens are counted first: the list is then allocated
    // once at its size, not grown by doubling (which held up to three
    // times the tokens' memory at once; issue 14).
    let mut toks: Vec<Spanned> = if src.len() > 64 * 1024 {
        Vec::with_capacity(Raw::lexer(src).count())
    } else {
        Vec::new()
    };
    let mut diags = Vec::new();
    // A UTF-8 byte-order mark (editors on Windows write one) is not source.
    let mut base = if src.starts_with('\u{feff}') { 3 } else { 0 };
    'restart: loop {
        let mut lx = Raw::lexer(&src[base..]);
        while let Some(r) = lx.next() {
            let range = lx.span();
            let (s, e) = (base + range.start, base + range.end);
            let sp = span(file, s, e);
            let text = &src[s..e];
            let tok = match r {
                Ok(Raw::Word) => {
                    if text.ends_with('_') || text.as_bytes().windows(2).any(|w| w == b"__") {
                        diags.push(D::misplaced_underscore_in_name(sp, text));
                    }
                    // A keyword has at most 12 letters: a word is put in
                    // lower case on the stack, not in a new string.
                    let mut buf = [0u8; 12];
                    let lower = buf.get_mut(..text.len()).and_then(|b| {
                        b.copy_from_slice(text.as_bytes());
                        b.make_ascii_lowercase();
                        std::str::from_utf8(b).ok()
                    });
                    match lower.and_then(Kw::from_lower) {
                        Some(k) => Token::Kw(k),
                        None => Token::Ident(super::ast::intern(text)),
                    }
                }
                Ok(Raw::Decimal) => match decimal(text) {
                    Ok(t) => t,
                    Err(fault) => {
                        diags.push(D::bad_number(sp, text, &fault));
                        Token::Error
                    }
                },
                Ok(Raw::Based) => match based(text) {
                    Ok(t) => t,
                    Err(fault) => {
                        diags.push(D::bad_number(sp, text, &fault));
                        Token::Error
                    }
                },
                Ok(Raw::BadExponent) => {
                    diags.push(D::bad_number(sp, text, &NumberFault::BadExponent));
                    Token::Error
                }
                Ok(Raw::Str) => Token::Str(text[1..text.len() - 1].replace("\"\"", "\"").into()),
                Ok(Raw::UnterminatedStr) => {
                    // As GNAT: the string ends before a `)`/`;` that closes
                    // the line (`Put_Line ("end);`), which are lexed again.
                    let body = text.trim_end();
                    let cut = [");", ";", ")"]
                        .iter()
                        .find_map(|t| body.strip_suffix(t))
                        .filter(|k| k.len() > 1);
                    let keep = cut.unwrap_or(text);
                    let sp = span(file, s, s + keep.len());
                    diags.push(D::unterminated_string(sp));
                    let tok = Token::Str(keep[1..].replace("\"\"", "\"").into());
                    if cut.is_some() {
                        toks.push((tok, sp));
                        base = sp.hi();
                        continue 'restart;
                    }
                    tok
                }
                Ok(Raw::Tick) => {
                    let attribute_mark = matches!(
                        toks.last(),
                        Some((
                            Token::Ident(_) | Token::RParen | Token::Kw(Kw::All) | Token::Str(_),
                            _
                        ))
                    );
                    if attribute_mark {
                        Token::Tick
                    } else {
                        // A character literal 'c', or a misprinted string 'abc'.
                        let rest = &src[e..];
                        let mut chars = rest.char_indices();
                        match (chars.next(), chars.next()) {
                            (Some((_, c)), Some((i, '\''))) if c != '\n' => {
                                let end = e + i + 1;
                                toks.push((Token::Char(c), span(file, s, end)));
                                base = end;
                                continue 'restart;
                            }
                            _ => {
                                let line_end = rest.find('\n').unwrap_or(rest.len());
                                if let Some(close) = rest[..line_end].find('\'') {
                                    let inner = &rest[..close];
                                    let end = e + close + 1;
                                    diags.push(D::single_quoted_string(span(file, s, end), inner));
                                    toks.push((Token::Str(inner.into()), span(file, s, end)));
                                    base = end;
                                    continue 'restart;
                                }
                                diags.push(D::stray_tick(sp));
                                Token::Error
                            }
                        }
                    }
                }
                Ok(Raw::LParen) => Token::LParen,
                Ok(Raw::RParen) => Token::RParen,
                Ok(Raw::Comma) => Token::Comma,
                Ok(Raw::Semi) => Token::Semi,
                Ok(Raw::Colon) => Token::Colon,
                Ok(Raw::Dot) => Token::Dot,
                Ok(Raw::DotDot) => Token::DotDot,
                Ok(Raw::Assign) => Token::Assign,
                Ok(Raw::Arrow) => Token::Arrow,
                Ok(Raw::Box) => Token::Box,
                Ok(Raw::Bar) | Ok(Raw::Bang) => Token::Bar,
                Ok(Raw::Amp) => Token::Amp,
                Ok(Raw::Plus) => Token::Plus,
                Ok(Raw::Minus) => Token::Minus,
                Ok(Raw::Star) => Token::Star,
                Ok(Raw::StarStar) => Token::StarStar,
                Ok(Raw::Slash) => Token::Slash,
                Ok(Raw::Eq) => Token::Eq,
                Ok(Raw::Ne) => Token::Ne,
                Ok(Raw::EqEq) => {
                    diags.push(D::foreign_operator(sp, "==", "="));
                    Token::Eq
                }
                Ok(Raw::BangEq) => {
                    diags.push(D::foreign_operator(sp, "!=", "/="));
                    Token::Ne
                }
                Ok(Raw::Lt) => Token::Lt,
                Ok(Raw::Le) => Token::Le,
                Ok(Raw::Gt) => Token::Gt,
                Ok(Raw::Ge) => Token::Ge,
                Err(()) => {
                    let c = text.chars().next().unwrap_or('?');
                    // A run of the same stray character is one mistake (a
                    // pasted line of `@` or `#`): one diagnostic for it,
                    // not one per character.
                    if let Some(prev) = diags.last_mut()
                        && prev.span.hi() == s
                        && prev.span.context == file
                        && prev.code == crate::diag::codes::E0001
                        && src[prev.span.lo()..].starts_with(c)
                    {
                        // (Only runs of one character are merged: its first
                        // is enough to look at.)
                        let run = span(file, prev.span.lo(), e);
                        let n = (e - run.lo()) / c.len_utf8();
                        let hint = prev.hint.take();
                        *prev = D::stray_chars(run, c, n);
                        prev.hint = hint;
                        continue;
                    }
                    let mut d = D::stray_char(sp, c);
                    if c == '@' {
                        d = d.with_hint("`@` (Ada 2022's target name) is not part of AdaIR: write the name again, as in `Count := Count + 1;`");
                    } else if c == '$' {
                        d = d.with_hint(
                            "delete it: AdaIR has no `$` (a hexadecimal literal is written 16#FF#)",
                        );
                    } else if c == '[' || c == ']' {
                        d = d.with_hint("Ada indexes arrays with parentheses: A (I)");
                    } else if c == '{' || c == '}' {
                        d = d.with_hint("Ada has no braces: blocks are `begin ... end;`");
                    }
                    diags.push(d);
                    continue;
                }
            };
            toks.push((tok, sp));
        }
        break;
    }
    // The parser holds every token at once: no growth slack on a big file.
    toks.shrink_to_fit();
    (toks, diags)
}

/// Evaluates a numeric literal (decimal or based) on its own, as `'Value` needs.
pub fn numeric_literal(text: &str) -> Option<Token> {
    let mut lx = Raw::lexer(text);
    let tok = lx.next()?;
    if lx.span().end != text.len() || lx.next().is_some() {
        return None;
    }
    match tok {
        Ok(Raw::Decimal) => decimal(text).ok(),
        Ok(Raw::Based) => based(text).ok(),
        _ => None,
    }
}

fn digits_ok(s: &str) -> bool {
    !s.is_empty() && !s.starts_with('_') && !s.ends_with('_') && !s.contains("__")
}

fn decimal(text: &str) -> Result<Token, NumberFault> {
    let (mant, exp) = match text.find(['e', 'E']) {
        Some(i) => (&text[..i], Some(&text[i + 1..])),
        None => (text, None),
    };
    let exp_val: i32 = match exp {
        Some(e) => {
            let digits = e.trim_start_matches(['+', '-']);
            if !digits_ok(digits) {
                return Err(NumberFault::BadExponent);
            }
            let v: i32 = digits
                .replace('_', "")
                .parse()
                .map_err(|_| NumberFault::ExponentTooLarge)?;
            if e.starts_with('-') { -v } else { v }
        }
        None => 0,
    };
    if let Some((ip, fp)) = mant.split_once('.') {
        if !digits_ok(ip) || !digits_ok(fp) {
            return Err(NumberFault::MisplacedUnderscore);
        }
        let s = format!(
            "{}.{}e{}",
            ip.replace('_', ""),
            fp.replace('_', ""),
            exp_val
        );
        s.parse::<f64>()
            .map(Token::Real)
            .map_err(|e| NumberFault::Other(e.to_string()))
    } else {
        if !digits_ok(mant) {
            return Err(NumberFault::MisplacedUnderscore);
        }
        if exp_val < 0 {
            return Err(NumberFault::NegativeExponent);
        }
        let mut v: i128 = mant
            .replace('_', "")
            .parse()
            .map_err(|_| NumberFault::TooLarge)?;
        for _ in 0..exp_val {
            v = v.checked_mul(10).ok_or(NumberFault::TooLarge)?;
        }
        Ok(Token::Int(IntLit::new(v)))
    }
}

fn based(text: &str) -> Result<Token, NumberFault> {
    let mut parts = text.splitn(3, '#');
    let base_s = parts.next().unwrap_or("");
    let body = parts.next().unwrap_or("");
    let tail = match parts.next() {
        Some(t) => t,
        None => return Err(NumberFault::NoClosingHash),
    };
    let base: u32 = base_s
        .replace('_', "")
        .parse()
        .map_err(|_| NumberFault::BadBase)?;
    if !(2..=16).contains(&base) {
        return Err(NumberFault::BaseOutOfRange(base));
    }
    let exp_val: i32 = if tail.is_empty() {
        0
    } else {
        let e = &tail[1..];
        let digits = e.trim_start_matches(['+', '-']);
        if !digits_ok(digits) {
            return Err(NumberFault::BadExponent);
        }
        let v: i32 = digits
            .replace('_', "")
            .parse()
            .map_err(|_| NumberFault::BadExponent)?;
        if e.starts_with('-') { -v } else { v }
    };
    let (ip, fp) = match body.split_once('.') {
        Some((a, b)) => (a, Some(b)),
        None => (body, None),
    };
    let digit = |c: char| -> Result<u32, NumberFault> {
        c.to_digit(base).ok_or(NumberFault::NotADigit(c, base))
    };
    if !digits_ok(ip) || fp.is_some_and(|f| !digits_ok(f)) {
        return Err(NumberFault::UnderscoreOrDigits);
    }
    match fp {
        None => {
            if exp_val < 0 {
                return Err(NumberFault::NegativeExponent);
            }
            let mut v: i128 = 0;
            for c in ip.chars().filter(|c| *c != '_') {
                let d = digit(c)?;
                v = v
                    .checked_mul(base as i128)
                    .and_then(|v| v.checked_add(d as i128))
                    .ok_or(NumberFault::TooLarge)?;
            }
            for _ in 0..exp_val {
                v = v.checked_mul(base as i128).ok_or(NumberFault::TooLarge)?;
            }
            Ok(Token::Int(IntLit::new(v)))
        }
        Some(fp) => {
            let mut v = 0f64;
            for c in ip.chars().filter(|c| *c != '_') {
                v = v * base as f64 + digit(c)? as f64;
            }
            let mut scale = 1f64 / base as f64;
            for c in fp.chars().filter(|c| *c != '_') {
                v += digit(c)? as f64 * scale;
                scale /= base as f64;
            }
            Ok(Token::Real(v * (base as f64).powi(exp_val)))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn toks(s: &str) -> Vec<Token> {
        lex(s, 0).0.into_iter().map(|t| t.0).collect()
    }

    #[test]
    fn literals() {
        assert_eq!(
            toks("16#FF# 8#340# 2#1010_0001# 1_000 2E3"),
            vec![
                Token::Int(IntLit::new(255)),
                Token::Int(IntLit::new(224)),
                Token::Int(IntLit::new(161)),
                Token::Int(IntLit::new(1000)),
                Token::Int(IntLit::new(2000))
            ]
        );
        assert_eq!(
            toks("1.0E-3 16#F.8#"),
            vec![Token::Real(1.0e-3), Token::Real(15.5)]
        );
    }

    #[test]
    fn keywords_in_any_case_and_longer_words_as_names() {
        // The longest keyword (12 letters) in any case; a 13-letter word and
        // a non-ASCII one are names, spelled as written.
        assert_eq!(
            toks("SYNCHRONIZED Synchronized synchronized End_Effectors Öffnung_Ende BEGIN"),
            vec![
                Token::Kw(Kw::Synchronized),
                Token::Kw(Kw::Synchronized),
                Token::Kw(Kw::Synchronized),
                Token::Ident("End_Effectors".into()),
                Token::Ident("Öffnung_Ende".into()),
                Token::Kw(Kw::Begin),
            ]
        );
        let (_, diags) = lex("Grip__Force Axis_ Gripper", 0);
        assert_eq!(diags.len(), 2, "{diags:?}");
    }

    #[test]
    fn tick_ambiguity() {
        assert_eq!(
            toks("Character'('a')"),
            vec![
                Token::Ident("Character".into()),
                Token::Tick,
                Token::LParen,
                Token::Char('a'),
                Token::RParen
            ]
        );
        assert_eq!(
            toks("X := ''';"),
            vec![
                Token::Ident("X".into()),
                Token::Assign,
                Token::Char('\''),
                Token::Semi
            ]
        );
    }

    #[test]
    fn a_run_of_one_stray_character_is_one_diagnostic() {
        // 20,000 `@` pasted in used to be 20,000 diagnostics, each showing
        // the whole line (minutes of output); a run is one mistake.
        let src = format!("A {} B @ @ $$", "@".repeat(20_000));
        let (t, d) = lex(&src, 0);
        let got: Vec<(String, usize, usize)> = d
            .iter()
            .map(|d| {
                (
                    d.message.clone(),
                    d.span.start as usize,
                    d.span.end as usize,
                )
            })
            .collect();
        assert_eq!(
            got,
            [
                (
                    "unexpected characters `@` (20000 of them)".to_string(),
                    2,
                    20_002
                ),
                ("unexpected character `@`".to_string(), 20_005, 20_006),
                ("unexpected character `@`".to_string(), 20_007, 20_008),
                (
                    "unexpected characters `$` (2 of them)".to_string(),
                    20_009,
                    20_011
                ),
            ]
        );
        assert_eq!(t.len(), 2);
    }

    #[test]
    fn errors_continue() {
        // Each bad piece gives one diagnostic at its own place, and lexing
        // goes on after it: the tokens around the errors all come out.
        let src = "A $ B := 'abc' \"open";
        let (t, d) = lex(src, 0);
        let got: Vec<(String, &str)> = d
            .iter()
            .map(|d| {
                (
                    d.message.clone(),
                    &src[d.span.start as usize..d.span.end as usize],
                )
            })
            .collect();
        let toks: Vec<(Token, &str)> = t
            .iter()
            .map(|(tok, sp)| (tok.clone(), &src[sp.start as usize..sp.end as usize]))
            .collect();
        assert_eq!(
            got,
            [
                ("unexpected character `$`".to_string(), "$"),
                ("string literal in single quotes".to_string(), "'abc'"),
                ("unterminated string literal".to_string(), "\"open"),
            ]
        );
        assert_eq!(
            toks,
            [
                (Token::Ident("A".into()), "A"),
                (Token::Ident("B".into()), "B"),
                (Token::Assign, ":="),
                (Token::Str("abc".into()), "'abc'"),
                (Token::Str("open".into()), "\"open"),
            ]
        );
    }
}
