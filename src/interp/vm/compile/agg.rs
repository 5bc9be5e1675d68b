//! Compiling aggregates and allocators: each part is evaluated by
//! instructions, into temporaries, and the value is built by the runtime
//! value-level functions (`interp/aggregate.rs`).

use super::*;
use crate::check::types::Types;
use crate::interp::aggregate::repeatable;

impl<'r> Compiler<'r> {
    /// `e` evaluated into a fresh temporary (an aggregate's part: each is
    /// taken from its slot when the value is built).
    fn fresh(&mut self, e: &Ex) -> Var {
        let t = self.temp();
        self.expr_into(e, t);
        t
    }

    /// An array aggregate into `dst`: positional components or the named
    /// choices' bounds first, in order, then the bounds of the whole
    /// (checked), then each choice's value (once, or once per component
    /// when it has effects), then `others` for the components left.
    pub(in crate::interp::vm) fn array_agg(&mut self, agg: &ArrayAgg, dst: Var, span: Span) {
        self.scalar = false;
        let bounds = [self.temp(), self.temp(), self.temp()];
        let (items, ranges, choices, others) = match &agg.kind {
            ArrayAggKind::Positional(items, others) => {
                let items: Vec<Var> = items.iter().map(|i| self.fresh(i)).collect();
                (items, None, None, others)
            }
            ArrayAggKind::Named(choices, others) => {
                let ranges: Vec<Box<[[Var; 2]]>> = choices
                    .iter()
                    .map(|(rs, _)| {
                        rs.iter()
                            .map(|(l, h)| [self.fresh(l), self.fresh(h)])
                            .collect()
                    })
                    .collect();
                (Vec::new(), Some(ranges), Some(choices), others)
            }
        };
        self.with_discrs(Op::AggBounds(Box::new(AggBoundsOp {
            out: bounds,
            ty: agg.ty,
            items: items.len() as u32,
            ranges: ranges
                .as_ref()
                .map(|r| r.iter().flatten().copied().collect()),
            has_others: others.is_some(),
            span,
        })));
        let choices = choices.map(|cs| {
            let ranges = ranges.expect("a named aggregate's ranges");
            cs.iter()
                .zip(ranges)
                .map(|((_, v), rs)| {
                    let part = self.part(v, &rs, None);
                    (rs, part)
                })
                .collect()
        });
        let others = others.as_deref().map(|o| {
            let (one, cnt) = (self.temp(), bounds[2]);
            self.ops.push(Op::Int(one, 1));
            self.part(o, &[[one, cnt]], Some(cnt))
        });
        self.with_discrs(Op::ArrayAgg(Box::new(ArrayAggOp {
            dst,
            ty: agg.ty,
            bounds,
            items: items.into(),
            choices,
            others,
            span,
        })));
    }

    /// What a choice gives the components of `ranges` (slots of their
    /// bounds): its value once when that is the same as once per
    /// component, else a list of one value per component. `count`: the
    /// slot of how many components `others` covers (then its value is not
    /// evaluated at all when that is none).
    fn part(&mut self, v: &Ex, ranges: &[[Var; 2]], count: Option<Var>) -> PartOp {
        if repeatable(self.types, v) {
            let t = self.temp();
            let skip = count.map(|c| {
                self.ops.push(Op::CmpKJumpNot {
                    op: CmpOp::Gt,
                    x: c,
                    k: 0,
                    target: 0,
                });
                self.ops.len() - 1
            });
            self.expr_into(v, t);
            if let Some(j) = skip {
                let end = self.here();
                self.patch(j, end);
            }
            return PartOp::One(t);
        }
        let list = self.temp();
        self.ops.push(Op::ListNew(list));
        for &[l, h] in ranges {
            let counter = self.temp();
            let start = self.ops.len();
            self.ops.push(Op::ForStart {
                var: counter,
                low: l,
                high: h,
                reverse: false,
                exit: 0,
            });
            let body = self.here();
            let x = self.fresh(v);
            self.ops.push(Op::ListPush(list, x));
            self.ops.push(Op::ForNext {
                var: counter,
                low: l,
                high: h,
                reverse: false,
                body,
                span: v.span,
            });
            let end = self.here();
            self.patch(start, end);
        }
        PartOp::Each(list)
    }

