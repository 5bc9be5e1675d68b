//! Aggregates: positional, named and `others` associations of records and
//! arrays.

use super::*;

impl Checker {
    /// A record aggregate (RM 4.3.1): the discriminants first, then the
    /// components of the variant they choose (a discriminant that governs
    /// a variant must be static), each exactly once.
    fn record_aggregate(
        &mut self,
        items: &[ast::Assoc],
        t: TypeId,
        fields: &[types::Field],
        sp: Span,
    ) -> Ex {
        let nd = fields.iter().take_while(|f| f.discriminant).count();
        let tn = self.tables.types.name(t).to_string();
        // Which component each association names: positional ones in
        // order (the discriminants, then the components present), named
        // ones by name, `others` the rest.
        enum To<'a> {
            Pos(&'a ast::Assoc),
            Named(&'a ast::Assoc, usize),
            Others(&'a ast::Assoc),
        }
        let mut assocs: Vec<To> = Vec::new();
        for it in items {
            if it.choices.is_empty() {
                assocs.push(To::Pos(it));
                continue;
            }
            for c in &it.choices {
                match c {
                    Choice::Others(_) => assocs.push(To::Others(it)),
                    Choice::Expr(ast::Expr {
                        kind: ExprKind::Name(n),
                        ..
                    }) => match fields.iter().position(|f| *f.key == *n.key) {
                        Some(i) => {
                            self.index_field_ref(n.span, t, i as u32);
                            assocs.push(To::Named(it, i));
                        }
                        None => {
                            self.err(diagnostics::aggregate_no_component(n.span, &tn, &n.name));
                        }
                    },
                    Choice::Expr(x) | Choice::Range(x, _) => {
                        self.err(diagnostics::record_aggregate_unnamed(x.span));
                    }
                }
            }
        }
        let mut vals: Vec<Option<Ex>> = vec![None; fields.len()];
        // The discriminants: positional first, then named.
        let positional: Vec<&ast::Assoc> = assocs
            .iter()
            .filter_map(|a| match a {
                To::Pos(it) => Some(*it),
                _ => None,
            })
            .collect();
        let given = |c: &mut Self, i: usize, it: &ast::Assoc, vals: &mut Vec<Option<Ex>>| {
            let f = &fields[i];
            if matches!(it.value.kind, ExprKind::Error) {
                // `Name => <>`: the component's default.
                let ft = f.dependent.unwrap_or(f.ty);
                vals[i] = Some(f.default.clone().unwrap_or(Ex {
                    kind: ExKind::Default(ft),
                    ty: ft,
                    span: it.span,
                }));
                return;
            }
            let v = c.expr(&it.value, Some(f.ty));
            vals[i] = Some(c.coerce(v, f.ty));
        };
        for (i, it) in positional.iter().take(nd).enumerate() {
            given(self, i, it, &mut vals);
        }
        for a in &assocs {
            if let To::Named(it, i) = a
                && *i < nd
            {
                given(self, *i, it, &mut vals);
            }
        }
        // The components present: those of the variant the (static)
        // discriminants choose.
        let statics: Vec<Option<i64>> = vals[..nd]
            .iter()
            .map(|v| match v.as_ref().and_then(|v| self.static_value(v)) {
                Some(Static::Int(x)) => i64::try_from(x).ok(),
                _ => None,
            })
            .collect();
        let mut reported = vec![false; nd];
        let mut present = vec![true; fields.len()];
        for (i, f) in fields.iter().enumerate() {
            let Some(conds) = &f.variant else { continue };
            for (d, ranges) in conds.iter() {
                let d = *d as usize;
                match statics[d] {
                    Some(x) => {
                        if !ranges.iter().any(|(l, h)| *l <= x && x <= *h) {
                            present[i] = false;
                        }
                    }
                    None => {
                        if let Some(v) = &vals[d]
                            && !reported[d]
                            && v.ty != ERROR
                        {
                            reported[d] = true;
                            self.err(diagnostics::discriminant_not_static(
                                v.span,
                                &fields[d].name,
                            ));
                        }
                        present[i] = false;
                    }
                }
            }
        }
        let chosen = {
            let shown: Vec<String> = (0..nd)
                .filter_map(|d| {
                    vals[d]
                        .as_ref()
                        .map(|v| format!("`{} => {}`", fields[d].name, self.snippet(v.span)))
                })
                .collect();
            shown.join(", ")
        };
        // The other components.
        let mut next = nd;
        for it in positional.iter().skip(nd) {
            while next < fields.len() && !present[next] {
                next += 1;
            }
            if next >= fields.len() {
                let count = present.iter().filter(|p| **p).count();
                if !reported.iter().any(|r| *r) {
                    self.err(diagnostics::aggregate_too_many(it.span, &tn, count));
                }
                self.expr(&it.value, None);
                continue;
            }
            given(self, next, it, &mut vals);
            next += 1;
        }
        for a in &assocs {
            match a {
                To::Named(it, i) if *i >= nd => {
                    if !present[*i] {
                        if !reported.iter().any(|r| *r) {
                            let text = chosen.clone();
                            self.err(diagnostics::component_not_in_variant(
                                it.choices
                                    .iter()
                                    .find_map(|c| match c {
                                        Choice::Expr(x) => Some(x.span),
                                        _ => None,
                                    })
                                    .unwrap_or(it.span),
                                &fields[*i].name,
                                &text,
                            ));
                        }
                        self.expr(&it.value, Some(fields[*i].ty));
                        continue;
                    }
                    given(self, *i, it, &mut vals);
                }
                To::Others(it) => {
                    for i in 0..fields.len() {
                        if vals[i].is_none() && present[i] {
                            given(self, i, it, &mut vals);
                        }
                    }
                }
                _ => {}
            }
        }
        let mut out = Vec::with_capacity(fields.len());
        for (i, v) in vals.into_iter().enumerate() {
            match v {
                Some(v) => out.push(v),
                None if !present[i] => out.push(Ex::int(0)),
                None => {
                    if !reported.iter().any(|r| *r) {
                        self.err(diagnostics::aggregate_lacks(sp, &fields[i].name, &tn));
                    }
                    out.push(self.err_ex(sp));
                }
            }
        }
        // Its type is the record type: a constrained subtype expected is
        // then checked against its discriminants (`coerce`).
        let ty = if nd > 0 { self.tables.types.base(t) } else { t };
        self.mk(ExKind::RecordAgg(out.into()), ty, sp)
    }

    pub(super) fn aggregate(&mut self, items: &[ast::Assoc], t: TypeId, sp: Span) -> Ex {
        if let Some(fields) = self.tables.types.fields(t).map(|f| f.to_vec()) {
            return self.record_aggregate(items, t, &fields, sp);
        }
        let Some((idx, el, bounds)) = self
            .tables
            .types
            .array(t)
            .map(|(i, e, b)| (i.to_vec(), e, b.cloned()))
        else {
            self.err(diagnostics::aggregate_wrong_type(sp, &self.tname(t)));
            return self.err_ex(sp);
        };
        // For several dimensions, components are rows of the remaining dimensions.
        let comp_ty = if idx.len() > 1 {
            let rest = TypeKind::Array {
                index: idx[1..].to_vec(),
                elem: el,
                bounds: bounds.as_ref().map(|b| b[1..].to_vec()),
            };
            let name = format!("{} row", self.tables.types.name(t));
            self.tables.types.add(&name, rest)
        } else {
            el
        };
        let mut positional = Vec::new();
        let mut named = Vec::new();
        let mut others = None;
        for it in items {
            // `Choice => <>` (parsed as an error value): the component's
            // default (RM 4.3.3(23.1)).
            let v = if matches!(it.value.kind, ExprKind::Error) && !it.choices.is_empty() {
                Ex {
                    kind: ExKind::Default(comp_ty),
                    ty: comp_ty,
                    span: it.span,
                }
            } else {
                let v = self.expr(&it.value, Some(comp_ty));
                self.coerce(v, comp_ty)
            };
            if it.choices.is_empty() {
                positional.push(v);
                continue;
            }
            let mut ranges = Vec::new();
            for c in &it.choices {
                match c {
                    Choice::Others(_) => others = Some(bx(v.clone())),
                    Choice::Expr(x) => {
                        if let Some(tt) = self.denote_quiet_type(x) {
                            ranges.push((
                                self.mk(ExKind::TypeFirst(tt), tt, x.span),
                                self.mk(ExKind::TypeLast(tt), tt, x.span),
                            ));
                        } else {
                            let i = self.expr(x, Some(idx[0]));
                            let i = self.coerce_base(i, idx[0]);
                            ranges.push((i.clone(), i));
                        }
                    }
                    Choice::Range(l, h) => {
                        let l = self.expr(l, Some(idx[0]));
                        let l = self.coerce_base(l, idx[0]);
                        let h = self.expr(h, Some(idx[0]));
                        let h = self.coerce_base(h, idx[0]);
                        ranges.push((l, h));
                    }
                }
            }
            if !ranges.is_empty() {
                named.push((ranges, v));
            }
        }
        if !positional.is_empty() && !named.is_empty() {
            self.err(diagnostics::aggregate_mixed(sp));
        }
        // RM 4.3.3(18): static choices never cover an index twice.
        let mut seen: Vec<(i128, i128, Span)> = Vec::new();
        for (ranges, _) in &named {
            for (l, h) in ranges {
                if let (Some(Static::Int(a)), Some(Static::Int(b))) =
                    (self.static_value(l), self.static_value(h))
                    && a <= b
                {
                    let span = Span {
                        start: l.span.start,
                        end: h.span.end.max(l.span.end),
                        context: l.span.context,
                    };
                    seen.push((a, b, span));
                }
            }
        }
        seen.sort_by_key(|x| (x.0, x.2.start));
        for w in seen.windows(2) {
            let ((_, prev_hi, prev_sp), (lo, _, sp2)) =
                ((w[0].0, w[0].1, w[0].2), (w[1].0, w[1].1, w[1].2));
            if lo <= prev_hi {
                let (first, second) = if prev_sp.start <= sp2.start {
                    (prev_sp, sp2)
                } else {
                    (sp2, prev_sp)
                };
                self.err(diagnostics::aggregate_choice_twice(second, first));
                break;
            }
        }
        if others.is_some() && bounds.is_none() {
            self.err(diagnostics::others_needs_bounds(
                sp,
                self.tables.types.name(t),
            ));
        }
        // A static length check for positional aggregates of constrained types.
        if let Some(b) = &bounds
            && others.is_none()
            && named.is_empty()
            && let (Some(Static::Int(l)), Some(Static::Int(h))) =
                (self.static_value(&b[0].0), self.static_value(&b[0].1))
        {
            let len = (h - l + 1).max(0) as usize;
            if positional.len() != len {
                self.err(diagnostics::aggregate_length(
                    sp,
                    self.tables.types.name(t),
                    len,
                    positional.len(),
                ));
            }
        }
        let kind = if named.is_empty() {
            ArrayAggKind::Positional(positional, others)
        } else {
            ArrayAggKind::Named(named, others)
        };
        self.mk(ExKind::ArrayAgg(Box::new(ArrayAgg { ty: t, kind })), t, sp)
    }
}
