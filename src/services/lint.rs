//! What `adair check` can tell about a robot program before anything
//! moves, beyond types: a service called before `InitRobot` (W0005) and a
//! literal target the robot cannot reach (W0006), judged for the robot
//! the run drives (`--robot`, a script's `-- adair: --robot` line, or the
//! default RV-M1).
//!
//! Both read the checked program only (the script's statements and the
//! main subprogram's body; not the bodies of other subprograms or tasks)
//! and warn only where the fault is certain:
//! - W0005: a service that needs `InitRobot` is called where no path
//!   through the program so far has called `InitRobot` (directly, or in a
//!   subprogram that calls it), and no enclosing handler catches
//!   `SystemNotInitialized` (or `others`): a test of that exception is
//!   meant.
//! - W0006: `MoveAxesAbsolute` with an aggregate of literal angles one of
//!   which lies outside its joint's limits however many turns are taken
//!   off (as the service does; AxesVector is in radians: 3.0 meant as
//!   degrees is 172 degrees), or `MoveFrameAbsolute (Trans (X, Y,
//!   Z))` with literals farther from the base than the arm's full stretch.

use crate::check::ir::{Arg, ArrayAggKind, Body, Ex, ExKind, FuncId, ProgramRef, Stmt, StmtKind};
use crate::diag::codes;
use crate::diag::{Diagnostic, Span};
use crate::kinematics::RobotDescription;

/// The warnings for the checked program `stmts` (and `main`'s body).
pub fn warnings(
    p: ProgramRef<'_>,
    stmts: &[Stmt],
    main: Option<FuncId>,
    robot: &RobotDescription,
) -> Vec<Diagnostic> {
    let mut l = Lint {
        p,
        robot,
        out: Vec::new(),
        guarded: 0,
        not_initialized: p
            .excs
            .iter()
            .position(|e| e.name.eq_ignore_ascii_case("ADAIR.SYSTEMNOTINITIALIZED"))
            .map(|i| i as u32),
        inits: Vec::new(),
    };
    let mut init = l.stmts(stmts, false);
    if let Some(f) = main
        && let Some(body) = p.funcs.get(f as usize).and_then(|f| f.body.clone())
    {
        init = l.body(&body, init);
    }
    let _ = init;
    l.out
}

struct Lint<'a> {
    p: ProgramRef<'a>,
    robot: &'a RobotDescription,
    out: Vec<Diagnostic>,
    /// How many enclosing handlers catch `SystemNotInitialized`.
    guarded: u32,
    not_initialized: Option<u32>,
    /// Which subprograms call `InitRobot` (memo; `None`: being decided).
    inits: Vec<(FuncId, Option<bool>)>,
}

/// The import name of a subprogram, when it is a service or builtin.
fn import<'p>(p: &ProgramRef<'p>, f: FuncId) -> Option<&'p str> {
    p.imports.get(f as usize).and_then(|i| i.as_deref())
}

/// Services that answer before `InitRobot` (services.md): itself, and
/// `ValueErrorStatus`.
const BEFORE_INIT: &[&str] = &["InitRobot", "ValueErrorStatus"];

