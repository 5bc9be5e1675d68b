//! Every diagnostic code of adair, its one-line title and its page for
//! `adair explain` (`docs/errors/CODE.md`: what it means, a wrong and a
//! right example, which the tests check and run).
//!
//! Architecture invariant: a code, once given, keeps its meaning; a code
//! that is no longer produced stays in the table (say so on its page).
//! Errors are `E0xxx`, warnings `W0xxx`: `E00xx` lexical, `E01xx` syntax,
//! `E02xx` names, `E03xx` types and values, `E04xx` subprograms and
//! statements, `E05xx` tasks and devices, `E07xx` outside the subset,
//! `E09xx` run time.

/// A stable diagnostic code, such as `E0201`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Code(pub &'static str);

impl std::fmt::Display for Code {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.0)
    }
}

/// One entry of the table.
pub struct Entry {
    pub code: Code,
    pub title: &'static str,
    /// The page `adair explain` prints (Markdown).
    pub page: &'static str,
}

macro_rules! codes {
    ($($name:ident: $title:literal,)*) => {
        $(
            #[doc = $title]
            pub const $name: Code = Code(stringify!($name));
        )*
        /// Every code, in order.
        pub const ALL: &[Entry] = &[
            $(Entry {
                code: $name,
                title: $title,
                page: include_str!(concat!("../../docs/errors/", stringify!($name), ".md")),
            },)*
        ];
    };
}

codes! {
    E0001: "a character that is not part of any Ada token",
    E0002: "a string literal without its closing quote",
    E0003: "a string literal in single quotes",
    E0004: "a malformed numeric literal",
    E0101: "text the grammar does not expect here",
    E0102: "a construct without its `end`",
    E0103: "a missing `;`, `then`, `loop` or `is`",
    E0104: "an operator or word from another language (`==`, `=` for `:=`, `inout`)",
    E0105: "nesting or an operator chain past adair's limits",
    E0106: "a malformed part of a construct",
    E0201: "a name that is not declared",
    E0202: "a name declared twice",
    E0203: "a `with` of a unit that cannot be found or read",
    E0204: "a name of the wrong kind of entity for its place",
    E0205: "a declaration without its body",
    E0206: "a body without its declaration",
    E0207: "a private type or deferred constant declared or completed wrongly",
    E0301: "a value of the wrong type",
    E0302: "a static value outside its type's range",
    E0303: "a call that no version of the subprogram accepts, or more than one",
    E0304: "an operator not defined for these operands",
    E0305: "a conversion between types that cannot be converted",
    E0306: "an assignment to something that is not a variable",
    E0307: "an aggregate that does not fit its type",
    E0308: "an attribute used wrongly",
    E0309: "a value that must be static and is not",
    E0310: "a `case` whose choices do not cover each value once",
    E0311: "a name indexed, called or selected wrongly",
    E0312: "a constraint that does not fit its type",
    E0313: "a renaming of a value that is not an object",
    E0314: "a discriminant part or discriminant constraint used wrongly",
    E0315: "a record aggregate that does not fit the variant its discriminants choose",
    E0316: "an assignment to a discriminant",
    E0317: "the full view of a private type used outside its package",
    E0318: "a value of a limited type copied or compared",
    E0401: "a `return` that does not fit its subprogram",
    E0402: "a statement that is not an assignment or a procedure call",
    E0403: "an `exit` or loop name that names no enclosing loop",
    E0404: "a parameter declared wrongly",
    E0405: "an import that does not match the service or builtin",
    E0406: "a subprogram renaming whose profile no subprogram of that name has",
    E0407: "a subprogram renaming whose modes or names do not conform",
    E0501: "an entry, `accept` or entry call used wrongly",
    E0502: "a protected object's rule broken",
    E0503: "a device, register, interrupt or address clause used wrongly",
    E0504: "a `delay` or timed call used wrongly",
    E0505: "an entry family or its index used wrongly",
    E0506: "a `requeue` used wrongly",
    E0701: "a feature of Ada that is outside the AdaIR subset",
    E0901: "an exception that no handler caught",
    E0902: "a deadlock: every task is blocked",
    E0903: "a run stopped by the user (Ctrl-C)",
    W0001: "a variable that is never read",
    W0002: "a service that only the simulator has",
    W0003: "a number of degrees where radians are expected",
    W0004: "a static value that will raise `Constraint_Error`",
    W0005: "a motion before `InitRobot`",
    W0006: "a literal target the robot cannot reach",
}

/// The entry of a code, written as the user typed it (`e0201` too).
pub fn lookup(code: &str) -> Option<&'static Entry> {
    ALL.iter()
        .find(|e| e.code.0.eq_ignore_ascii_case(code.trim()))
}
