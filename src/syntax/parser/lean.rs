//! The grammar's error type, and the lean first pass it allows. chumsky's
//! `Rich` error collects, at every alternative that fails, the tokens it
//! expected: on a text without a syntax error that work (allocations,
//! merges of expected lists) was most of a parse, and all of it thrown
//! away. So a text is parsed first with lean errors, which say only that
//! there is one ([`Lean`]); a text whose lean pass meets an error is parsed
//! again with `Rich` errors, and only their diagnostics are reported.
//!
//! The two passes take the same paths: what an error holds never steers
//! the grammar (a choice, a repetition and a recovery look only at whether
//! and where a parser failed), so a text without errors gets from the lean
//! pass alone the tree the rich one would build (`tests/parse_passes.rs`
//! compares them on every program of the repository).
//!
//! Which kind of error is built is a per-thread mode, set for the length
//! of a lean pass ([`leanly`]): chumsky builds errors through static
//! constructors, with no state of the parse at hand.

use crate::diag::Span;
use crate::syntax::token::Token;
use chumsky::error::{Error, LabelError, Rich, RichPattern};
use chumsky::input::Input;
use chumsky::util::MaybeRef;
use std::cell::Cell;

thread_local! {
    static LEAN: Cell<bool> = const { Cell::new(false) };
}

fn lean() -> bool {
    LEAN.with(Cell::get)
}

/// Runs `f` (a parse) with lean errors.
pub(super) fn leanly<T>(f: impl FnOnce() -> T) -> T {
    struct Restore(bool);
    impl Drop for Restore {
        fn drop(&mut self) {
            LEAN.with(|l| l.set(self.0));
        }
    }
    let _outer = Restore(LEAN.with(|l| l.replace(true)));
    f()
}

/// A syntax error: that there is one (a lean pass), or chumsky's `Rich`.
#[derive(Clone, Debug)]
pub enum PErr<'t> {
    Lean,
    Rich(Rich<'t, Token, Span>),
}

pub use PErr::Lean;

impl<'t> PErr<'t> {
    /// An error of the grammar's own (`Rich::custom`): its code and message
    /// (see `syntax::diagnostics::custom`).
    pub fn custom(span: Span, msg: impl Into<String>) -> Self {
        if lean() {
            Lean
        } else {
            PErr::Rich(Rich::custom(span, msg))
        }
    }

    /// The rich error (a lean one is never reported: its text is parsed
    /// again).
    pub fn rich(self) -> Option<Rich<'t, Token, Span>> {
        match self {
            PErr::Rich(r) => Some(r),
            Lean => None,
        }
    }
}

impl<'t, I: Input<'t, Token = Token, Span = Span>> Error<'t, I> for PErr<'t> {
    fn merge(self, other: Self) -> Self {
        match (self, other) {
            (PErr::Rich(a), PErr::Rich(b)) => {
                PErr::Rich(<Rich<'t, Token, Span> as Error<'t, I>>::merge(a, b))
            }
            (PErr::Rich(a), Lean) | (Lean, PErr::Rich(a)) => PErr::Rich(a),
            (Lean, Lean) => Lean,
        }
    }
}

impl<'t, I, L> LabelError<'t, I, L> for PErr<'t>
where
    I: Input<'t, Token = Token, Span = Span>,
    L: TryInto<RichPattern<'t, Token>>,
{
    fn expected_found<E: IntoIterator<Item = L>>(
        expected: E,
        found: Option<MaybeRef<'t, Token>>,
        span: Span,
    ) -> Self {
        if lean() {
            Lean
        } else {
            PErr::Rich(
                <Rich<'t, Token, Span> as LabelError<'t, I, L>>::expected_found(
                    expected, found, span,
                ),
            )
        }
    }

    fn merge_expected_found<E: IntoIterator<Item = L>>(
        self,
        expected: E,
        found: Option<MaybeRef<'t, Token>>,
        span: Span,
    ) -> Self {
        match self {
            PErr::Rich(r) => PErr::Rich(
                <Rich<'t, Token, Span> as LabelError<'t, I, L>>::merge_expected_found(
                    r, expected, found, span,
                ),
            ),
            Lean => <Self as LabelError<'t, I, L>>::expected_found(expected, found, span),
        }
    }

    fn replace_expected_found<E: IntoIterator<Item = L>>(
        self,
        expected: E,
        found: Option<MaybeRef<'t, Token>>,
        span: Span,
    ) -> Self {
        match self {
            PErr::Rich(r) => PErr::Rich(
                <Rich<'t, Token, Span> as LabelError<'t, I, L>>::replace_expected_found(
                    r, expected, found, span,
                ),
            ),
            Lean => <Self as LabelError<'t, I, L>>::expected_found(expected, found, span),
        }
    }

    fn label_with(&mut self, label: L) {
        if let PErr::Rich(r) = self {
            <Rich<'t, Token, Span> as LabelError<'t, I, L>>::label_with(r, label);
        }
    }

    fn in_context(&mut self, label: L, span: Span) {
        if let PErr::Rich(r) = self {
            <Rich<'t, Token, Span> as LabelError<'t, I, L>>::in_context(r, label, span);
        }
    }
}
