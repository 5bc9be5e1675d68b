//! The diagnostics of the checker, each built by a named constructor with its code (`E02xx` names, `E03xx` types and values, `E04xx` subprograms and statements, `E05xx` tasks and devices, `E07xx` outside the subset, `W0xxx` warnings; see `diag::codes`).
//!
//! A constructor takes the words its message is built from (names,
//! types, values), so that the wording of a fault lives in one place and
//! code decides by [`Diagnostic::code`], never by a message's words.
//!
//! One file for one concern, though long: one constructor per message
//! family, by code, so that every message of the checker is read in one
//! place.

use crate::diag::codes::{self, Code};
use crate::diag::{Diagnostic, Span};
use std::fmt::Display;

fn d(code: Code, span: Span, message: impl Into<String>) -> Diagnostic {
    Diagnostic::new(code, span, message)
}

fn join<S: AsRef<str>>(items: &[S], sep: &str) -> String {
    items
        .iter()
        .map(|s| s.as_ref())
        .collect::<Vec<&str>>()
        .join(sep)
}

// ---- E0106: malformed parts the checker finds ----

pub fn not_an_operator_symbol(span: Span, op: &str) -> Diagnostic {
    d(
        codes::E0106,
        span,
        format!("\"{op}\" is not an operator symbol"),
    )
}

/// `end N;` that does not repeat the unit's name.
pub fn end_name_mismatch(span: Span, end: &str, name: &str) -> Diagnostic {
    d(
        codes::E0106,
        span,
        format!("`end {end};` does not match `{name}`"),
    )
    .with_hint(format!("write `end {name};`"))
}

pub fn end_loop_mismatch(span: Span, end: &str, name: &str) -> Diagnostic {
    d(
        codes::E0106,
        span,
        format!("`end loop {end}` does not match the loop name `{name}`"),
    )
}

pub fn end_loop_unnamed(span: Span, end: &str) -> Diagnostic {
    d(
        codes::E0106,
        span,
        format!("the loop has no name, but its end says `{end}`"),
    )
}

pub fn constant_without_value(span: Span) -> Diagnostic {
    d(codes::E0106, span, "a constant needs an initial value")
}

pub fn others_in_membership(span: Span) -> Diagnostic {
    d(
        codes::E0106,
        span,
        "`others` is not allowed in a membership test",
    )
}

/// `raise;` outside an exception handler.
pub fn reraise_outside_handler(span: Span) -> Diagnostic {
    d(
        codes::E0106,
        span,
        "`raise;` re-raises, so it can only stand in an exception handler",
    )
    .with_hint("name the exception: `raise Constraint_Error;`")
}

// ---- E0201: names not declared ----

/// `name` is not declared (its hint, if any, is set by the caller:
/// [`Diagnostic::with_guess`] for a spelling guess).
pub fn not_declared(span: Span, name: &str) -> Diagnostic {
    d(codes::E0201, span, format!("`{name}` is not declared"))
        .with_label("undefined name")
        .about(&[name])
}

/// What AdaIR calls a command of another robot language (RAPID, KRL,
/// URScript, RoboDK, MELFA BASIC), by its lower-case name.
pub fn from_other_robot_languages(key: &str) -> Option<&'static str> {
    const GRIP: &str = "AdaIR opens and closes the hand with `MoveTool (Distance, Force)`: `MoveTool (60.0, 0.0);` opens it to 60 mm, `MoveTool (0.0, 10.0);` closes it until it grips with 10 N";
    const SPEED: &str =
        "AdaIR sets the speed with `SetVelocity (Percent);`, e.g. `SetVelocity (50.0);`";
    const LINEAR: &str = "AdaIR moves in a straight line with `SetMoveMode (StraightLine);` and then `MoveFrameAbsolute (F);`";
    const JOINT: &str = "AdaIR moves joint-interpolated with `MoveAxesAbsolute (Axes);` (angles in radians), or `SetMoveMode (JointInterpolated);` and `MoveFrameAbsolute (F);`";
    const HOME: &str = "AdaIR's `InitRobot;` calibrates and moves the arm to its zero pose";
    const WAIT: &str = "Ada waits with `delay 1.5;` (seconds)";
    const PRINT: &str = "Ada prints with `Put_Line (\"text\");` (`Integer'Image (N)` or `Float'Image (X)` make numbers text)";
    Some(match key {
        "gripper"
        | "opengripper"
        | "closegripper"
        | "open_gripper"
        | "close_gripper"
        | "grip"
        | "gripopen"
        | "gripclose"
        | "hopen"
        | "hclose"
        | "setgripper"
        | "set_tool_digital_out" => GRIP,
        "setspeed" | "set_speed" | "speed" | "velset" | "setvel" | "ovr" | "speedset" => SPEED,
        "movelinear" | "move_linear" | "movel" | "lin" | "mvs" | "linear" => LINEAR,
        "movej" | "move_joint" | "movejoint" | "moveabsj" | "ptp" | "mov" | "movjoint" => JOINT,
        "home" | "gohome" | "movehome" | "nest" => HOME,
        "waittime" | "wait" | "sleep" | "dly" => WAIT,
        "tpwrite" | "print" | "textout" | "popup" => PRINT,
        _ => return None,
    })
}

/// `prefix.name` where `prefix` declares no `name`.
pub fn not_declared_in(span: Span, name: &str, prefix: &str) -> Diagnostic {
    d(
        codes::E0201,
        span,
        format!("`{name}` is not declared in `{prefix}`"),
    )
    .about(&[name, prefix])
}

/// A name reported "not declared" that its scope declares later on
/// (`decl` is the declaration; `subprogram`: it declares a subprogram).
pub fn used_before_declaration(span: Span, name: &str, decl: Span, subprogram: bool) -> Diagnostic {
    let hint = if subprogram {
        format!(
            "declare `{name}`'s specification before its first use (Ada resolves names in declaration order)"
        )
    } else {
        format!(
            "move the declaration of `{name}` above its first use (Ada resolves names in declaration order)"
        )
    };
    d(
        codes::E0201,
        span,
        format!("`{name}` is used before its declaration"),
    )
    .with_label("used here before it is declared")
    .with_hint(hint)
    .with_note(decl, "declared here")
    .about(&[name])
}

// ---- E0202: declared twice ----

pub fn declared_twice(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0202,
        span,
        format!("`{name}` is already declared in this scope"),
    )
}

pub fn declared_with_same_profile(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0202,
        span,
        format!("`{name}` is already declared with this profile"),
    )
}

pub fn component_declared_twice(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0202,
        span,
        format!("component `{name}` is declared twice"),
    )
}

pub fn entry_declared_twice(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0202,
        span,
        format!("entry `{name}` is declared twice"),
    )
    .with_hint(
        "entry families and overloaded entries are not supported: give each entry its own name",
    )
}

/// A second body of a task.
pub fn task_body_twice(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0202,
        span,
        format!("task `{name}` already has a body"),
    )
}

/// A second body of a subprogram of a protected type.
pub fn body_twice(span: Span, name: &str) -> Diagnostic {
    d(codes::E0202, span, format!("`{name}` already has a body"))
}

pub fn entry_body_twice(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0202,
        span,
        format!("entry `{name}` already has a body"),
    )
}

// ---- E0203: units ----

pub fn no_library_unit(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0203,
        span,
        format!("no library unit named `{name}`"),
    )
    .with_hint("AdaIR provides Ada.Text_IO, Ada.Integer_Text_IO, Ada.Float_Text_IO, Ada.Numerics, Ada.Numerics.Elementary_Functions, Ada.Calendar, Ada.Real_Time, Ada.Exceptions and AdaIR")
}

// ---- E0204: the wrong kind of entity ----

pub fn not_a_type(span: Span, text: &str) -> Diagnostic {
    d(codes::E0204, span, format!("`{text}` is not a type"))
}

pub fn not_a_package(span: Span, text: &str) -> Diagnostic {
    d(codes::E0204, span, format!("`{text}` is not a package"))
}

pub fn not_an_exception(span: Span, text: &str) -> Diagnostic {
    d(codes::E0204, span, format!("`{text}` is not an exception"))
}

pub fn not_a_subprogram(span: Span, text: &str) -> Diagnostic {
    d(codes::E0204, span, format!("`{text}` is not a subprogram"))
}

