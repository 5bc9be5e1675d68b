//! Case choices: static values and ranges, coverage and overlap.

use super::*;

impl Checker {
    /// Static choices of a `case`: per arm, the ranges; and the index of the
    /// `others` arm. Reports non-static, duplicate and missing choices.
    pub(in crate::check) fn case_choices(
        &mut self,
        t: TypeId,
        arms: &[&[Choice]],
        sp: Span,
    ) -> (Vec<Vec<(i64, i64)>>, Option<usize>) {
        if !self.tables.types.is_discrete(t) && t != ERROR {
            self.err(diagnostics::case_needs_discrete(sp, &self.tname(t)));
        }
        let mut out = Vec::new();
        let mut others = None;
        let mut all: Vec<(i64, i64, Span)> = Vec::new();
        for (i, choices) in arms.iter().enumerate() {
            let mut rs = Vec::new();
            for c in choices.iter() {
                let (lo, hi, csp) = match c {
                    Choice::Others(s) => {
                        if i + 1 != arms.len() || choices.len() != 1 {
                            self.err(diagnostics::others_not_last(*s));
                        }
                        others = Some(i);
                        continue;
                    }
                    Choice::Expr(x) => {
                        if let Some(tt) = self.denote_quiet_type(x) {
                            match self.tables.types.discrete_bounds(tt) {
                                Some((l, h)) => {
                                    (Some(Static::Int(l)), Some(Static::Int(h)), x.span)
                                }
                                None => (None, None, x.span),
                            }
                        } else {
                            let v = self.expr(x, Some(t));
                            let v = self.coerce_base(v, t);
                            let s = self.static_value(&v);
                            (s.clone(), s, x.span)
                        }
                    }
                    Choice::Range(l, h) => {
                        let l = self.expr(l, Some(t));
                        let l = self.coerce_base(l, t);
                        let h = self.expr(h, Some(t));
                        let h = self.coerce_base(h, t);
                        let sp2 = Span {
                            start: l.span.start,
                            end: h.span.end,
                            context: l.span.context,
                        };
                        (self.static_value(&l), self.static_value(&h), sp2)
                    }
                };
                match (lo, hi) {
                    (Some(Static::Int(l)), Some(Static::Int(h))) => {
                        // A choice outside the selector's static subtype
                        // (RM 5.4(7); GNAT: "minimum allowed choice value").
                        if l <= h
                            && t != ERROR
                            && let Some((lo, hi)) = self.tables.types.discrete_bounds(t)
                            && (l < lo || h > hi)
                        {
                            let name = self.tables.types.name(t);
                            let lits = self.tables.types.enum_lits(t).map(|l| l.to_vec());
                            let show = |v: i128| match &lits {
                                Some(ls) if self.tables.types.base(t) != CHARACTER => ls
                                    .get(v as usize)
                                    .map(|l| l.to_string())
                                    .unwrap_or_default(),
                                _ => v.to_string(),
                            };
                            self.err(diagnostics::case_choice_outside(
                                csp,
                                name,
                                &show(lo),
                                &show(hi),
                            ));
                        }
                        let (l, h) = (l as i64, h as i64);
                        if l <= h {
                            if let Some(prev) = all.iter().find(|(a, b, _)| l <= *b && *a <= h) {
                                let prev_sp = prev.2;
                                self.err(diagnostics::case_choice_twice(csp, prev_sp));
                            }
                            all.push((l, h, csp));
                        }
                        rs.push((l, h));
                    }
                    _ => {
                        if t != ERROR {
                            self.err(diagnostics::case_choice_not_static(csp));
                        }
                    }
                }
            }
            out.push(rs);
        }
        if others.is_none() && t != ERROR && self.tables.types.is_discrete(t) {
            match self.tables.types.discrete_bounds(t) {
                Some((lo, hi)) => {
                    all.sort_by_key(|x| x.0);
                    let mut missing: Vec<(i128, i128)> = Vec::new();
                    let mut next = lo;
                    for (a, b, _) in &all {
                        if (*a as i128) > next {
                            missing.push((next, (*a as i128 - 1).min(hi)));
                        }
                        next = next.max(*b as i128 + 1);
                    }
                    if next <= hi {
                        missing.push((next, hi));
                    }
                    let missing: Vec<(i128, i128)> =
                        missing.into_iter().filter(|(a, b)| a <= b).collect();
                    if !missing.is_empty() {
                        let lits = self.tables.types.enum_lits(t).map(|l| l.to_vec());
                        let show = |v: i128| match &lits {
                            Some(l) if self.tables.types.base(t) != CHARACTER => {
                                l.get(v as usize).map(|l| l.to_string()).unwrap_or_default()
                            }
                            _ => v.to_string(),
                        };
                        let text: Vec<String> = missing
                            .iter()
                            .take(8)
                            .map(|(a, b)| {
                                if a == b {
                                    show(*a)
                                } else {
                                    format!("{} .. {}", show(*a), show(*b))
                                }
                            })
                            .collect();
                        self.err(diagnostics::case_missing(
                            sp,
                            self.tables.types.name(t),
                            &text,
                        ));
                    }
                }
                None => self.err(diagnostics::case_needs_others(
                    sp,
                    self.tables.types.name(t),
                )),
            }
        }
        (out, others)
    }
}
