//! Aggregates: positional, named and `others` associations of records and
//! arrays.

use super::*;

impl Checker {
    pub(super) fn aggregate(&mut self, items: &[ast::Assoc], t: TypeId, sp: Span) -> Ex {
        if let Some(fields) = self.tables.types.fields(t).map(|f| f.to_vec()) {
            let mut vals: Vec<Option<Ex>> = vec![None; fields.len()];
            let mut pos = 0;
            for it in items {
                if it.choices.is_empty() {
                    if pos >= fields.len() {
                        self.err(diagnostics::aggregate_too_many(
                            it.span,
                            self.tables.types.name(t),
                            fields.len(),
                        ));
                        continue;
                    }
                    let v = self.expr(&it.value, Some(fields[pos].ty));
                    vals[pos] = Some(self.coerce(v, fields[pos].ty));
                    pos += 1;
                    continue;
                }
                for c in &it.choices {
                    let targets: Vec<usize> = match c {
                        Choice::Others(_) => {
                            (0..fields.len()).filter(|i| vals[*i].is_none()).collect()
                        }
                        Choice::Expr(ast::Expr {
                            kind: ExprKind::Name(n),
                            ..
                        }) => match fields.iter().position(|f| *f.key == *n.key) {
                            Some(i) => {
                                self.index_field_ref(n.span, t, i as u32);
                                vec![i]
                            }
                            None => {
                                self.err(diagnostics::aggregate_no_component(
                                    n.span,
                                    self.tables.types.name(t),
                                    &n.name,
                                ));
                                vec![]
                            }
                        },
                        Choice::Expr(x) | Choice::Range(x, _) => {
                            self.err(diagnostics::record_aggregate_unnamed(x.span));
                            vec![]
                        }
                    };
                    for i in targets {
                        if matches!(it.value.kind, ExprKind::Error) {
                            // `Name => <>`: the component's default.
                            let ft = fields[i].ty;
                            vals[i] = Some(fields[i].default.clone().unwrap_or(Ex {
                                kind: ExKind::Default(ft),
                                ty: ft,
                                span: it.span,
                            }));
                            continue;
                        }
                        let v = self.expr(&it.value, Some(fields[i].ty));
                        vals[i] = Some(self.coerce(v, fields[i].ty));
                    }
                }
            }
            let mut out = Vec::new();
            for (i, v) in vals.into_iter().enumerate() {
                match v {
                    Some(v) => out.push(v),
                    None => {
                        self.err(diagnostics::aggregate_lacks(
                            sp,
                            &fields[i].name,
                            self.tables.types.name(t),
                        ));
                        out.push(self.err_ex(sp));
                    }
                }
            }
            return self.mk(ExKind::RecordAgg(out.into()), t, sp);
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
