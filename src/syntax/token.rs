//! Tokens of AdaIR (Ada 2012 lexical rules, chapter 2 of the RM).

use std::fmt;

/// Reserved words of Ada 2012 (all of them, so that unsupported ones are
/// recognised and reported as "not supported" instead of as identifiers).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kw {
    Abort,
    Abs,
    Abstract,
    Accept,
    Access,
    Aliased,
    All,
    And,
    Array,
    At,
    Begin,
    Body,
    Case,
    Constant,
    Declare,
    Delay,
    Delta,
    Digits,
    Do,
    Else,
    Elsif,
    End,
    Entry,
    Exception,
    Exit,
    For,
    Function,
    Generic,
    Goto,
    If,
    In,
    Interface,
    Is,
    Limited,
    Loop,
    Mod,
    New,
    Not,
    Null,
    Of,
    Or,
    Others,
    Out,
    Overriding,
    Package,
    Pragma,
    Private,
    Procedure,
    Protected,
    Raise,
    Range,
    Record,
    Rem,
    Renames,
    Requeue,
    Return,
    Reverse,
    Select,
    Separate,
    Some,
    Subtype,
    Synchronized,
    Tagged,
    Task,
    Terminate,
    Then,
    Type,
    Until,
    Use,
    When,
    While,
    With,
    Xor,
}

impl Kw {
    pub const ALL: &'static [(&'static str, Kw)] = &[
        ("abort", Kw::Abort),
        ("abs", Kw::Abs),
        ("abstract", Kw::Abstract),
        ("accept", Kw::Accept),
        ("access", Kw::Access),
        ("aliased", Kw::Aliased),
        ("all", Kw::All),
        ("and", Kw::And),
        ("array", Kw::Array),
        ("at", Kw::At),
        ("begin", Kw::Begin),
        ("body", Kw::Body),
        ("case", Kw::Case),
        ("constant", Kw::Constant),
        ("declare", Kw::Declare),
        ("delay", Kw::Delay),
        ("delta", Kw::Delta),
        ("digits", Kw::Digits),
        ("do", Kw::Do),
        ("else", Kw::Else),
        ("elsif", Kw::Elsif),
        ("end", Kw::End),
        ("entry", Kw::Entry),
        ("exception", Kw::Exception),
        ("exit", Kw::Exit),
        ("for", Kw::For),
        ("function", Kw::Function),
        ("generic", Kw::Generic),
        ("goto", Kw::Goto),
        ("if", Kw::If),
        ("in", Kw::In),
        ("interface", Kw::Interface),
        ("is", Kw::Is),
        ("limited", Kw::Limited),
        ("loop", Kw::Loop),
        ("mod", Kw::Mod),
        ("new", Kw::New),
        ("not", Kw::Not),
        ("null", Kw::Null),
        ("of", Kw::Of),
        ("or", Kw::Or),
        ("others", Kw::Others),
        ("out", Kw::Out),
        ("overriding", Kw::Overriding),
        ("package", Kw::Package),
        ("pragma", Kw::Pragma),
        ("private", Kw::Private),
        ("procedure", Kw::Procedure),
        ("protected", Kw::Protected),
        ("raise", Kw::Raise),
        ("range", Kw::Range),
        ("record", Kw::Record),
        ("rem", Kw::Rem),
        ("renames", Kw::Renames),
        ("requeue", Kw::Requeue),
        ("return", Kw::Return),
        ("reverse", Kw::Reverse),
        ("select", Kw::Select),
        ("separate", Kw::Separate),
        ("some", Kw::Some),
        ("subtype", Kw::Subtype),
        ("synchronized", Kw::Synchronized),
        ("tagged", Kw::Tagged),
        ("task", Kw::Task),
        ("terminate", Kw::Terminate),
        ("then", Kw::Then),
        ("type", Kw::Type),
        ("until", Kw::Until),
        ("use", Kw::Use),
        ("when", Kw::When),
        ("while", Kw::While),
        ("with", Kw::With),
        ("xor", Kw::Xor),
    ];

    /// Looks a lower-case word up among the reserved words.
    pub fn from_lower(word: &str) -> Option<Kw> {
        Self::ALL
            .binary_search_by(|(w, _)| (*w).cmp(word))
            .ok()
            .map(|i| Self::ALL[i].1)
    }

    pub fn as_str(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(_, k)| *k == self)
            .map(|(w, _)| *w)
            .unwrap_or("?")
    }
}

/// The value of an integer literal: an `i128` kept in two 8-byte halves,
/// so that it does not raise the alignment (and size) of every token and
/// expression to 16 bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct IntLit([u64; 2]);

impl IntLit {
    pub fn new(v: i128) -> IntLit {
        IntLit([v as u64, (v >> 64) as u64])
    }
    pub fn get(self) -> i128 {
        (u128::from(self.0[0]) | (u128::from(self.0[1]) << 64)) as i128
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum Token {
    Kw(Kw),
    /// An identifier as written (case kept for messages).
    Ident(std::rc::Rc<str>),
    Int(IntLit),
    Real(f64),
    Char(char),
    Str(std::rc::Rc<str>),
    /// `'` used as the attribute or qualification mark.
    Tick,
    LParen,
    RParen,
    Comma,
    Semi,
    Colon,
    Dot,
    DotDot,
    Assign,
    Arrow,
    Box,
    Bar,
    Amp,
    Plus,
    Minus,
    Star,
    StarStar,
    Slash,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    /// Placeholder for a lexical error (already reported), so parsing can go on.
    Error,
    /// The statements of a long subprogram body, not lexed into the
    /// skeleton of `syntax::parse_source_lazy` (its span is their text).
    Statements,
}

impl fmt::Display for Token {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Token::Kw(k) => write!(f, "`{}`", k.as_str()),
            Token::Ident(s) => write!(f, "identifier `{s}`"),
            Token::Int(i) => write!(f, "number {}", i.get()),
            Token::Real(r) => write!(f, "number {r}"),
            Token::Char(c) => write!(f, "character '{c}'"),
            Token::Str(s) => write!(f, "string \"{s}\""),
            Token::Error => write!(f, "invalid token"),
            Token::Statements => write!(f, "statements"),
            other => write!(f, "`{}`", other.punct()),
        }
    }
}

impl Token {
    pub fn punct(&self) -> &'static str {
        match self {
            Token::Tick => "'",
            Token::LParen => "(",
            Token::RParen => ")",
            Token::Comma => ",",
            Token::Semi => ";",
            Token::Colon => ":",
            Token::Dot => ".",
            Token::DotDot => "..",
            Token::Assign => ":=",
            Token::Arrow => "=>",
            Token::Box => "<>",
            Token::Bar => "|",
            Token::Amp => "&",
            Token::Plus => "+",
            Token::Minus => "-",
            Token::Star => "*",
            Token::StarStar => "**",
            Token::Slash => "/",
            Token::Eq => "=",
            Token::Ne => "/=",
            Token::Lt => "<",
            Token::Le => "<=",
            Token::Gt => ">",
            Token::Ge => ">=",
            _ => "",
        }
    }
}