impl Lint<'_> {
    /// Walks `stmts` with `init`: whether some path so far has called
    /// `InitRobot`. Returns it after them.
    fn stmts(&mut self, stmts: &[Stmt], mut init: bool) -> bool {
        for s in stmts {
            init = self.stmt(s, init);
        }
        init
    }

    fn body(&mut self, b: &Body, init: bool) -> bool {
        let catches = b.handlers.iter().any(|h| match &h.choices {
            None => true,
            Some(cs) => self.not_initialized.is_some_and(|e| cs.contains(&e)),
        });
        self.guarded += u32::from(catches);
        let after = self.stmts(&b.stmts, init);
        self.guarded -= u32::from(catches);
        // A handler runs after some of the statements.
        let mut any = after;
        for h in &b.handlers {
            any |= self.stmts(&h.stmts, after);
        }
        any
    }

    fn stmt(&mut self, s: &Stmt, init: bool) -> bool {
        match &s.kind {
            StmtKind::Call(f, args) => self.call(*f, args, s.span, init),
            StmtKind::If(arms, els) => {
                let mut any = self.stmts(els, init);
                for (_, b) in arms {
                    any |= self.stmts(b, init);
                }
                any
            }
            StmtKind::Case(_, arms, others) => {
                let mut any = others.as_ref().is_some_and(|o| self.stmts(o, init));
                for (_, b) in arms.iter() {
                    any |= self.stmts(b, init);
                }
                any || init
            }
            StmtKind::Loop { body, .. } | StmtKind::While { body, .. } => {
                // A later round sees what an earlier one called.
                let first = self.stmts(body, init);
                init || first
            }
            StmtKind::For(f) => init || self.stmts(&f.body, init),
            StmtKind::Block(b) | StmtKind::Master(b) => self.body(b, init),
            _ => init,
        }
    }

    fn call(&mut self, f: FuncId, args: &[Arg], span: Span, init: bool) -> bool {
        match import(&self.p, f) {
            Some(name) if crate::services::SERVICES.iter().any(|s| s.import == name) => {
                if name == "InitRobot" {
                    return true;
                }
                if !init && self.guarded == 0 && !BEFORE_INIT.contains(&name) {
                    self.out.push(before_init(span, name));
                }
                self.target(name, args);
                init
            }
            Some(_) => init,
            None => init || self.calls_init(f),
        }
    }

    /// Whether the subprogram `f` calls `InitRobot` on some path.
    fn calls_init(&mut self, f: FuncId) -> bool {
        if let Some((_, known)) = self.inits.iter().find(|(g, _)| *g == f) {
            return known.unwrap_or(false);
        }
        self.inits.push((f, None));
        let body = self.p.funcs.get(f as usize).and_then(|s| s.body.clone());
        let found = body.is_some_and(|b| self.mentions_init(&b.stmts));
        if let Some(e) = self.inits.iter_mut().find(|(g, _)| *g == f) {
            e.1 = Some(found);
        }
        found
    }

    fn mentions_init(&mut self, stmts: &[Stmt]) -> bool {
        stmts.iter().any(|s| match &s.kind {
            StmtKind::Call(f, _) => match import(&self.p, *f) {
                Some(n) => n == "InitRobot",
                None => self.calls_init(*f),
            },
            StmtKind::If(arms, els) => {
                arms.iter().any(|(_, b)| self.mentions_init(b)) || self.mentions_init(els)
            }
            StmtKind::Case(_, arms, others) => {
                arms.iter().any(|(_, b)| self.mentions_init(b))
                    || others.as_ref().is_some_and(|o| self.mentions_init(o))
            }
            StmtKind::Loop { body, .. } | StmtKind::While { body, .. } => self.mentions_init(body),
            StmtKind::For(f) => self.mentions_init(&f.body),
            StmtKind::Block(b) | StmtKind::Master(b) => {
                self.mentions_init(&b.stmts)
                    || b.handlers.iter().any(|h| self.mentions_init(&h.stmts))
            }
            _ => false,
        })
    }

    /// W0006 for a literal target of `name`.
    fn target(&mut self, name: &str, args: &[Arg]) {
        let Some(first) = args.first() else { return };
        match name {
            "MoveAxesAbsolute" => {
                let Some(q) = literal_reals(&first.value) else {
                    return;
                };
                let Ok(q) = <[f64; crate::kinematics::JOINTS]>::try_from(q) else {
                    return;
                };
                // As the service takes it: multiples of 2 pi removed.
                let k = crate::kinematics::Kinematics::new(self.robot.clone());
                if let Err(v) = k.fit_limits(&q, &q) {
                    self.out.push(joint_out_of_reach(
                        first.value.span,
                        v.joint,
                        q[v.joint - 1],
                        v.min,
                        v.max,
                    ));
                }
            }
            "MoveFrameAbsolute" => {
                let Some(xyz) = self.literal_position(&first.value) else {
                    return;
                };
                let reach = self.reach();
                let d = (xyz[0] * xyz[0] + xyz[1] * xyz[1] + xyz[2] * xyz[2]).sqrt();
                if d > reach {
                    self.out
                        .push(frame_out_of_reach(first.value.span, d, reach));
                }
            }
            _ => {}
        }
    }

    /// The position of a frame written with literals: `Trans (X, Y, Z)`,
    /// turned by rotations on the right (`Trans (...) * RotY (...)`).
    fn literal_position(&self, e: &Ex) -> Option<[f64; 3]> {
        let ExKind::Call(f, args) = &strip(e).kind else {
            return None;
        };
        let name = self.p.funcs.get(*f as usize)?.name.to_ascii_lowercase();
        match (name.as_str(), args.as_ref()) {
            ("trans", [x, y, z]) => {
                Some([literal(&x.value)?, literal(&y.value)?, literal(&z.value)?])
            }
            ("\"*\"" | "*", [a, b]) => {
                let ExKind::Call(r, _) = &strip(&b.value).kind else {
                    return None;
                };
                let rot = self.p.funcs.get(*r as usize)?.name.to_ascii_lowercase();
                matches!(rot.as_str(), "rotx" | "roty" | "rotz")
                    .then(|| self.literal_position(&a.value))
                    .flatten()
            }
            _ => None,
        }
    }

    /// The farthest the tool centre can be from the base's origin: the
    /// full stretch (the zero pose, arm straight up) with a fifth more for
    /// any offset of the shoulder.
    fn reach(&self) -> f64 {
        let zero = [0.0; crate::kinematics::JOINTS];
        let k = crate::kinematics::Kinematics::new(self.robot.clone());
        let tcp = k.fk_tcp(&zero, &self.robot.standard_tool());
        tcp.translation.norm() * 1.2
    }
}

