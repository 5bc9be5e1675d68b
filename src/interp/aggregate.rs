//! Aggregates and allocators (RM 4.3, 4.8): the values both engines build
//! from the parts each engine evaluates itself, and the run-time checks
//! they make, in one place.

use super::*;

/// What one choice of an array aggregate gives the components it covers.
pub(crate) enum AggPart {
    /// A value evaluated once and copied into each component.
    One(Value),
    /// One value per component, in index order (a value with effects is
    /// evaluated once per component, RM 4.3.3(23)).
    Each(Vec<Value>),
}

/// The shape of an array aggregate's first dimension once its choices are
/// known.
pub(crate) struct AggBounds {
    pub lo: i64,
    pub hi: i64,
    /// How many components `others` covers.
    pub others: i64,
}

impl AggPart {
    fn next(&mut self) -> Option<Value> {
        match self {
            AggPart::One(v) => Some(v.clone()),
            AggPart::Each(vs) => vs.pop(),
        }
    }

    /// Ready for [`AggPart::next`] (which takes from the end).
    fn ordered(mut self) -> Self {
        if let AggPart::Each(vs) = &mut self {
            vs.reverse();
        }
        self
    }
}

impl<'c> Run<'_, 'c> {
    /// The bounds of an array aggregate of type `t` with `items` positional
    /// components (`named`: None) or the named choices' ranges, checked: at
    /// most [`MAX_ELEMENTS`] components (Storage_Error), as many as the
    /// bounds hold unless `others` fills the rest, and every choice inside
    /// them (Constraint_Error).
    pub(crate) fn agg_bounds(
        &mut self,
        t: TypeId,
        items: usize,
        named: Option<&[(i64, i64)]>,
        has_others: bool,
        span: Span,
    ) -> R<AggBounds> {
        let fixed = self.array_bounds(t)?.map(|b| b[0]);
        let (lo, hi) = match (fixed, named) {
            (Some(b), _) => b,
            (None, None) => {
                let lo = self.index_first(t);
                (lo, lo + items as i64 - 1)
            }
            (None, Some(rs)) => (
                rs.iter().map(|r| r.0).min().unwrap_or(1),
                rs.iter().map(|r| r.1).max().unwrap_or(0),
            ),
        };
        if hi - lo + 1 > MAX_ELEMENTS {
            return Err(self.raise(check::STORAGE_ERROR, "aggregate too large", span));
        }
        self.reserve(hi - lo + 1, span)?;
        let n = (hi - lo + 1).max(0);
        let covered = match named {
            None => items as i64,
            Some(rs) => {
                let mut c = 0;
                for &(l, h) in rs.iter().filter(|(l, h)| l <= h) {
                    if l < lo || h > hi {
                        return Err(self.check_failed("index check failed", span));
                    }
                    c += h - l + 1;
                }
                c
            }
        };
        if covered > n || (covered < n && !has_others) {
            return Err(self.check_failed("length check failed", span));
        }
        Ok(AggBounds {
            lo,
            hi,
            others: n - covered,
        })
    }

    /// The first index of an array type's index subtype (the lower bound
    /// of a positional aggregate of an unconstrained type).
    fn index_first(&self, t: TypeId) -> i64 {
        let types = self.c.types;
        types
            .array(t)
            .and_then(|(i, _, _)| i.first().copied())
            .map(|it| match types.get(it).static_range {
                Some((l, _)) => l as i64,
                None => match types.kind(it) {
                    TypeKind::Enum(_) => 0,
                    _ => i32::MIN as i64,
                },
            })
            .unwrap_or(1)
    }

    /// A positional array aggregate's value from its components and the
    /// part `others` gives the rest (see [`Self::agg_bounds`]).
    pub(crate) fn positional_agg(
        &mut self,
        t: TypeId,
        b: &AggBounds,
        mut items: Vec<Value>,
        others: Option<AggPart>,
        span: Span,
    ) -> R<Value> {
        if let Some(o) = others
            && b.others > 0
        {
            let mut o = o.ordered();
            for _ in 0..b.others {
                items.push(o.next().unwrap_or_default());
            }
        }
        self.agg_array(t, items, (b.lo, b.hi), span)
    }

    /// A named array aggregate's value from its choices (ranges and the
    /// part each gives) and `others`.
    pub(crate) fn named_agg(
        &mut self,
        t: TypeId,
        b: &AggBounds,
        choices: Vec<(Vec<(i64, i64)>, AggPart)>,
        others: Option<AggPart>,
        span: Span,
    ) -> R<Value> {
        let n = (b.hi - b.lo + 1).max(0) as usize;
        let mut vals: Vec<Option<Value>> = vec![None; n];
        for (rs, part) in choices {
            let mut part = part.ordered();
            for (l, h) in rs {
                for i in l..=h {
                    vals[(i - b.lo) as usize] = part.next();
                }
            }
        }
        let mut others = others.map(AggPart::ordered);
        let mut out = Vec::with_capacity(n);
        for v in vals {
            match v.or_else(|| others.as_mut().and_then(AggPart::next)) {
                Some(v) => out.push(v),
                None => return Err(self.check_failed("length check failed", span)),
            }
        }
        self.agg_array(t, out, (b.lo, b.hi), span)
    }

    fn agg_array(
        &mut self,
        t: TypeId,
        vals: Vec<Value>,
        first: (i64, i64),
        span: Span,
    ) -> R<Value> {
        let fixed = self.array_bounds(t)?;
        // Rows of a multi-dimensional aggregate are flattened, also when the
        // type is unconstrained and the bounds come from the rows.
        let dims = self.c.types.array(t).map_or(1, |(i, _, _)| i.len());
        self.rows_to_array(vals, first, fixed, dims, span)
    }

    /// A record aggregate's value of type `t` from its components in
    /// order, the discriminants first: the components of the variant not
    /// chosen are cleared, and those whose subtypes read the
    /// discriminants fit them.
    pub(crate) fn record_agg(&mut self, t: TypeId, mut v: value::Fields, span: Span) -> R<Value> {
        let nd = self.c.types.discriminants(t).len();
        if nd > 0 {
            self.m.discrs.push(v[..nd].to_vec());
            let r = self.shape_record(t, &mut v, span);
            self.m.discrs.pop();
            r?;
        }
        Ok(Value::record(v))
    }

    /// `new T'(v)` or `new T`: the designated object, with room for it.
    pub(crate) fn allocate(&mut self, v: Value, span: Span) -> R<Value> {
        self.reserve(4, span)?;
        Ok(Value::Ptr(Some(Obj::new(v))))
    }

    /// The object `new T` makes for the access type `access`: its default
    /// value, whose tasks belong to the access type's master (activated
    /// by the caller).
    pub(crate) fn allocated_default(&mut self, access: TypeId, t: TypeId, span: Span) -> R<Value> {
        let outer = self.m.sched.alloc_master;
        self.m.sched.alloc_master = self.collection_master(access);
        let v = self.default_value(t, span);
        self.m.sched.alloc_master = outer;
        v
    }

    /// The value of the discriminant `i` of the record being built (a
    /// component's default, a bound of a component's subtype).
    pub(crate) fn discriminant(&self, i: u32, span: Span) -> R<Value> {
        match self.m.discrs.last().and_then(|d| d.get(i as usize)) {
            Some(v) => Ok(v.clone()),
            None => Err(self.raise(
                check::PROGRAM_ERROR,
                "a discriminant read outside its record",
                span,
            )),
        }
    }
}