pub fn type_is_not_a_value(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0204,
        span,
        format!("the type `{ty}` is not a value"),
    )
    .with_hint(format!(
        "convert a value with `{ty} (X)` or use an attribute like `{ty}'First`"
    ))
}

pub fn exception_is_not_a_value(span: Span, text: &str) -> Diagnostic {
    d(
        codes::E0204,
        span,
        format!("the exception `{text}` is not a value"),
    )
    .with_hint(format!("raise it with `raise {text};`"))
}

pub fn package_is_not_a_value(span: Span, text: &str) -> Diagnostic {
    d(
        codes::E0204,
        span,
        format!("the package `{text}` is not a value"),
    )
}

// ---- E0205: declarations without their bodies ----

pub fn no_body(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0205,
        span,
        format!("`{name}` is declared but has no body"),
    )
    .with_hint(format!(
        "write the body of `{name}` in the same declarative part"
    ))
}

pub fn package_without_body(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0205,
        span,
        format!("package `{name}` declares subprograms but has no body"),
    )
    .with_hint(format!(
        "write `package body {name} is ... end {name};` in the same declarative part"
    ))
}

/// A package body without the body of `member`, which its spec declares.
pub fn package_body_lacks(span: Span, name: &str, member: &str) -> Diagnostic {
    d(
        codes::E0205,
        span,
        format!("package body `{name}` lacks a body for `{member}`"),
    )
}

pub fn task_without_body(span: Span, name: &str) -> Diagnostic {
    d(codes::E0205, span, format!("task `{name}` has no body")).with_hint(format!(
        "write `task body {name} is ... begin ... end {name};` in the same declarative part (in the REPL: in the same entry)"
    ))
}

pub fn protected_without_body(span: Span, name: &str) -> Diagnostic {
    d(codes::E0205, span, format!("protected `{name}` has no body")).with_hint(format!(
        "write `protected body {name} is ... end {name};` in the same declarative part (in the REPL: in the same entry)"
    ))
}

/// A protected body without the body of `what` (a subprogram, with its
/// kind: "procedure `P`").
pub fn protected_body_lacks(span: Span, name: &str, what: &str) -> Diagnostic {
    d(
        codes::E0205,
        span,
        format!("protected body `{name}` lacks a body for `{what}`"),
    )
}

pub fn protected_body_lacks_entry(span: Span, name: &str, entry: &str) -> Diagnostic {
    d(
        codes::E0205,
        span,
        format!("protected body `{name}` lacks a body for entry `{entry}`"),
    )
}

// ---- E0206: bodies without their declarations ----

pub fn package_body_without_spec(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0206,
        span,
        format!("package body `{name}` has no package spec"),
    )
    .with_hint(format!("declare `package {name} is ... end {name};` first"))
}

pub fn task_body_without_spec(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0206,
        span,
        format!("task body `{name}` has no task declaration"),
    )
    .with_hint(format!(
        "declare `task {name} is ... end {name};` (or `task type`) before its body"
    ))
}

pub fn protected_body_without_spec(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0206,
        span,
        format!("protected body `{name}` has no protected declaration"),
    )
}

/// A subprogram body in protected body `prot` that its declaration
/// does not declare.
pub fn not_in_protected_with_profile(span: Span, name: &str, prot: &str) -> Diagnostic {
    d(
        codes::E0206,
        span,
        format!("`{name}` is not declared in protected `{prot}` with this profile"),
    )
}

/// An entry body in protected body `prot` that its declaration does not
/// declare.
pub fn not_an_entry_of_protected(span: Span, name: &str, prot: &str) -> Diagnostic {
    d(
        codes::E0206,
        span,
        format!("`{name}` is not an entry of protected `{prot}`"),
    )
}

// ---- E0207: private types and deferred constants without their completion ----

/// `type T is private;` outside the visible part of a package.
pub fn private_type_context(span: Span) -> Diagnostic {
    d(
        codes::E0207,
        span,
        "a private type can only be declared in the visible part of a package",
    )
    .with_hint("declare it between `package P is` and `private`, and its full type after `private`")
}

pub fn private_type_not_completed(span: Span, name: &str, pkg: &str) -> Diagnostic {
    d(
        codes::E0207,
        span,
        format!("private type `{name}` has no full declaration in the private part of `{pkg}`"),
    )
    .with_hint(format!(
        "declare its full type after `private`: `type {name} is record ... end record;`"
    ))
}

pub fn deferred_constant_not_completed(span: Span, name: &str, pkg: &str) -> Diagnostic {
    d(
        codes::E0207,
        span,
        format!(
            "deferred constant `{name}` has no full declaration in the private part of `{pkg}`"
        ),
    )
    .with_hint(format!(
        "give it its value after `private`: `{name} : constant ... := ...;`"
    ))
}

/// The full type of a private type declared in the visible part.
pub fn full_view_in_visible_part(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0207,
        span,
        format!("the full declaration of private type `{name}` must be in the private part"),
    )
    .with_hint("move it after `private`")
}

/// A deferred constant completed with another type.
pub fn deferred_type_mismatch(span: Span, name: &str, declared: &str, at: Span) -> Diagnostic {
    d(
        codes::E0207,
        span,
        format!("`{name}` is declared a constant of type `{declared}`: its full declaration must have that type"),
    )
    .with_note(at, "the deferred constant is declared here")
}

pub fn limited_completion_of_nonlimited(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0207,
        span,
        format!("private type `{name}` is not limited, so its full type cannot be limited"),
    )
    .with_hint(format!("declare it `type {name} is limited private;`"))
}

/// The full declaration of a private type whose partial view has
/// discriminants (`type Buffer (Size : Positive) is private;`) declares
/// other ones (RM 7.3(13), 6.3.1: full conformance). `what`: GNAT's
/// reason (`name "Count" does not match`, `too few discriminants`).
pub fn discriminants_not_conformant(
    span: Span,
    name: &str,
    what: &str,
    partial: Span,
) -> Diagnostic {
    d(
        codes::E0207,
        span,
        format!("the discriminants of `{name}` are not fully conformant with its partial view: {what}"),
    )
    .with_note(partial, "the partial view declares its discriminants here")
    .with_hint("the full declaration repeats the discriminant part of `type ... is private;`: the same names, subtypes and defaults, in order")
}

/// The full declaration of a private type whose partial view has
/// discriminants declares none.
pub fn full_view_missing_discriminants(span: Span, name: &str, partial: Span) -> Diagnostic {
    d(
        codes::E0207,
        span,
        format!("missing discriminants in the full declaration of `{name}`"),
    )
    .with_label("its partial view has discriminants")
    .with_note(partial, "the partial view declares its discriminants here")
    .with_hint("repeat the discriminant part of `type ... is private;` in the full declaration: a record, task or protected type")
}

/// `(<>)` on a type that is not a private type's partial view.
pub fn unknown_discriminants_on_full_type(span: Span) -> Diagnostic {
    d(
        codes::E0207,
        span,
        "a full type declaration cannot have unknown discriminants",
    )
    .with_label("`(<>)` is for a private type's partial view")
    .with_hint("declare `type T (<>) is private;` in a package's visible part, and the full type, with or without discriminants, in its private part")
}

/// The full type of a private type (without discriminants) that needs a
/// constraint: an unconstrained array, discriminants without defaults.
pub fn indefinite_full_view(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0207,
        span,
        format!("the full type of private type `{name}` must not need a constraint"),
    )
    .with_label("one is constrained, the other unconstrained")
    .with_hint(format!(
        "outside the package, objects of `{name}` are declared without bounds or discriminants: constrain the array (`array (1 .. 8) of ...`) or give the discriminants defaults"
    ))
}

/// An object of a private type before its full declaration.
pub fn premature_private_object(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0207,
        span,
        format!(
            "`{ty}` has no full declaration yet: an object of it can only be declared after it"
        ),
    )
    .with_hint("declare the object after the package, or make it a deferred constant")
}

// ---- E0301: the wrong type ----