    /// A record aggregate into `dst`: its components in order, those after
    /// the discriminants with the discriminants' slots in reach.
    pub(in crate::interp::vm) fn record_agg(
        &mut self,
        fields: &[Ex],
        ty: TypeId,
        dst: Var,
        span: Span,
    ) {
        self.scalar = false;
        let nd = self.types.discriminants(ty).len();
        let mut vars: Vec<Var> = fields[..nd].iter().map(|f| self.fresh(f)).collect();
        if nd > 0 {
            self.discrs.push(vars.clone().into());
        }
        vars.extend(fields[nd..].iter().map(|f| self.fresh(f)));
        if nd > 0 {
            self.discrs.pop();
        }
        self.ops.push(Op::Record(Box::new(RecordOp {
            dst,
            ty,
            plain: nd == 0,
            fields: vars.into(),
            span,
        })));
    }

    /// An allocator into `dst`; one of tasks activates them and waits for
    /// their activation (Tasking_Error when it fails, and the target keeps
    /// its value).
    pub(in crate::interp::vm) fn allocator(
        &mut self,
        e: &Ex,
        init: Option<&Ex>,
        t: TypeId,
        dst: Var,
    ) {
        self.scalar = false;
        let span = e.span;
        match init {
            Some(x) => {
                let v = self.fresh(x);
                self.ops.push(Op::Alloc(dst, v, span));
            }
            None if self.has_task(e.ty) => {
                let p = self.temp();
                self.with_discrs(Op::AllocTask {
                    dst: p,
                    access: e.ty,
                    ty: t,
                    span,
                });
                self.ops.push(Op::Activate(span));
                self.ops.push(Op::Move(dst, p));
            }
            None => self.with_discrs(Op::AllocDefault {
                dst,
                access: e.ty,
                ty: t,
                span,
            }),
        }
    }

    /// Pushes `op`, which may read a subtype that depends on the
    /// discriminants of a record aggregate being compiled: with them in
    /// reach.
    pub(in crate::interp::vm) fn with_discrs(&mut self, op: Op) {
        match self.discrs.last() {
            Some(d) => {
                let d = d.clone();
                self.ops.push(Op::PushDiscrs(d));
                self.ops.push(op);
                self.ops.push(Op::PopDiscrs);
            }
            None => self.ops.push(op),
        }
    }
}

/// Whether an array aggregate's value is the same each time it is
/// evaluated, with no effect and no check whose outcome can change: its
/// subtype is static ([`static_subtype`]) and each component, choice and
/// `others` is a literal or such an aggregate. The compiled engine makes
/// such a value once per run (`Op::Cached`).
pub(in crate::interp::vm) fn static_agg(types: &Types, e: &Ex) -> bool {
    let lit = |x: &Ex| matches!(x.kind, ExKind::Int(_));
    match &e.kind {
        ExKind::Int(_) | ExKind::Real(_) | ExKind::Str(_) => true,
        ExKind::ArrayAgg(agg) => {
            static_subtype(types, agg.ty)
                && match &agg.kind {
                    ArrayAggKind::Positional(items, others) => {
                        items.iter().all(|i| static_agg(types, i))
                            && others.as_deref().is_none_or(|o| static_agg(types, o))
                    }
                    ArrayAggKind::Named(choices, others) => {
                        choices.iter().all(|(rs, v)| {
                            rs.iter().all(|(l, h)| lit(l) && lit(h)) && static_agg(types, v)
                        }) && others.as_deref().is_none_or(|o| static_agg(types, o))
                    }
                }
        }
        _ => false,
    }
}

/// Whether a subtype's constraints are the same in every run of the code
/// that names it: an array subtype with literal bounds of such components,
/// or a scalar subtype without a range or with a static one (a subtype
/// declared in a subprogram can depend on its parameters).
fn static_subtype(types: &Types, t: TypeId) -> bool {
    if let Some((_, elem, bounds)) = types.array(t) {
        let lit = |x: &Ex| matches!(x.kind, ExKind::Int(_));
        return bounds.is_some_and(|bs| bs.iter().all(|(l, h)| lit(l) && lit(h)))
            && static_subtype(types, elem);
    }
    let info = types.get(t);
    types.is_scalar(t)
        && (info.range.is_none() || info.static_range.is_some() || info.static_frange.is_some())
}