/// Whether evaluating `e` again gives an equal value and does nothing
/// else (no call, no allocator, no check against bounds that are not
/// static, which evaluates them): then a choice that covers many
/// components is evaluated once, not once per component (RM 4.3.3(23)
/// asks for the latter, which only such effects could tell apart;
/// nothing else runs between the components' evaluations). The engine's
/// [`vm::effects_unless`] decides, with aggregates and range checks judged
/// here. Both engines ask it.
pub(crate) fn repeatable(types: &check::types::Types, e: &Ex) -> bool {
    !vm::effects_unless(e, &|x| match &x.kind {
        ExKind::ArrayAgg(a) => Some(!repeatable_agg(types, a)),
        ExKind::RangeCheck(_, t) => {
            let info = types.get(*t);
            (info.static_range.is_none() && info.static_frange.is_none()).then_some(true)
        }
        _ => None,
    })
}

/// [`repeatable`] for an array aggregate: its type's bounds and its parts.
fn repeatable_agg(types: &check::types::Types, a: &ArrayAgg) -> bool {
    let both = |(l, h): &(Ex, Ex)| repeatable(types, l) && repeatable(types, h);
    let bounds = match types.array(a.ty) {
        Some((_, _, Some(bs))) => bs.iter().all(both),
        _ => true,
    };
    bounds
        && match &a.kind {
            ArrayAggKind::Positional(items, others) => {
                items.iter().all(|i| repeatable(types, i))
                    && others.as_deref().is_none_or(|o| repeatable(types, o))
            }
            ArrayAggKind::Named(choices, others) => {
                choices
                    .iter()
                    .all(|(rs, v)| repeatable(types, v) && rs.iter().all(both))
                    && others.as_deref().is_none_or(|o| repeatable(types, o))
            }
        }
}