/// `found` describes the value (`` `Float` ``, "a number", ...);
/// `found_type` is its type's name.
pub fn type_mismatch(span: Span, expected: &str, found: &str, found_type: &str) -> Diagnostic {
    d(
        codes::E0301,
        span,
        format!("expected `{expected}`, found {found}"),
    )
    .with_label(format!("this has type `{found_type}`"))
}

/// `found`: the condition's type, `None` for a universal number.
pub fn condition_not_boolean(span: Span, found: Option<&str>) -> Diagnostic {
    let found = match found {
        None => "a number".to_string(),
        Some(t) => format!("`{t}`"),
    };
    d(
        codes::E0301,
        span,
        format!("a condition must be Boolean, this is {found}"),
    )
    .with_hint("compare it: `X /= 0`")
}

pub fn range_not_discrete(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0301,
        span,
        format!("a discrete range is needed, `{ty}` is not discrete"),
    )
    .with_hint("ranges of loops and indices are integers or enumerations")
}

pub fn not_a_discrete_type(span: Span, ty: &str) -> Diagnostic {
    d(codes::E0301, span, format!("`{ty}` is not a discrete type"))
}

pub fn range_of_other_type(span: Span, range: &str, ty: &str) -> Diagnostic {
    d(
        codes::E0301,
        span,
        format!("this range is of `{range}`, not `{ty}`"),
    )
}

pub fn not_a_subtype_of(span: Span, sub: &str, ty: &str) -> Diagnostic {
    d(
        codes::E0301,
        span,
        format!("`{sub}` is not a subtype of `{ty}`"),
    )
}

pub fn if_expression_without_else(span: Span) -> Diagnostic {
    d(
        codes::E0301,
        span,
        "an `if` expression needs an `else` part unless it is Boolean",
    )
}

pub fn allocator_without_access_type(span: Span) -> Diagnostic {
    d(
        codes::E0301,
        span,
        "an allocator needs an access type from its context",
    )
    .with_hint("assign it to a variable of an access type")
}

/// An allocator of `ty` for access type `access`, which designates
/// `designated`.
pub fn designates_other_type(span: Span, access: &str, designated: &str, ty: &str) -> Diagnostic {
    d(
        codes::E0301,
        span,
        format!("`{access}` designates `{designated}`, not `{ty}`"),
    )
}

pub fn case_needs_discrete(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0301,
        span,
        format!("a `case` needs a discrete value, this is `{ty}`"),
    )
}

pub fn for_of_needs_array(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0301,
        span,
        format!("`for ... of` needs an array, and this is of type `{ty}`"),
    )
    .with_hint("to count, write `for I in A .. B loop`")
}

pub fn task_expected(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0301,
        span,
        format!("a task is expected here, this is `{ty}`"),
    )
}

// ---- E0302: static values out of range ----

/// A static integer beyond 32 bits, expected of `ty` (an integer type).
pub fn static_outside_integer(span: Span, value: impl Display, ty: &str) -> Diagnostic {
    let ty = match ty {
        "Integer" => "`Integer`".to_string(),
        n => format!("`Integer`, the base type of `{n}`"),
    };
    d(
        codes::E0302,
        span,
        format!(
            "the static value {value} is not in range of {ty} ({} .. {})",
            i32::MIN,
            i32::MAX
        ),
    )
    .with_hint("a static expression is computed exactly, and its value must fit its type")
}

/// A static value outside the values 0 .. `last` of the modular type
/// `ty` (RM 4.9(35): a static expression of a modular type lies in its
/// base range; only its operations wrap around).
pub fn static_outside_modular(span: Span, value: impl Display, ty: &str, last: i64) -> Diagnostic {
    d(
        codes::E0302,
        span,
        format!("the static value {value} is not in range of `{ty}` (0 .. {last})"),
    )
    .with_hint(format!(
        "a modular type's operations wrap around, its literals and conversions do not: write a value in 0 .. {last}"
    ))
}

/// A static real (`shown` as written) beyond the base range of `ty`.
pub fn static_outside_float(span: Span, shown: &str, ty: &str, lo: &str, hi: &str) -> Diagnostic {
    d(
        codes::E0302,
        span,
        format!("{shown} is not in range of `{ty}` ({lo} .. {hi})"),
    )
    .with_hint("a static expression is computed exactly, and its value must fit its type")
}

pub fn integer_literal_too_large(span: Span) -> Diagnostic {
    d(codes::E0302, span, "integer literal too large")
}

/// `T'Val (v)` with `v` outside `lo .. hi`.
pub fn not_a_position(
    span: Span,
    value: impl Display,
    ty: &str,
    lo: impl Display,
    hi: impl Display,
) -> Diagnostic {
    d(
        codes::E0302,
        span,
        format!("{value} is not a position of `{ty}` (its positions are {lo} .. {hi})"),
    )
    .with_label("static value out of range")
}

/// `T'Succ` of the last value (`which` = "Succ", `end` = "last"), or
/// `T'Pred` of the first.
pub fn no_successor(span: Span, which: &str, end: &str, ty: &str) -> Diagnostic {
    d(
        codes::E0302,
        span,
        format!("`'{which}` of the {end} value of `{ty}` has no value"),
    )
    .with_label("static value out of range")
}

// ---- E0303: calls ----

/// Why the arguments of a call do not fit a subprogram's parameters.
#[derive(Debug, Clone, PartialEq)]
pub enum ArgsMismatch {
    PositionalAfterNamed,
    /// The subprogram, its number of parameters, the arguments given.
    TooMany(String, usize, usize),
    /// A parameter named twice.
    GivenTwice(String),
    /// The subprogram, the name given, its parameters.
    NoSuchParameter(String, String, Vec<String>),
    /// The parameter, the subprogram.
    Missing(String, String),
}

impl Display for ArgsMismatch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ArgsMismatch::PositionalAfterNamed => {
                f.write_str("a positional argument cannot follow a named one")
            }
            ArgsMismatch::TooMany(sub, n, given) => {
                write!(f, "`{sub}` takes {n} argument(s), {given} given")
            }
            ArgsMismatch::GivenTwice(p) => write!(f, "parameter `{p}` is given twice"),
            ArgsMismatch::NoSuchParameter(sub, name, params) => write!(
                f,
                "`{sub}` has no parameter named `{name}` (its parameters: {})",
                params.join(", ")
            ),
            ArgsMismatch::Missing(p, sub) => {
                write!(f, "missing argument for parameter `{p}` of `{sub}`")
            }
        }
    }
}

/// The arguments of a call that do not fit the one subprogram of the
/// name (`signature`: its profile).
pub fn arguments_rejected(span: Span, why: &ArgsMismatch, signature: &str) -> Diagnostic {
    d(codes::E0303, span, why.to_string()).with_hint(format!("`{signature}`"))
}

pub fn ambiguous_call<S: AsRef<str>>(span: Span, name: &str, candidates: &[S]) -> Diagnostic {
    d(
        codes::E0303,
        span,
        format!(
            "ambiguous call: {} versions of `{name}` match these arguments",
            candidates.len()
        ),
    )
    .with_hint(format!(
        "qualify an argument with its type, like `T'(X)`; the candidates are:\n  {}",
        join(candidates, "\n  ")
    ))
}

pub fn no_version_accepts<S: AsRef<str>>(span: Span, name: &str, candidates: &[S]) -> Diagnostic {
    d(
        codes::E0303,
        span,
        format!("no version of `{name}` accepts these arguments"),
    )
    .with_hint(format!(
        "the candidates are:\n  {}",
        join(candidates, "\n  ")
    ))
}

// ---- E0304: operators ----

pub fn ordering_undefined(span: Span, op: &str, ty: &str) -> Diagnostic {
    d(
        codes::E0304,
        span,
        format!("`{op}` is not defined for `{ty}`"),
    )
    .with_hint("ordering is defined for scalars and strings")
}

pub fn operands_mixed(span: Span, op: &str, x: &str, y: &str) -> Diagnostic {
    d(
        codes::E0304,
        span,
        format!("`{op}` cannot combine `{x}` and `{y}`"),
    )
    .with_label("Ada does not mix types implicitly")
}

pub fn operator_needs_number(span: Span, op: &str, ty: &str) -> Diagnostic {
    d(
        codes::E0304,
        span,
        format!("`{op}` needs a number, this is `{ty}`"),
    )
}

// ---- E0305: conversions ----

