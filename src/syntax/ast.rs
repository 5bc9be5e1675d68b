//! The abstract syntax tree, as parsed: names are still strings and
//! `F (X)` is still ambiguous (call, index, conversion); the checker decides.

use crate::diag::Span;
use serde::{Deserialize, Serialize};
use std::rc::Rc;

/// An identifier. Its two strings are shared by every occurrence of the
/// same spelling (interned per thread), so that a long program's names
/// cost no memory each (issue 14).
#[derive(Clone, Debug, PartialEq)]
pub struct Ident {
    /// As written, for messages.
    pub name: Rc<str>,
    /// Lower case, for look-up.
    pub key: Rc<str>,
    pub span: Span,
}

thread_local! {
    /// Spelling -> (spelling, lower case), shared by the idents of a thread.
    /// (Sized for a short program's names and the library's: growing from
    /// empty rehashed it five times at every start.)
    static NAMES: std::cell::RefCell<std::collections::HashMap<Rc<str>, Rc<str>>> =
        std::cell::RefCell::new(std::collections::HashMap::with_capacity(512));
}

/// The shared spelling and lower-case key of a name.
fn interned(name: &str) -> (Rc<str>, Rc<str>) {
    NAMES.with_borrow_mut(|names| match names.get_key_value(name) {
        Some((n, k)) => (n.clone(), k.clone()),
        None => {
            let n: Rc<str> = name.into();
            // Ada identifiers are case-insensitive in every script.
            let k: Rc<str> = if name
                .bytes()
                .all(|b| b.is_ascii() && !b.is_ascii_uppercase())
            {
                // Its own key, which is not interned yet (it missed).
                n.clone()
            } else {
                let lower = name.to_lowercase();
                match names.get_key_value(lower.as_str()) {
                    Some((k, _)) => k.clone(),
                    None if lower == name => n.clone(),
                    None => lower.into(),
                }
            };
            names.insert(n.clone(), k.clone());
            (n, k)
        }
    })
}

/// The shared spelling of a name (the lexer's identifier tokens).
pub fn intern(name: &str) -> Rc<str> {
    interned(name).0
}

impl Ident {
    pub fn new(name: &str, span: Span) -> Self {
        let (name, key) = interned(name);
        Ident { name, key, span }
    }
}

/// An identifier is kept (`syntax::compact`) as its spelling and its span;
/// read back, it is interned as the lexer interns it.
impl Serialize for Ident {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        (&*self.name, self.span).serialize(s)
    }
}

impl<'de> Deserialize<'de> for Ident {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let (name, span) = <(&'de str, Span)>::deserialize(d)?;
        Ok(Ident::new(name, span))
    }
}

/// What an unsupported construct is (a text of the parser's). (A name for
/// the type: serde would take a `&str` field for one borrowed from its input.)
pub type What = &'static str;

/// A tree with an unsupported construct is not kept in the compact form
/// (`syntax::compact`).
mod unsupported {
    use serde::{Deserializer, Serializer, de, ser};