/// An expression without the checks and conversions around a literal.
fn strip(e: &Ex) -> &Ex {
    match &e.kind {
        ExKind::RangeCheck(x, _) | ExKind::ArrayConvert(x, _) => strip(x),
        _ => e,
    }
}

/// A literal number (`3.0`, `-1.5`, `2` as a Float).
fn literal(e: &Ex) -> Option<f64> {
    match &strip(e).kind {
        ExKind::Real(v) => Some(*v),
        ExKind::Int(v) => Some(*v as f64),
        ExKind::IntToFloat(x) => literal(x),
        ExKind::FloatNeg(x) => literal(x).map(|v| -v),
        _ => None,
    }
}

/// A positional aggregate of literal numbers.
fn literal_reals(e: &Ex) -> Option<Vec<f64>> {
    match &strip(e).kind {
        ExKind::ArrayAgg(a) => match &a.kind {
            ArrayAggKind::Positional(xs, None) => xs.iter().map(literal).collect(),
            _ => None,
        },
        _ => None,
    }
}

fn before_init(span: Span, service: &str) -> Diagnostic {
    Diagnostic::new(
        codes::W0005,
        span,
        format!("`{service}` is called before `InitRobot` on every path to it"),
    )
    .with_label("raises SystemNotInitialized here")
    .with_hint("call `InitRobot;` first: every service but `ValueErrorStatus` needs it")
}

fn joint_out_of_reach(span: Span, joint: usize, v: f64, min: f64, max: f64) -> Diagnostic {
    let deg = |r: f64| r.to_degrees();
    let mut d = Diagnostic::new(
        codes::W0006,
        span,
        format!(
            "joint {joint}'s target {v:?} rad ({:.1} degrees) is outside its limits ({:.1} .. {:.1} degrees)",
            deg(v),
            deg(min),
            deg(max)
        ),
    )
    .with_label("OutOfReach will be raised here");
    // 3.0 meant as degrees (a number as people write one).
    let written = (v * 100.0).fract() == 0.0;
    if written && v.to_radians() >= min && v.to_radians() <= max {
        d = d.with_hint(format!(
            "an AxesVector is in radians: for {v:?} degrees write `Rad ({v:?})` ({:.4})",
            v.to_radians()
        ));
    }
    d
}

fn frame_out_of_reach(span: Span, d: f64, reach: f64) -> Diagnostic {
    Diagnostic::new(
        codes::W0006,
        span,
        format!(
            "this frame is {d:.0} mm from the robot's base, farther than the arm reaches (under {reach:.0} mm)"
        ),
    )
    .with_label("OutOfReach will be raised here")
    .with_hint("a frame's position is in mm from the base; check the units and the numbers")
}