pub fn conversion_arity(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0305,
        span,
        format!("a conversion to `{ty}` takes exactly one value"),
    )
}

/// Between array types whose indices or components differ.
pub fn cannot_convert_arrays(span: Span, from: &str, to: &str) -> Diagnostic {
    d(
        codes::E0305,
        span,
        format!("cannot convert `{from}` to `{to}`"),
    )
}

pub fn cannot_convert(span: Span, from: &str, to: &str) -> Diagnostic {
    cannot_convert_arrays(span, from, to)
        .with_hint("Ada converts only between numeric types, and between related types")
}

// ---- E0306: assignments to what is not a variable ----

/// `what` says how the name is used ("the target of an assignment", ...).
pub fn assigned_constant_or_in(span: Span, name: &str, what: &str) -> Diagnostic {
    d(
        codes::E0306,
        span,
        format!("`{name}` is a constant or an `in` parameter and cannot be assigned"),
    )
    .with_label(format!("used as {what}"))
    .with_hint("declare it as a variable, or make the parameter `in out`")
}

pub fn assigned_constant(span: Span, name: &str, what: &str) -> Diagnostic {
    d(
        codes::E0306,
        span,
        format!("`{name}` is a constant and cannot be assigned"),
    )
    .with_label(format!("used as {what}"))
    .with_hint("declare it as a variable to change it")
}

pub fn not_a_variable(span: Span, what: &str) -> Diagnostic {
    d(codes::E0306, span, format!("{what} must be a variable"))
        .with_label("this is a value, not a variable")
}

// ---- E0307: aggregates ----

pub fn aggregate_type_unknown(span: Span) -> Diagnostic {
    d(
        codes::E0307,
        span,
        "the type of this aggregate cannot be determined",
    )
    .with_hint("qualify it with its type: `T'(...)`")
}

pub fn aggregate_too_many(span: Span, ty: &str, expected: usize) -> Diagnostic {
    d(
        codes::E0307,
        span,
        format!("too many components for `{ty}` ({expected} expected)"),
    )
}

pub fn aggregate_no_component(span: Span, ty: &str, name: &str) -> Diagnostic {
    d(
        codes::E0307,
        span,
        format!("`{ty}` has no component `{name}`"),
    )
}

pub fn record_aggregate_unnamed(span: Span) -> Diagnostic {
    d(
        codes::E0307,
        span,
        "a record aggregate names its components",
    )
}

pub fn aggregate_lacks(span: Span, component: &str, ty: &str) -> Diagnostic {
    d(
        codes::E0307,
        span,
        format!("the aggregate lacks component `{component}` of `{ty}`"),
    )
}

pub fn aggregate_wrong_type(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0307,
        span,
        format!("an aggregate cannot have type `{ty}`"),
    )
}

pub fn aggregate_mixed(span: Span) -> Diagnostic {
    d(
        codes::E0307,
        span,
        "an array aggregate is either positional or named, not both",
    )
}

pub fn aggregate_choice_twice(span: Span, first: Span) -> Diagnostic {
    d(
        codes::E0307,
        span,
        "this aggregate choice covers an index a choice before it covers",
    )
    .with_note(first, "covered here already")
    .with_hint("each index of a named array aggregate is given once")
}

pub fn others_needs_bounds(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0307,
        span,
        "`others` needs the bounds from the context",
    )
    .with_hint(format!(
        "use a constrained subtype, e.g. `{ty} (1 .. 3)'(others => ...)`"
    ))
}

pub fn aggregate_length(span: Span, ty: &str, needed: impl Display, given: usize) -> Diagnostic {
    d(
        codes::E0307,
        span,
        format!("`{ty}` needs {needed} components in this dimension, the aggregate has {given}"),
    )
}

// ---- E0308: attributes ----

pub fn attribute_needs_argument(span: Span, attr: &str) -> Diagnostic {
    d(codes::E0308, span, format!("`'{attr}` needs an argument"))
}

pub fn dimension_not_static(span: Span) -> Diagnostic {
    d(
        codes::E0308,
        span,
        "the dimension must be a static positive integer",
    )
}

pub fn no_such_dimension(span: Span) -> Diagnostic {
    d(codes::E0308, span, "no such dimension")
}

pub fn too_few_dimensions(span: Span, ty: &str, n: usize) -> Diagnostic {
    d(
        codes::E0308,
        span,
        format!("`{ty}` has only {n} dimension(s)"),
    )
}

pub fn val_needs_integer(span: Span) -> Diagnostic {
    d(codes::E0308, span, "`'Val` needs an integer")
}

pub fn range_outside_range_context(span: Span) -> Diagnostic {
    d(
        codes::E0308,
        span,
        "`'Range` can only be used as a range (in `for` loops, memberships and constraints)",
    )
}

const SUPPORTED_ATTRIBUTES: &str =
    "AdaIR supports First Last Range Length Image Value Pos Val Succ Pred Min Max";

pub fn attribute_unsupported_for_type(span: Span, attr: &str, ty: &str) -> Diagnostic {
    d(
        codes::E0308,
        span,
        format!("`'{attr}` is not supported for the type `{ty}`"),
    )
    .with_hint(SUPPORTED_ATTRIBUTES)
}

pub fn attribute_unsupported_on_arrays(span: Span, attr: &str) -> Diagnostic {
    d(
        codes::E0308,
        span,
        format!("`'{attr}` is not supported on arrays"),
    )
}

/// RM 3.7.2(2): `X'Constrained` of an object without discriminants.
pub fn constrained_without_discriminants(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0308,
        span,
        "the prefix of `'Constrained` must be an object of a type with discriminants",
    )
    .with_label(format!("an object of type `{ty}`"))
}

pub fn attribute_unsupported_here(span: Span, attr: &str) -> Diagnostic {
    d(
        codes::E0308,
        span,
        format!("`'{attr}` is not supported here"),
    )
    .with_hint(SUPPORTED_ATTRIBUTES)
}

pub fn range_needs_scalar_or_array(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0308,
        span,
        format!("`{ty}'Range` needs a scalar or constrained array type"),
    )
}

pub fn range_needs_array(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0308,
        span,
        format!("`'Range` needs an array, this is `{ty}`"),
    )
}

// ---- E0309: values that must be static ----

pub fn named_number_not_static(span: Span) -> Diagnostic {
    d(codes::E0309, span, "a named number needs a static value")
        .with_hint("give the constant a type: `K : constant Float := ...;`")
}

pub fn integer_range_not_static(span: Span) -> Diagnostic {
    d(
        codes::E0309,
        span,
        "the range of an integer type must be static",
    )
}

pub fn modulus_not_static(span: Span) -> Diagnostic {
    d(
        codes::E0309,
        span,
        "the modulus of a modular type must be static",
    )
    .with_hint("use a literal, a named number or a static constant: `mod 2**16`")
}

pub fn digits_not_static(span: Span) -> Diagnostic {
    d(codes::E0309, span, "`digits` needs a static integer")
}

pub fn case_choice_not_static(span: Span) -> Diagnostic {
    d(codes::E0309, span, "a `case` choice must be static").with_hint(
        "use literals, named numbers or constants with static values; use `if` for run-time values",
    )
}

/// `what` ("an address", ...) must be a static integer.
pub fn not_static_integer(span: Span, what: &str) -> Diagnostic {
    d(
        codes::E0309,
        span,
        format!("{what} must be a static integer"),
    )
}

// ---- E0310: case choices ----

pub fn others_not_last(span: Span) -> Diagnostic {
    d(
        codes::E0310,
        span,
        "`others` must be the only choice of the last alternative",
    )
}

pub fn case_choice_outside(span: Span, ty: &str, lo: &str, hi: &str) -> Diagnostic {
    d(
        codes::E0310,
        span,
        format!("this `case` choice is outside `{ty}` ({lo} .. {hi})"),
    )
    .with_label("no value of the selector is here")
}

pub fn case_choice_twice(span: Span, before: Span) -> Diagnostic {
    d(codes::E0310, span, "this `case` choice is covered twice")
        .with_note(before, "covered here already")
}