    pub fn serialize<S: Serializer>(_: &super::What, _: S) -> Result<S::Ok, S::Error> {
        Err(ser::Error::custom("an unsupported construct"))
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(_: D) -> Result<super::What, D::Error> {
        Err(de::Error::custom("an unsupported construct"))
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CompilationUnit {
    pub items: Vec<TopItem>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum TopItem {
    With(Vec<Name>, Span),
    Use(Vec<Name>, Span),
    Decl(Box<Decl>),
    Stmt(Stmt),
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Decl {
    pub kind: DeclKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum DeclKind {
    Object {
        names: Vec<Ident>,
        constant: bool,
        ty: SubtypeInd,
        init: Option<Expr>,
        /// An anonymous array type (`A : array (1 .. 3) of Float;`), named by `ty.mark`.
        anon: Option<Box<TypeDef>>,
    },
    /// `K : constant := 2.5;`
    Number {
        names: Vec<Ident>,
        value: Expr,
    },
    Type {
        name: Ident,
        /// `type R (Kind : Tool_Kind := Jaws) is ...`: the discriminant
        /// part (empty without one), read as a parameter list.
        discriminants: Vec<Param>,
        /// `type T (<>) is private;`: unknown discriminants (RM 3.7(1)),
        /// where the box is.
        unknown_discriminants: Option<Span>,
        def: TypeDef,
    },
    Subtype {
        name: Ident,
        ind: SubtypeInd,
    },
    Exception {
        names: Vec<Ident>,
    },
    /// A subprogram specification alone (forward declaration or imported).
    SubprogramDecl {
        spec: SubprogramSpec,
        import: Option<String>,
    },
    SubprogramBody(Box<SubprogramBody>),
    PackageSpec(Box<PackageSpec>),
    PackageBody(Box<PackageBody>),
    Use(Vec<Name>),
    /// A declaration outside the subset; kept for messages.
    Unsupported(#[serde(with = "unsupported")] What),
    /// A renaming declaration (RM 8.5): `X : T renames Y;`,
    /// `E : exception renames F;`, `package P renames Q;`,
    /// `procedure P (...) renames Q;`.
    Renaming(Box<Renaming>),
    /// An unsupported declaration and the names it would declare (a
    /// generic unit and its formals, an instance, a separate body): the
    /// checker reports it once, and uses of these names raise no
    /// follow-on "not declared".
    UnsupportedNamed(#[serde(with = "unsupported")] What, Vec<Ident>),
    TaskSpec(Box<TaskSpec>),
    TaskBody(Box<TaskBody>),
    /// `for E use at Addr;` (an interrupt entry or a device register).
    InterruptUse {
        entry: Ident,
        address: Expr,
    },
    ProtectedSpec(Box<ProtectedSpec>),
    ProtectedBody(Box<ProtectedBody>),
    /// `entry E (...) when Barrier is ... begin ... end E;` in a protected body.
    EntryBody(Box<EntryBody>),
    /// `pragma Name (Args);`
    Pragma {
        name: Ident,
        args: Vec<Expr>,
    },
}

/// A renaming declaration: what it declares, and the name after `renames`
/// (an expression, as parsed: the checker says whether it is a name of the
/// right kind).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Renaming {
    pub what: Renamed,
    pub renamed: Expr,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Renamed {
    /// `X : T renames Y;` (the subtype mark alone).
    Object { name: Ident, ty: Name },
    /// `E : exception renames F;`
    Exception(Ident),
    /// `package P renames Q;`
    Package(Ident),
    /// `procedure P (...) renames Q;`, `function "+" (...) return T renames Q;`
    Subprogram(SubprogramSpec),
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SubtypeInd {
    pub mark: Name,
    pub constraint: Option<Constraint>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Constraint {
    Range(Box<Expr>, Box<Expr>),
    /// Index constraint: `String (1 .. 10)`, `Matrix (1 .. 3, 1 .. 4)`;
    /// also a discriminant constraint of positional values only
    /// (`Buffer (80)`, `Gripper (Vacuum)`), which the checker tells apart
    /// by the type.
    Index(Vec<DiscreteRange>),
    /// A discriminant constraint with named values: `Station (Id => 7,
    /// Speed => 40)`, `Station (7, Speed => 40)` (positional ones first).
    Discriminants(Vec<Arg>),
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum DiscreteRange {
    Range(Expr, Expr),
    /// A subtype name, possibly with a range constraint, or `T'Range`.
    Subtype(SubtypeInd),
    /// `A'Range` / `A'Range (N)`
    Attr(Expr),
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum TypeDef {
    Enum(Vec<EnumLit>),
    IntRange(Expr, Expr),
    /// `mod N`: a modular type, values 0 .. N - 1.
    Modular(Expr),
    Float {
        digits: Expr,
        range: Option<(Expr, Expr)>,
    },
    Derived(SubtypeInd),
    Array {
        /// `Positive range <>` for unconstrained (Some(mark) each), or ranges.
        index: ArrayIndex,
        elem: SubtypeInd,
    },
    Record(ComponentList),
    Access(SubtypeInd),
    /// `type T;` incomplete declaration (for linked structures).
    Incomplete,
    /// `type T is private;` / `type T is limited private;` in a package's
    /// visible part, completed in its private part.
    Private {
        limited: bool,
    },
    Unsupported(#[serde(with = "unsupported")] What),
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum EnumLit {
    Ident(Ident),
    Char(char, Span),
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum ArrayIndex {
    Unconstrained(Vec<Name>),
    Constrained(Vec<DiscreteRange>),
}

/// The components of a record (or of one variant): the components, then
/// the variant part if there is one.
#[derive(Clone, Debug, PartialEq, Default, Serialize, Deserialize)]
pub struct ComponentList {
    pub components: Vec<Component>,
    pub variants: Option<Box<VariantPart>>,
}

/// `case Kind is when Jaws => ...; when others => null; end case;`
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct VariantPart {
    /// The discriminant that chooses the variant.
    pub discriminant: Ident,
    pub arms: Vec<CaseArm<ComponentList>>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Component {
    pub names: Vec<Ident>,
    pub ty: SubtypeInd,
    pub default: Option<Expr>,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Mode {
    In,
    Out,
    InOut,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Param {
    pub names: Vec<Ident>,
    pub mode: Mode,
    pub ty: Name,
    pub default: Option<Expr>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Designator {
    Ident(Ident),
    /// `"*"` and other operator symbols.
    Op(String, Span),
}

impl Designator {
    pub fn key(&self) -> String {
        match self {
            Designator::Ident(i) => i.key.to_string(),
            Designator::Op(o, _) => format!("\"{}\"", o.to_ascii_lowercase()),
        }
    }
    pub fn span(&self) -> Span {
        match self {
            Designator::Ident(i) => i.span,
            Designator::Op(_, s) => *s,
        }
    }
    pub fn display(&self) -> String {
        match self {
            Designator::Ident(i) => i.name.to_string(),
            Designator::Op(o, _) => format!("\"{o}\""),
        }
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SubprogramSpec {
    pub name: Designator,
    pub params: Vec<Param>,
    /// `Some` for functions.
    pub ret: Option<Name>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SubprogramBody {
    pub spec: SubprogramSpec,
    pub decls: Vec<Decl>,
    pub body: Block,
    pub end_name: Option<(String, Span)>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PackageSpec {
    pub name: Name,
    pub decls: Vec<Decl>,
    pub private: Vec<Decl>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PackageBody {
    pub name: Name,
    pub decls: Vec<Decl>,
    pub init: Option<Block>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TaskSpec {
    pub name: Ident,
    /// `task type T (Id : Positive) is`: its discriminant part.
    pub discriminants: Vec<Param>,
    pub entries: Vec<EntryDecl>,
    pub is_type: bool,
    /// `for E use at Addr;` inside the spec.
    pub addresses: Vec<(Ident, Expr)>,
    /// `pragma Priority (N);` inside the spec.
    pub priority: Option<Expr>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ProtectedSpec {
    pub name: Ident,
    /// `protected type P (Size : Positive) is`: its discriminant part.
    pub discriminants: Vec<Param>,
    pub is_type: bool,
    /// Subprogram declarations and entries (as `SubprogramDecl` and `Entry`).
    pub ops: Vec<ProtOp>,
    /// The private part: components (object declarations) and more operations.
    pub private: Vec<Decl>,
    /// The private part's entries (called from the body only: requeue
    /// targets).
    pub private_entries: Vec<EntryDecl>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum ProtOp {
    Sub(SubprogramSpec),
    Entry(EntryDecl),
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ProtectedBody {
    pub name: Ident,
    pub decls: Vec<Decl>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EntryBody {
    pub name: Ident,
    /// `(for I in Range)` of an entry family's body: the index's name and
    /// the family's range.
    pub family: Option<(Ident, DiscreteRange)>,
    pub params: Vec<Param>,
    pub barrier: Expr,
    pub decls: Vec<Decl>,
    pub body: Block,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EntryDecl {
    pub name: Ident,
    /// `entry E (Range) (...)`: an entry family and its index range.
    pub family: Option<DiscreteRange>,
    pub params: Vec<Param>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TaskBody {
    pub name: Ident,
    pub decls: Vec<Decl>,
    pub body: Block,
}

/// `begin stmts [exception handlers] end`
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Block {
    /// In a cell so that the checker can take the statements it has
    /// lowered and drop them one by one (a long program's AST and its
    /// checked form are then not both held whole; issue 14).
    pub stmts: std::cell::RefCell<Vec<Stmt>>,
    pub handlers: Vec<Handler>,
    pub span: Span,
    /// A subprogram body's statements not parsed yet: where they are in
    /// the text (`stmts` is then empty). `adair check` and `run` parse a
    /// file's bodies this way and the checker parses each a part at a time
    /// as it lowers it (see `syntax::parse_source_lazy`).
    pub lazy: Option<Span>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Handler {
    pub occurrence: Option<Ident>,
    /// Empty choices vector never happens; `others` is `None` in the list.
    pub choices: Vec<Option<Name>>,
    pub stmts: Vec<Stmt>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Stmt {
    pub kind: StmtKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum StmtKind {
    Null,
    Assign(Box<Expr>, Box<Expr>),
    /// A procedure call or entry call (a name, possibly with arguments).
    Call(Box<Expr>),
    If {
        arms: Vec<(Expr, Vec<Stmt>)>,
        els: Option<Vec<Stmt>>,
    },
    Case {
        subject: Box<Expr>,
        arms: Vec<CaseArm<Vec<Stmt>>>,
    },
    Loop {
        label: Option<Box<Ident>>,
        scheme: Box<LoopScheme>,
        body: Vec<Stmt>,
        end_label: Option<Box<Ident>>,
    },
    Exit {
        label: Option<Box<Ident>>,
        cond: Option<Box<Expr>>,
    },
    Return(Option<Box<Expr>>),
    Block {
        label: Option<Box<Ident>>,
        decls: Vec<Decl>,
        body: Box<Block>,
    },
    Raise {
        name: Option<Box<Name>>,
        message: Option<Box<Expr>>,
    },
    /// `delay D;` or `delay until T;` (true).
    Delay(bool, Box<Expr>),
    /// `abort T1, T2;`
    Abort(Vec<Expr>),
    Accept {
        entry: Box<Ident>,
        /// `accept E (I) ...`: the member of an entry family.
        index: Option<Box<Expr>>,
        params: Vec<Param>,
        body: Option<Box<Block>>,
    },
    Select(Vec<SelectAlt>),
    /// `requeue E [with abort];`
    Requeue {
        target: Box<Expr>,
        abort: bool,
    },
    /// A declaration among statements (script mode only).
    Decl(Box<Decl>),
    Error,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SelectAlt {
    pub guard: Option<Expr>,
    pub kind: SelectKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum SelectKind {
    Accept(Box<Stmt>, Vec<Stmt>),
    /// `delay [until] D; stmts`
    Delay(bool, Expr, Vec<Stmt>),
    /// An entry call and the statements after it (timed and conditional calls).
    Call(Expr, Vec<Stmt>),
    Terminate,
    Else(Vec<Stmt>),
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CaseArm<T> {
    pub choices: Vec<Choice>,
    pub body: T,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Choice {
    Expr(Expr),
    Range(Expr, Expr),
    Others(Span),
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum LoopScheme {
    Plain,
    While(Expr),
    For {
        var: Ident,
        reverse: bool,
        range: DiscreteRange,
    },
    /// `for E of [reverse] A loop`: each component of the array `A`.
    ForOf {
        var: Ident,
        reverse: bool,
        array: Expr,
    },
}

pub type Name = Expr;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum BinOp {
    And,
    Or,
    Xor,
    AndThen,
    OrElse,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    Add,
    Sub,
    Cat,
    Mul,
    Div,
    Mod,
    Rem,
    Pow,
}

impl BinOp {
    pub fn symbol(self) -> &'static str {
        match self {
            BinOp::And => "and",
            BinOp::Or => "or",
            BinOp::Xor => "xor",
            BinOp::AndThen => "and then",
            BinOp::OrElse => "or else",
            BinOp::Eq => "=",
            BinOp::Ne => "/=",
            BinOp::Lt => "<",
            BinOp::Le => "<=",
            BinOp::Gt => ">",
            BinOp::Ge => ">=",
            BinOp::Add => "+",
            BinOp::Sub => "-",
            BinOp::Cat => "&",
            BinOp::Mul => "*",
            BinOp::Div => "/",
            BinOp::Mod => "mod",
            BinOp::Rem => "rem",
            BinOp::Pow => "**",
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum UnOp {
    Neg,
    Plus,
    Not,
    Abs,
}

impl UnOp {
    pub fn symbol(self) -> &'static str {
        match self {
            UnOp::Neg => "-",
            UnOp::Plus => "+",
            UnOp::Not => "not",
            UnOp::Abs => "abs",
        }
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Assoc {
    /// Empty for positional; several for `A | B => X`.
    pub choices: Vec<Choice>,
    pub value: Expr,
    /// `<>` as the value (default component).
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum ExprKind {
    Int(crate::syntax::token::IntLit),
    Real(f64),
    Char(char),
    Str(String),
    Null,
    Name(Ident),
    /// `Prefix.Selector`
    Select(Box<Expr>, Ident),
    /// `Prefix.all`
    Deref(Box<Expr>),
    /// `Prefix (args)`: call, index, conversion or slice.
    Apply(Box<Expr>, Vec<Arg>),
    /// `Prefix'Attr` with optional arguments.
    Attr(Box<Expr>, Ident, Vec<Expr>),
    /// `T'(expr)` or `T'(aggregate)`.
    Qualified(Box<Expr>, Box<Expr>),
    Binary(BinOp, Box<Expr>, Box<Expr>),
    Unary(UnOp, Box<Expr>),
    /// `X [not] in A .. B` / `X [not] in T`
    Membership {
        negated: bool,
        subject: Box<Expr>,
        choices: Vec<Choice>,
    },
    Aggregate(Vec<Assoc>),
    If {
        arms: Vec<(Expr, Expr)>,
        els: Option<Box<Expr>>,
    },
    Case {
        subject: Box<Expr>,
        arms: Vec<CaseArm<Expr>>,
    },
    /// `new T` / `new T'(...)`
    Allocator(Box<Expr>, Option<Box<Expr>>),
    /// `(Expr)` kept so that `(A)` is not taken for a one-element aggregate.
    Paren(Box<Expr>),
    Error,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Arg {
    pub name: Option<Ident>,
    pub value: Expr,
    pub span: Span,
}

#[cfg(test)]
mod tests {
    /// Statement lists hold their statements inline: a big variant inline
    /// made every statement of a long program cost 576 bytes (issue 14).
    #[test]
    fn statements_stay_small() {
        use std::mem::size_of;
        // Expressions and the token stream (a long program's AST and
        // tokens are held whole while it parses): interned identifiers and
        // an 8-byte-aligned integer literal keep them at 112 and 48 bytes
        // (they were 144 and 64).
        assert!(
            size_of::<super::Expr>() <= 112,
            "{}",
            size_of::<super::Expr>()
        );
        let token = size_of::<(crate::syntax::token::Token, crate::diag::Span)>();
        assert!(token <= 48, "{token}");
        assert!(
            size_of::<super::Stmt>() <= 80,
            "{}",
            size_of::<super::Stmt>()
        );
        assert!(
            size_of::<super::TopItem>() <= 96,
            "{}",
            size_of::<super::TopItem>()
        );
    }
}
