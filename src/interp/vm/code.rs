//! A compiled body, its handler regions, and the parts of a long body
//! compiled as soon as they are checked.

use super::*;

/// A part of a long body compiled as it was checked (see
/// [`compile_part`]): its instructions and handler regions,
/// with targets counted from its first instruction.
#[derive(Default)]
pub struct Part {
    /// None: no code yet; then whether the code only puts scalars in the
    /// frame (see `Code::scalar`).
    pub(super) scalar: Option<bool>,
    pub(super) ops: Vec<Op>,
    pub(super) regions: Vec<Region>,
}

/// Compiles a part of a long subprogram body as soon as the checker has
/// made it (an [`crate::check::ir::PartCompiler`]), for `adair run`: the
/// checked statements are dropped here, the instructions are added to the
/// body's code so far (`into`), which waits for [`Compiler::splice`].
/// Which calls go to a native is decided now: those of an imported
/// subprogram (as [`Run::native_call`] says). A subprogram
/// whose body is not checked yet (the body itself, when it calls itself;
/// one declared before and completed later) gets a compiled call (one left
/// without body raises when called, see `compile_first`).
pub(crate) fn compile_part(
    prog: ProgramRef<'_>,
    at: crate::check::ir::PartAt,
    stmts: Vec<Stmt>,
    into: &crate::check::ir::Precompiled,
) -> u32 {
    let native_calls = |f: FuncId| prog.imports.get(f as usize).is_some_and(|n| n.is_some());
    let mut c = Compiler::new(at.level, at.own, &native_calls, prog.types);
    c.masters = u32::from(at.master);
    c.stmts(&stmts);
    drop(stmts);
    into.fill(|body: &mut Part| {
        // One list for the whole body, grown in place (a big list's memory
        // is remapped, not copied, as it grows).
        let by = body.ops.len() as u32;
        body.ops.extend(c.ops.into_iter().map(|mut op| {
            relocate(&mut op, by);
            op
        }));
        body.regions
            .extend(c.regions.into_iter().map(|r| r.moved(by)));
        body.scalar = Some(body.scalar.unwrap_or(true) && c.scalar);
    });
    c.max_temp
}

/// A part of the code whose exceptions go to handlers.
pub(super) struct Region {
    pub(super) start: u32,
    pub(super) end: u32,
    pub(super) dispatch: u32,
}

impl Region {
    /// The region `by` instructions on.
    pub(super) fn moved(&self, by: u32) -> Region {
        Region {
            start: self.start + by,
            end: self.end + by,
            dispatch: self.dispatch + by,
        }
    }
}

/// A compiled body.
pub(crate) struct Code {
    /// The subprogram whose body this is (None: level-0 code).
    pub(super) func: Option<FuncId>,
    /// Every parameter is `in`: a return has nothing to copy back.
    pub(super) all_in: bool,
    /// Every value in its frame is a scalar (`Undef`, `Int`, `Real`: its
    /// parameters' and variables' types are scalar, and no instruction
    /// puts anything else there): freeing the frame drops nothing, so it
    /// is freed without looking at its slots.
    pub(super) scalar: bool,
    /// `all_in` and `scalar`: a return from it copies nothing back and
    /// frees its frame without looking at it (one test for the inner
    /// loop's quick return, `fast.rs`).
    pub(super) quick: bool,
    /// The static level of its frame (its own slots are `Var`s of it).
    pub(super) level: u16,
    pub(super) ops: Vec<Op>,
    /// Slots beyond the subprogram's own: temporaries.
    pub(super) temps: u32,
    /// The frame's size: the subprogram's own slots and the temporaries.
    pub(super) frame: u32,
    /// Handler regions, innermost first.
    pub(super) regions: Vec<Region>,
}

/// What is compiled: a body, level-0 statements, or the call of the main
/// subprogram.
pub(super) enum Compiled<'a> {
    Body(&'a Body),
    Stmts(&'a [Stmt]),
    Main(FuncId),
}