pub fn case_missing<S: AsRef<str>>(span: Span, ty: &str, missing: &[S]) -> Diagnostic {
    d(
        codes::E0310,
        span,
        format!(
            "this `case` does not cover every value of `{ty}`: missing {}",
            join(missing, ", ")
        ),
    )
    .with_hint("add the missing choices or a `when others =>` alternative")
}

pub fn case_needs_others(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0310,
        span,
        format!("a `case` on `{ty}` needs `when others`"),
    )
}

// ---- E0311: names indexed, called or selected wrongly ----

/// `F := P (A, B);` where `P` gives its result in its last, `out`
/// parameter: `written` is the call as a statement, `P (A, B, F);`.
pub fn procedure_result_in_out_param(
    span: Span,
    name: &str,
    param: &str,
    written: &str,
    signature: &str,
) -> Diagnostic {
    d(
        codes::E0311,
        span,
        format!("`{name}` is a procedure and has no value"),
    )
    .with_label(format!(
        "it gives its result in its `out` parameter `{param}`"
    ))
    .with_hint(format!(
        "call it as a statement: `{written}` (`{signature}`)"
    ))
}

pub fn procedure_has_no_value(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0311,
        span,
        format!("`{name}` is a procedure and has no value"),
    )
    .with_hint("call it as a statement: `P (...);`")
}

pub fn all_needs_access(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0311,
        span,
        format!("`.all` needs an access value, this is `{ty}`"),
    )
}

/// `ty` has no component `name`; `components` are those it has.
pub fn no_component<S: AsRef<str>>(
    span: Span,
    ty: &str,
    name: &str,
    components: &[S],
) -> Diagnostic {
    d(
        codes::E0311,
        span,
        format!("`{ty}` has no component `{name}`"),
    )
    .with_hint(format!("its components are: {}", join(components, ", ")))
}

pub fn selection_needs_record(span: Span, component: &str, ty: &str) -> Diagnostic {
    d(
        codes::E0311,
        span,
        format!("`.{component}` needs a record, this is `{ty}`"),
    )
}

pub fn cannot_call_or_index(span: Span, text: &str) -> Diagnostic {
    d(
        codes::E0311,
        span,
        format!("`{text}` cannot be called or indexed"),
    )
}

pub fn neither_array_nor_subprogram(span: Span, text: &str, ty: &str) -> Diagnostic {
    d(
        codes::E0311,
        span,
        format!("`{text}` is neither an array nor a subprogram and cannot be indexed or called"),
    )
    .with_label(format!("this has type `{ty}`"))
}

pub fn index_count(span: Span, ty: &str, dimensions: usize, given: usize) -> Diagnostic {
    d(
        codes::E0311,
        span,
        format!("`{ty}` has {dimensions} dimension(s), {given} index(es) given"),
    )
}

pub fn named_array_index(span: Span) -> Diagnostic {
    d(codes::E0311, span, "array indices cannot be named")
}

// ---- E0312: constraints ----

pub fn unconstrained_object(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0312,
        span,
        format!(
            "an object of the unconstrained array type `{ty}` needs bounds or an initial value"
        ),
    )
    .with_hint(format!("write `{ty} (1 .. N)` or give an initial value"))
}

pub fn range_constraint_not_scalar(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0312,
        span,
        format!("a range constraint needs a scalar type, not `{ty}`"),
    )
}

pub fn index_constraint_not_array(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0312,
        span,
        format!("`{ty}` is not an array type and takes no index constraint"),
    )
}

pub fn already_constrained(span: Span, ty: &str) -> Diagnostic {
    d(codes::E0312, span, format!("`{ty}` is already constrained"))
}

pub fn index_constraint_count(span: Span, ty: &str, indices: usize, given: usize) -> Diagnostic {
    d(
        codes::E0312,
        span,
        format!("`{ty}` has {indices} index(es), the constraint gives {given}"),
    )
}

pub fn array_component_unconstrained(span: Span) -> Diagnostic {
    d(
        codes::E0312,
        span,
        "array components must have a constrained type",
    )
    .with_hint("give the component type bounds, e.g. `String (1 .. 10)`")
}

pub fn record_component_unconstrained(span: Span) -> Diagnostic {
    d(
        codes::E0312,
        span,
        "record components must have a constrained type",
    )
}

// ---- E0313: renaming a value ----

/// `X : T renames 3;`: what is renamed is a value (`what` says which
/// kind: a literal, an expression, a conversion, a named number).
pub fn renames_a_value(span: Span, text: &str, what: &str) -> Diagnostic {
    d(
        codes::E0313,
        span,
        format!("`{text}` is {what}, not an object: only an object can be renamed"),
    )
    .with_label("a renaming gives an existing object another name")
    .with_hint("to keep a value, declare a constant: `Name : constant T := ...;`")
}

// ---- E0314: discriminant parts and discriminant constraints ----

pub fn discriminant_not_discrete(span: Span) -> Diagnostic {
    d(
        codes::E0314,
        span,
        "a discriminant must have a discrete type",
    )
    .with_hint("use an integer or enumeration type (`Size : Positive`, `Kind : Tool_Kind`)")
}

/// RM 9.1(2), 9.4(2): only a task or protected *type* has discriminants.
pub fn single_unit_discriminants(span: Span, unit: &str, name: &str) -> Diagnostic {
    d(
        codes::E0314,
        span,
        format!("a discriminant part is not allowed on a single {unit}"),
    )
    .with_hint(format!(
        "declare `{unit} type {name} (...)` and an object of it with its discriminants"
    ))
}

pub fn discriminant_defaults_incomplete(span: Span) -> Diagnostic {
    d(
        codes::E0314,
        span,
        "incomplete specification of defaults for discriminants",
    )
    .with_hint("give every discriminant a default, or none")
}

pub fn no_discriminants(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0314,
        span,
        format!("invalid constraint: `{ty}` has no discriminants"),
    )
}

pub fn discriminant_count(span: Span, ty: &str, too_many: bool) -> Diagnostic {
    let how = if too_many { "too many" } else { "too few" };
    d(
        codes::E0314,
        span,
        format!("{how} discriminants given in the constraint of `{ty}`"),
    )
}

pub fn no_such_discriminant(span: Span, ty: &str, name: &str, names: &[&str]) -> Diagnostic {
    d(
        codes::E0314,
        span,
        format!("`{name}` does not match any discriminant of `{ty}`"),
    )
    .with_hint(format!("its discriminants: {}", join(names, ", ")))
}

pub fn discriminant_given_twice(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0314,
        span,
        format!("duplicate constraint for discriminant `{name}`"),
    )
}

/// An object of a type whose discriminants have no defaults, declared
/// without a constraint or an initial value.
pub fn discriminated_object_unconstrained(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0314,
        span,
        format!("an object of `{ty}` needs its discriminants: `{ty}` gives them no defaults"),
    )
    .with_label("unconstrained subtype not allowed (need initialization)")
    .with_hint(format!(
        "write `{ty} (...)` with the discriminants, give an initial value, or give the discriminants defaults"
    ))
}

/// An object (`what`: "an object", "an allocator", "a component", "an
/// array element") of
/// a private type with unknown discriminants (`type T (<>) is private;`)
/// without an initial value, outside its package.
pub fn unknown_discriminants_unconstrained(span: Span, ty: &str, what: &str) -> Diagnostic {
    let (label, hint) = if what == "an object" {
        (
            "unconstrained subtype not allowed (need initialization)",
            format!(
                "give it an initial value, from a function of the package that declares `{ty}`: `X : {ty} := Make (...);`"
            ),
        )
    } else if what == "an allocator" {
        (
            "uninitialized unconstrained allocation not allowed",
            format!(
                "give the allocator a value, from a function of the package that declares `{ty}`: `new {ty}'(Make (...))`"
            ),
        )
    } else {
        (
            "unconstrained subtype not allowed here",
            format!(
                "only objects with an initial value can be of `{ty}` outside its package; hold an access value, or give the partial view known discriminants"
            ),
        )
    };
    d(
        codes::E0314,
        span,
        format!("{what} of `{ty}` needs an initial value: `{ty}` has unknown discriminants"),
    )
    .with_label(label)
    .with_hint(hint)
}

/// RM 3.8(12): a discriminant in a component's constraint is the whole
/// bound or value, not part of an expression.
pub fn discriminant_not_alone(span: Span) -> Diagnostic {
    d(
        codes::E0314,
        span,
        "a discriminant in a component's constraint must appear alone",
    )
    .with_label("an expression of a discriminant")
    .with_hint(
        "use the discriminant itself as the bound (`String (1 .. Size)`), not an expression of it",
    )
}

/// RM 4.8(4): `new T` of a type whose discriminants have no defaults.
pub fn allocator_unconstrained(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0314,
        span,
        format!("an allocator of `{ty}` needs its discriminants: `{ty}` gives them no defaults"),
    )
    .with_label("uninitialized unconstrained allocation not allowed")
    .with_hint(format!(
        "write `new {ty} (...)` with the discriminants, or `new {ty}'(...)` with a value"
    ))
}

pub fn discriminated_component_unconstrained(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0314,
        span,
        format!("a component of `{ty}` needs its discriminants: `{ty}` gives them no defaults"),
    )
    .with_hint(format!("write `{ty} (...)` with the discriminants"))
}

pub fn variant_not_discriminant(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0314,
        span,
        format!(
            "`{name}` is not a discriminant of the record: a variant part chooses by a discriminant"
        ),
    )
}

// ---- E0315: record aggregates and the variant their discriminants choose ----

pub fn component_not_in_variant(span: Span, name: &str, discriminants: &str) -> Diagnostic {
    d(
        codes::E0315,
        span,
        format!("`{name}` is not a component of the aggregate subtype"),
    )
    .with_label(format!("not in the variant that {discriminants} chooses"))
}

pub fn discriminant_not_static(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0315,
        span,
        format!("the value for discriminant `{name}` must be static"),
    )
    .with_label("it chooses the aggregate's variant")
    .with_hint("write the discriminant's value as a literal or a static constant, one aggregate per variant")
}

// ---- E0316: assignments to discriminants ----

pub fn assigned_discriminant(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0316,
        span,
        format!("assignment to discriminant `{name}` not allowed"),
    )
    .with_hint("assign the whole record instead (`G := (Kind => Vacuum, ...);`), when its discriminants have defaults")
}

// ---- E0317: the full view of a private type where only its partial view is visible ----

pub fn private_component(span: Span, component: &str, ty: &str, pkg: &str) -> Diagnostic {
    d(
        codes::E0317,
        span,
        format!(
            "`{ty}` is a private type: its component `{component}` is not visible outside `{pkg}`"
        ),
    )
    .with_hint(format!("use the operations `{pkg}` declares for `{ty}`"))
}

pub fn private_aggregate(span: Span, ty: &str, pkg: &str) -> Diagnostic {
    d(
        codes::E0317,
        span,
        format!("`{ty}` is a private type: an aggregate of it can only be written inside `{pkg}`"),
    )
    .with_hint(format!(
        "use the operations or constants `{pkg}` declares for `{ty}`"
    ))
}

/// What else needs the full view: a literal, an index, an attribute, a
/// predefined operator or a conversion of the full type.
pub fn private_full_view(span: Span, what: &str, ty: &str, pkg: &str) -> Diagnostic {
    d(
        codes::E0317,
        span,
        format!("`{ty}` is a private type: {what} is not visible outside `{pkg}`"),
    )
    .with_hint(format!("use the operations `{pkg}` declares for `{ty}`"))
}

// ---- E0318: values of limited types copied or compared ----

pub fn limited_assignment(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0318,
        span,
        format!("`{ty}` is a limited type: its objects cannot be assigned"),
    )
}

pub fn limited_copy(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0318,
        span,
        format!(
            "`{ty}` is a limited type: an object of it is initialized by an aggregate or a function call, not a copy"
        ),
    )
}

pub fn limited_return(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0318,
        span,
        format!(
            "`{ty}` is a limited type: `return` gives an aggregate or a function call, not a copy of an object"
        ),
    )
}

pub fn limited_equality(span: Span, op: &str, ty: &str) -> Diagnostic {
    d(
        codes::E0318,
        span,
        format!("`{op}` is not defined for `{ty}`, a limited type"),
    )
    .with_hint(format!(
        "declare `function \"=\" (Left, Right : {ty}) return Boolean;` beside the type to compare its values"
    ))
}

/// What makes a type limited, when it is not so by its own declaration.
pub fn limited_because(d: Diagnostic, why: Option<String>) -> Diagnostic {
    match why {
        Some(w) => d.with_hint(w),
        None => d,
    }
}

// ---- E0401: return ----

pub fn function_without_return(span: Span, name: &str) -> Diagnostic {
    protected_function_without_return(span, name)
        .with_hint("a function must return a value on every path: add `return Value;`")
}

/// [`function_without_return`] of a protected function (no hint).
pub fn protected_function_without_return(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0401,
        span,
        format!("function `{name}` has no `return` statement"),
    )
}

pub fn return_outside_subprogram(span: Span) -> Diagnostic {
    d(codes::E0401, span, "`return` outside a subprogram")
}

pub fn procedure_returns_value(span: Span) -> Diagnostic {
    d(codes::E0401, span, "a procedure cannot return a value")
        .with_hint("make it a function, or write `return;`")
}

pub fn function_returns_nothing(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0401,
        span,
        format!("a function must return a value of type `{ty}`"),
    )
}

// ---- E0402: statements ----

pub fn function_result_unused(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0402,
        span,
        format!("`{name}` is a function: its result must be used"),
    )
    .with_hint("assign the result: `X := F (...);`")
}

const STATEMENT_HINT: &str = "a statement is an assignment `X := ...;` or a procedure call";

pub fn not_a_procedure_or_entry(span: Span, text: &str) -> Diagnostic {
    d(
        codes::E0402,
        span,
        format!("`{text}` is not a procedure or entry"),
    )
    .with_hint(STATEMENT_HINT)
}

pub fn not_a_procedure(span: Span, text: &str) -> Diagnostic {
    d(codes::E0402, span, format!("`{text}` is not a procedure")).with_hint(STATEMENT_HINT)
}

pub fn not_a_statement(span: Span) -> Diagnostic {
    d(codes::E0402, span, "this expression is not a statement")
}

// ---- E0403: exit and loop names ----

pub fn no_loop_named(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0403,
        span,
        format!("no enclosing loop is named `{name}`"),
    )
}

pub fn exit_outside_loop(span: Span) -> Diagnostic {
    d(codes::E0403, span, "`exit` outside a loop")
}

// ---- E0404: parameters ----

pub fn default_on_non_in_parameter(span: Span) -> Diagnostic {
    d(
        codes::E0404,
        span,
        "only `in` parameters can have default values",
    )
}

// ---- E0405: imports ----

pub fn no_builtin(span: Span, name: &str) -> Diagnostic {
    d(codes::E0405, span, format!("no builtin named \"{name}\""))
}

/// A profile `declared` for import `name`, whose service has `service`.
pub fn import_profile_mismatch(
    span: Span,
    name: &str,
    declared: &str,
    service: &str,
) -> Diagnostic {
    d(
        codes::E0405,
        span,
        format!(
            "this profile does not match the import \"{name}\": declared `{declared}`, the service is `{service}`"
        ),
    )
    .with_label("the service's natives would read the wrong arguments")
}

// ---- E0406, E0407: subprogram renamings ----

/// `procedure P (A : Float) renames Go;` where no `Go` has P's profile
/// (`candidates`: the signatures of the subprograms named so).
pub fn renaming_profile_mismatch<S: AsRef<str>>(
    span: Span,
    name: &str,
    renamed: &str,
    candidates: &[S],
) -> Diagnostic {
    let mut dg = d(
        codes::E0406,
        span,
        format!("no subprogram `{renamed}` has the profile of `{name}`"),
    )
    .with_label("the parameter and result types must be those of the renamed subprogram");
    if !candidates.is_empty() {
        dg = dg.with_hint(format!(
            "the subprograms named `{renamed}` are:\n  {}",
            join(candidates, "\n  ")
        ));
    }
    dg
}

/// `procedure P renames P;`: a subprogram renaming that names itself.
pub fn renames_itself(span: Span, name: &str) -> Diagnostic {
    d(codes::E0406, span, format!("`{name}` cannot rename itself"))
}

/// A renaming whose parameter `param` has mode `mode` where the renamed
/// subprogram's has `renamed_mode` (RM 8.5.4(4): mode conformance).
pub fn renaming_mode_mismatch(
    span: Span,
    param: &str,
    mode: &str,
    renamed_mode: &str,
    renamed: &str,
) -> Diagnostic {
    d(
        codes::E0407,
        span,
        format!("the parameter `{param}` is `{mode}` here and `{renamed_mode}` in `{renamed}`"),
    )
    .with_label("a renaming keeps the modes of the subprogram it renames")
}

/// A renaming-as-body whose parameter `param` is named `declared` in the
/// declaration it completes (RM 8.5.4(5): full conformance).
pub fn renaming_as_body_names(span: Span, param: &str, declared: &str) -> Diagnostic {
    d(
        codes::E0407,
        span,
        format!(
            "the parameter `{param}` is named `{declared}` in the declaration this renaming completes"
        ),
    )
    .with_label("a body, a renaming too, repeats its declaration's parameter names")
}

// ---- E0501: entries and accept ----

pub fn not_an_entry_of_task(span: Span, name: &str, task: &str) -> Diagnostic {
    d(
        codes::E0501,
        span,
        format!("`{name}` is not an entry of task `{task}`"),
    )
}

pub fn entry_body_outside_protected(span: Span) -> Diagnostic {
    d(
        codes::E0501,
        span,
        "an entry body stands only in a protected body",
    )
}

pub fn entry_body_params_differ(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0501,
        span,
        format!("the parameters of entry body `{name}` differ from its declaration"),
    )
}

/// An accept outside the body of its task (`here`: "procedure P", "the
/// main program").
pub fn misplaced_accept(span: Span, here: &str) -> Diagnostic {
    d(
        codes::E0501,
        span,
        format!(
            "an accept statement may only appear in the body of the task that declares the entry, not in {here}"
        ),
    )
}

pub fn no_such_entry<S: AsRef<str>>(
    span: Span,
    entry: &str,
    task: &str,
    entries: &[S],
) -> Diagnostic {
    d(
        codes::E0501,
        span,
        format!("no entry `{entry}` is declared for task `{task}`"),
    )
    .with_hint(format!(
        "the accept statement must name one of its entries ({})",
        join(entries, ", ")
    ))
}

/// An accept of `entry` inside an accept of the same entry (`outer`).
pub fn nested_accept(span: Span, entry: &str, outer: Span) -> Diagnostic {
    d(
        codes::E0501,
        span,
        format!("an accept statement for `{entry}` inside the body of an accept of the same entry"),
    )
    .with_note(outer, "the enclosing accept")
    .with_hint("Ada forbids it (RM 9.5.2(15)): the entry's caller is still in the rendezvous")
}

/// An accept of `entry` whose parameters (`given` of them) differ from the
/// entry's (`want`, written `X : in T`); `decl` says where it is declared.
pub fn accept_params_differ<S: AsRef<str>>(
    span: Span,
    entry: &str,
    decl: &str,
    given: usize,
    want: &[S],
) -> Diagnostic {
    let message = match (given, want) {
        (0, [one]) => format!(
            "`accept {entry}` has no parameters but the entry {entry}{decl} has one, `{}`",
            one.as_ref()
        ),
        _ => format!(
            "the parameters of `accept {entry}` differ from those of the entry {entry}{decl}"
        ),
    };
    let with = if want.is_empty() {
        String::new()
    } else {
        format!(" ({})", join(want, "; "))
    };
    d(codes::E0501, span, message).with_hint(format!("accept {entry}{with} do ... end {entry};"))
}

pub fn select_without_accept(span: Span) -> Diagnostic {
    d(
        codes::E0501,
        span,
        "a selective accept needs at least one `accept` alternative",
    )
}

pub fn count_needs_entry(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0501,
        span,
        format!("`{name}'Count` needs an entry of the enclosing task or protected body"),
    )
}

// ---- E0502: protected objects ----

/// `what` says how the component is used.
pub fn protected_function_changes(span: Span, name: &str, what: &str) -> Diagnostic {
    d(
        codes::E0502,
        span,
        format!(
            "`{name}` is a component of the protected object: a protected function cannot change it"
        ),
    )
    .with_label(format!("used as {what}"))
    .with_hint("change it in a protected procedure or entry (a function only reads the object)")
}

pub fn protected_function_calls_procedure(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0502,
        span,
        format!("a protected function cannot call `{name}`, a protected procedure of its object"),
    )
    .with_hint("call it from a protected procedure or entry (a function only reads the object)")
}

/// `name` is no procedure or entry (`procedure`), or no function, of
/// protected `prot`.
pub fn not_a_protected_operation(
    span: Span,
    name: &str,
    procedure: bool,
    prot: &str,
) -> Diagnostic {
    let kind = if procedure {
        "procedure or entry"
    } else {
        "function"
    };
    d(
        codes::E0502,
        span,
        format!("`{name}` is not a {kind} of protected `{prot}`"),
    )
}

/// A call from outside of an operation of the private part of `prot`.
pub fn private_protected_operation(span: Span, name: &str, prot: &str) -> Diagnostic {
    d(
        codes::E0502,
        span,
        format!("`{name}` is declared in the private part of `{prot}`: only the body of `{prot}` can call it"),
    )
    .with_hint(format!("declare it before `private` to call it from outside, or call a visible operation of `{prot}` that calls or requeues to it"))
}

// ---- E0503: devices, registers, interrupts, address clauses ----

/// `name`, the register (`role`) of device `device`, used as `what`.
pub fn device_input_assigned(
    span: Span,
    name: &str,
    role: &str,
    device: &str,
    what: &str,
) -> Diagnostic {
    d(
        codes::E0503,
        span,
        format!(
            "`{name}` is the {role} of device `{device}`: the outside world sets it, the program only reads it"
        ),
    )
    .with_label(format!("used as {what}"))
}

pub fn interrupt_entry_with_parameters(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0503,
        span,
        format!("the interrupt entry `{name}` has parameters"),
    )
    .with_hint(
        "an interrupt carries no data: declare `entry Interrupt;` and read the device's registers",
    )
}

/// An entry bound to `address`, the `role` of `device`, not an interrupt.
pub fn address_not_an_interrupt(span: Span, address: &str, role: &str, device: &str) -> Diagnostic {
    d(
        codes::E0503,
        span,
        format!("{address} is the {role} of device `{device}`, not an interrupt"),
    )
    .with_hint("an entry is bound to an interrupt address; map a register to an object: `R : Word; for R use at ...;`")
}

pub fn object_at_interrupt(span: Span, address: &str, device: &str) -> Diagnostic {
    d(
        codes::E0503,
        span,
        format!(
            "{address} is the interrupt of device `{device}`: an object cannot be mapped to it"
        ),
    )
    .with_hint(format!(
        "bind an entry to it in a task: `entry Interrupt; for Interrupt use at {address};`"
    ))
}

pub fn address_clause_not_object(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0503,
        span,
        format!("`{name}` is not an object declared in this declarative part"),
    )
}

pub fn register_type(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0503,
        span,
        format!("a register is 16 bits: `{name}` must be of an integer type or an array (0 .. 15) of Boolean"),
    )
    .with_hint("declare it as `type Word is array (0 .. 15) of Boolean;` or an integer type")
}

/// No device at `address` in the device file `source` (the hint, which
/// lists the addresses, is the caller's).
pub fn no_device_at(span: Span, address: &str, source: &str) -> Diagnostic {
    d(
        codes::E0503,
        span,
        format!("no device has the address {address} in {source}"),
    )
}

// ---- E0504: delay and timed calls ----

pub fn delay_until_needs_time(span: Span, ty: &str) -> Diagnostic {
    d(
        codes::E0504,
        span,
        format!("`delay until` needs a time, this is `{ty}`"),
    )
    .with_hint("`delay until Clock + 1.0;` (Ada.Calendar or Ada.Real_Time)")
}

pub fn timed_call_not_entry(span: Span) -> Diagnostic {
    d(
        codes::E0504,
        span,
        "a timed or conditional call must call an entry",
    )
}

pub fn entry_call_select_alternatives(span: Span) -> Diagnostic {
    d(
        codes::E0504,
        span,
        "an entry call in `select` takes one `or delay ...;` or one `else`",
    )
    .with_hint("`select T.E; or delay 1.0; Put_Line (\"late\"); end select;`")
}

pub fn select_one_delay_or_terminate(span: Span) -> Diagnostic {
    d(
        codes::E0504,
        span,
        "a `select` has at most one `delay` or `terminate` alternative here",
    )
}

pub fn select_terminate_and_delay(span: Span) -> Diagnostic {
    d(
        codes::E0504,
        span,
        "a `select` cannot have both `terminate` and `delay`, nor two of them",
    )
}

pub fn select_else_with_delay(span: Span) -> Diagnostic {
    d(
        codes::E0504,
        span,
        "a `select` with `else` has no `delay` or `terminate` alternative",
    )
}

pub fn entry_call_not_first(span: Span) -> Diagnostic {
    d(
        codes::E0504,
        span,
        "an entry call stands only first in a timed or conditional call",
    )
}

// ---- E0505: entry families ----

/// The range of entry family `entry` is not static.
pub fn family_range_not_static(span: Span, entry: &str) -> Diagnostic {
    d(
        codes::E0505,
        span,
        format!("the index range of entry family `{entry}` must be static in AdaIR"),
    )
    .with_hint("name a discrete type or subtype with static bounds (`type Priority is (High, Normal, Low);`, `entry Request (Priority) ...`), or write literal bounds (`1 .. 4`)")
}

/// A family whose low bound is negative (GNAT refuses it).
pub fn family_low_bound_negative(span: Span, entry: &str, lo: impl Display) -> Diagnostic {
    d(
        codes::E0505,
        span,
        format!("the low bound of entry family `{entry}` is {lo}; it must be at least 0"),
    )
    .with_hint("GNAT refuses entry families with a negative low bound: shift the range (`0 .. 9`)")
}

/// An interrupt address clause on an entry family.
pub fn interrupt_entry_family(span: Span, entry: &str) -> Diagnostic {
    d(
        codes::E0505,
        span,
        format!("entry family `{entry}` cannot be bound to an interrupt"),
    )
    .with_hint(
        "bind a single entry without parameters: `entry Interrupt; for Interrupt use at 8#340#;`",
    )
}

/// A family named without an index (`what`: where: an entry call, an
/// accept, ...).
pub fn family_needs_index(span: Span, entry: &str, what: &str, example: &str) -> Diagnostic {
    d(
        codes::E0505,
        span,
        format!("`{entry}` is an entry family: {what} must name one member"),
    )
    .with_hint(format!("give the index first: {example}"))
}

/// An index given for an entry that is not a family.
pub fn not_a_family(span: Span, entry: &str, example: &str) -> Diagnostic {
    d(
        codes::E0505,
        span,
        format!("`{entry}` is not an entry family: it takes no index"),
    )
    .with_hint(format!("write {example}"))
}

/// An entry body whose family index does not match the declaration.
pub fn family_body_differs(span: Span, entry: &str, declared: &str) -> Diagnostic {
    d(
        codes::E0505,
        span,
        format!("the index of the body of entry family `{entry}` does not match its declaration ({declared})"),
    )
    .with_hint(format!("write the declaration's range: `entry {entry} (for I in {declared}) ... when ... is`"))
}

// ---- E0506: requeue ----

/// `requeue` outside an accept statement or entry body (`here`: where).
pub fn misplaced_requeue(span: Span, here: &str) -> Diagnostic {
    d(
        codes::E0506,
        span,
        format!("a requeue statement must stand in an accept statement or an entry body, not in {here}"),
    )
    .with_hint("requeue passes on the call being served: it stands directly in the `accept ... do ... end` of that call or in the protected entry's body")
}

/// The target of a requeue is not an entry.
pub fn requeue_not_an_entry(span: Span, name: &str) -> Diagnostic {
    d(
        codes::E0506,
        span,
        format!("`{name}` is not an entry: a requeue statement names an entry"),
    )
    .with_hint("requeue to an entry of a task (`requeue Stock.Take;`) or of a protected object (`requeue Wait_For (Kind);`)")
}

/// The target of a requeue has parameters that differ from those of the
/// call being served.
pub fn requeue_profile_differs(
    span: Span,
    target: &str,
    served: &str,
    target_profile: &str,
    served_profile: &str,
) -> Diagnostic {
    d(
        codes::E0506,
        span,
        format!("`{target}` cannot take the requeued call of `{served}`: its parameters ({target_profile}) differ from those of `{served}` ({served_profile})"),
    )
    .with_hint("the target of a requeue takes the same parameters, with the same modes and subtypes, or none at all")
}

// ---- E0701: outside the subset ----

/// `what` ("a generic", ...) is not supported.
pub fn unsupported(span: Span, what: &str) -> Diagnostic {
    d(
        codes::E0701,
        span,
        format!("{what} is not supported by AdaIR"),
    )
    .with_label("outside the AdaIR subset")
    .with_hint("see docs/differences.md for the supported subset of Ada 2012")
}

/// An unsupported declaration (a representation clause: the ones that are
/// supported named in the hint).
pub fn unsupported_declaration(span: Span, what: &str) -> Diagnostic {
    let d = unsupported(span, what);
    if what == "a representation clause" {
        d.with_hint(
            "the representation clauses AdaIR reads are address clauses: `for Interrupt use at 8#340#;` binds an entry to an interrupt, `for Input use at 8#342#;` an object to a device register (tasks.md)",
        )
    } else {
        d
    }
}

pub fn unsupported_in_protected_private(span: Span) -> Diagnostic {
    unsupported(span, "this declaration in a protected type's private part")
        .with_hint("the private part holds the components: `Count : Natural := 0;`")
}

pub fn unsupported_in_protected_body(span: Span) -> Diagnostic {
    unsupported(span, "this declaration in a protected body")
        .with_hint("a protected body holds the bodies of its subprograms and entries")
}

/// An integer type's range beyond 32 bits (`first .. last`: the bounds
/// AdaIR allows).
pub fn integer_type_too_wide(span: Span, first: impl Display, last: impl Display) -> Diagnostic {
    d(codes::E0701, span, "integer types of AdaIR are 32-bit")
        .with_hint(format!("the range must lie in {first} .. {last}"))
}

pub fn modulus_out_of_range(span: Span, value: impl Display) -> Diagnostic {
    d(
        codes::E0701,
        span,
        format!("the modulus {value} is not supported: modular types of AdaIR are 32-bit"),
    )
    .with_hint("the modulus must lie in 1 .. 2**32")
}

// ---- warnings ----

pub fn never_read(span: Span, name: &str) -> Diagnostic {
    d(
        codes::W0001,
        span,
        format!("variable `{name}` is never read"),
    )
    .with_label("declared here")
    .with_hint("remove it, or use it; a value that is only assigned is lost")
}

pub fn simulator_only(span: Span, name: &str) -> Diagnostic {
    d(
        codes::W0002,
        span,
        format!("`{name}` exists only on the simulator: this script cannot finish on a real arm"),
    )
    .with_label("raises CommandNotSupported with --port, in the rehearsal too")
    .with_hint("keep simulator-only calls in scripts that never drive the arm")
}

/// `text`, a literal angle of more than a full turn in radians.
pub fn degrees_for_radians(span: Span, text: &str) -> Diagnostic {
    d(
        codes::W0003,
        span,
        format!("{text} radians is more than a full turn; did you mean degrees?"),
    )
    .with_label("AdaIR angles are in radians")
    .with_hint(format!("write `Rad ({text})` for {text} degrees"))
}

/// A static value outside a static range of `ty`.
pub fn wrong_discriminant_value(span: Span, name: &str, ty: &str) -> Diagnostic {
    d(
        codes::W0004,
        span,
        format!("incorrect value for discriminant `{name}` of `{ty}`"),
    )
    .with_label("Constraint_Error will be raised here at run time")
}

pub fn will_raise_constraint_error(
    span: Span,
    value: &str,
    ty: &str,
    lo: &str,
    hi: &str,
) -> Diagnostic {
    d(
        codes::W0004,
        span,
        format!("the value {value} is not in range of `{ty}` ({lo} .. {hi})"),
    )
    .with_label("Constraint_Error will be raised here at run time")
}
