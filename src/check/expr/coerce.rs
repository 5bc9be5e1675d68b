//! Coercion to an expected type: compatibility, universal operands, the
//! run-time checks Ada requires, and the type-mismatch messages and hints.

use super::*;

impl Checker {
    /// Converts a checked expression to the type `t`: reports a mismatch, fixes
    /// the type of universal operands and adds the run-time checks Ada requires
    /// (range of a constrained scalar subtype, length of a constrained array).
    /// Converts an operand to the base type of `t` (unconstrained, as Ada's
    /// `T'Base`): compatibility and universal types, but no range check.
    pub(in crate::check) fn coerce_base(&mut self, ex: Ex, t: TypeId) -> Ex {
        let base = self.tables.types.base(t);
        let saved = self.tables.types.list[base as usize].range.take();
        let r = self.coerce_to(ex, base, false);
        self.tables.types.list[base as usize].range = saved;
        r
    }

    pub(in crate::check) fn coerce(&mut self, ex: Ex, t: TypeId) -> Ex {
        self.coerce_to(ex, t, true)
    }

    /// [`Self::coerce`]; `whole` when `ex` is not an operand of a larger
    /// expression (the value of a static one is then its type's, RM 4.9(38)).
    fn coerce_to(&mut self, mut ex: Ex, t: TypeId, whole: bool) -> Ex {
        if ex.ty == ERROR || t == ERROR {
            return ex;
        }
        if !self.tables.types.compatible(ex.ty, t) {
            let mut d = diagnostics::type_mismatch(
                ex.span,
                &self.tname(t),
                &self.found_desc(ex.ty),
                &self.tname(ex.ty),
            );
            let (tf, ti) = (
                self.tables.types.is_float(t),
                self.tables.types.is_integer(t),
            );
            if tf && self.tables.types.is_integer(ex.ty) {
                d = match &ex.kind {
                    ExKind::Int(v) => d.with_hint(format!("write the literal as a real: `{v}.0`")),
                    _ => d.with_hint(format!(
                        "convert it: `{} ({})`",
                        self.tables.types.name(t),
                        self.snippet(ex.span)
                    )),
                };
            } else if ti && self.tables.types.is_float(ex.ty) {
                d = d.with_hint(format!(
                    "convert it: `{} ({})` (rounds to nearest, ties away from zero)",
                    self.tables.types.name(t),
                    self.snippet(ex.span)
                ));
            } else if t == types::STRING
                && matches!(
                    self.tables.types.kind(self.tables.types.base(ex.ty)),
                    TypeKind::Integer
                        | TypeKind::Float
                        | TypeKind::Enum(_)
                        | TypeKind::UnivInt
                        | TypeKind::UnivReal
                )
            {
                // `Put_Line (Count)`: text is made with 'Image.
                let tn = match self.tables.types.kind(ex.ty) {
                    TypeKind::UnivInt => "Integer".to_string(),
                    TypeKind::UnivReal => "Float".to_string(),
                    _ => self.tables.types.name(ex.ty).to_string(),
                };
                d = d.with_hint(format!(
                    "make it text: `{tn}'Image ({})`",
                    self.snippet(ex.span)
                ));
            } else if self.tables.types.base(t) == types::CHARACTER
                && matches!(
                    self.tables.types.kind(self.tables.types.base(ex.ty)),
                    TypeKind::Integer | TypeKind::Float | TypeKind::UnivInt | TypeKind::UnivReal
                )
            {
                // `"Z is " & Z`: `&` joins characters and strings only.
                let tn = match self.tables.types.kind(ex.ty) {
                    TypeKind::UnivInt => "Integer".to_string(),
                    TypeKind::UnivReal => "Float".to_string(),
                    _ => self.tables.types.name(ex.ty).to_string(),
                };
                d = d.with_hint(format!(
                    "`&` joins text, not numbers: make it text with `{tn}'Image ({})`",
                    self.snippet(ex.span)
                ));
            } else if self.tables.types.base(ex.ty) == types::STRING
                && (ti
                    || tf
                    || matches!(
                        self.tables.types.kind(self.tables.types.base(t)),
                        TypeKind::Enum(_)
                    ))
            {
                // Text where a number or an enumeration value is wanted.
                let text = self.snippet(ex.span);
                let lit = text.strip_prefix('"').and_then(|t| t.strip_suffix('"'));
                let lits = self
                    .tables
                    .types
                    .enum_lits(t)
                    .map(|l| l.to_vec())
                    .unwrap_or_default();
                let same = lit.and_then(|l| lits.iter().find(|x| x.eq_ignore_ascii_case(l)));
                let hint = match (same, lit) {
                    (Some(name), _) => format!(
                        "write `{}` without quotes",
                        self.spelled(&name.to_lowercase())
                    ),
                    (None, Some(l)) if (ti || tf) && !l.is_empty() => format!(
                        "convert the text: `{}'Value ({text})`, or write the number `{l}`",
                        self.tables.types.name(t)
                    ),
                    _ => format!(
                        "convert the text: `{}'Value ({text})`",
                        self.tables.types.name(t)
                    ),
                };
                d = d.with_hint(hint);
            } else if let ExKind::Int(v) = ex.kind
                && self.tables.types.is_universal(ex.ty)
            {
                // An integer literal where a Boolean or an enumeration
                // value is wanted.
                if self.tables.types.base(t) == types::BOOLEAN {
                    d = d.with_hint(format!(
                        "write `{}` (Ada's Boolean is not a number)",
                        if v == 0 { "False" } else { "True" }
                    ));
                } else if let Some(lits) = self.tables.types.enum_lits(t).map(|l| l.to_vec())
                    && self.tables.types.base(t) != types::CHARACTER
                {
                    let names: Vec<String> = lits
                        .iter()
                        .take(6)
                        .map(|l| format!("`{}`", self.spelled(&l.to_lowercase())))
                        .collect();
                    let more = if lits.len() > 6 { ", ..." } else { "" };
                    d = d.with_hint(format!(
                        "write one of {}{more} (or `{}'Val ({v})`)",
                        names.join(", "),
                        self.tables.types.name(t)
                    ));
                }
            }
            if self.tables.types.is_hidden(t)
                && (self.tables.types.is_universal(ex.ty)
                    || matches!(
                        self.tables.types.kind(ex.ty),
                        TypeKind::Null | TypeKind::AnyComposite
                    ))
            {
                d = d.with_hint(format!(
                    "`{}` is a private type: outside `{}` its values come from what `{}` declares",
                    self.tname(t),
                    self.private_package(t),
                    self.private_package(t)
                ));
            }
            self.err(d);
            ex.ty = ERROR;
            return ex;
        }
        // A modular type's base range is 0 .. modulus - 1 (RM 4.9(35)):
        // a static value outside it is illegal, not wrapped.
        if let Some(n) = self.tables.types.modulus(t)
            && let Some(Static::Int(v)) = self.shallow_static(&ex)
        {
            if v < 0 || v >= n as i128 {
                let tn = self.tname(self.tables.types.base(t));
                self.err(diagnostics::static_outside_modular(ex.span, v, &tn, n - 1));
                ex.ty = ERROR;
                return ex;
            }
        } else if let ExKind::Int(v) = ex.kind
            && self.tables.types.is_integer(t)
            && !self.tables.types.is_universal(t)
            && i32::try_from(v).is_err()
        {
            self.err(diagnostics::static_outside_integer(
                ex.span,
                v,
                &self.tname(t),
            ));
            ex.ty = ERROR;
            return ex;
        }
        // RM 4.9(35): a static real expected of a floating point type lies
        // in that type's base range (a literal beyond it, `1.0E309` or
        // `1.0E39` for `Float`, is illegal, not infinity).
        if self.tables.types.is_float(t)
            && !self.tables.types.is_universal(t)
            && let Some((lo, hi)) = self.float_base_range(t)
            && (matches!(ex.kind, ExKind::Real(v) if !v.is_finite())
                || matches!(self.static_value(&ex), Some(Static::Real(v))
                    if exact::overflows(&v) || !(lo..=hi).contains(&exact::to_f64(&v))))
        {
            let e = |x: f64| {
                let t = format!("{x:.5e}");
                match t.split_once('e') {
                    Some((m, p)) if p.starts_with('-') => format!("{m}E{p}"),
                    Some((m, p)) => format!("{m}E+{p}"),
                    None => t,
                }
            };
            let shown = match self.snippet(ex.span) {
                s if s.len() <= 40 => s,
                _ => "the static value".to_string(),
            };
            self.err(diagnostics::static_outside_float(
                ex.span,
                &shown,
                &self.tname(self.tables.types.base(t)),
                &e(lo),
                &e(hi),
            ));
            ex.ty = ERROR;
            return ex;
        }
        // RM 4.9(38): a static value given to Duration is a whole number
        // of nanoseconds, truncated toward zero as GNAT does.
        if whole
            && self.tables.types.whole_ns(t)
            && let Some(Static::Real(v)) = self.static_value(&ex)
        {
            let ns = exact::to_whole_ns(&v);
            if ns != v {
                let (ty, span) = (ex.ty, ex.span);
                ex = self.real_lit(ns, ty, span);
            }
        }
        let from = ex.ty;
        if self.tables.types.is_universal(ex.ty)
            || matches!(
                self.tables.types.kind(ex.ty),
                TypeKind::Null | TypeKind::AnyComposite
            )
        {
            ex.ty = t;
        }
        let info = self.tables.types.get(t);
        // Operations yield values of the base type, which may lie outside
        // the subtype even when their type is the subtype itself.
        let computed = matches!(
            ex.kind,
            ExKind::IntBin(..)
                | ExKind::ModBin(..)
                | ExKind::FloatBin(..)
                | ExKind::IntNeg(_)
                | ExKind::FloatNeg(_)
                | ExKind::IntAbs(_)
                | ExKind::FloatAbs(_)
                | ExKind::IntToFloat(_)
                | ExKind::FloatToInt(_)
        );
        if self.tables.types.is_scalar(t)
            && info.range.is_some()
            && (from != t || computed)
            && t != INTEGER
        {
            // Statically known to be in range: no check needed.
            let inside = match (
                self.static_value(&ex),
                info.static_range,
                info.static_frange,
            ) {
                (Some(Static::Int(v)), Some((l, h)), _) => l <= v && v <= h,
                (Some(Static::Real(v)), _, Some((l, h))) => {
                    let v = exact::to_f64(&v);
                    l <= v && v <= h
                }
                _ => false,
            };
            let same_range = !computed
                && from != ERROR
                && self.tables.types.get(from).static_range.is_some()
                && self.tables.types.get(from).static_range == info.static_range;
            if !inside && !same_range {
                // A static value outside a static range: it will raise.
                let outside = match (
                    self.static_value(&ex),
                    info.static_range,
                    info.static_frange,
                ) {
                    (Some(Static::Int(v)), Some((l, h)), _) => {
                        Some((v.to_string(), l.to_string(), h.to_string()))
                    }
                    (Some(Static::Real(v)), _, Some((l, h))) => Some((
                        format!("{:?}", exact::to_f64(&v)),
                        format!("{l:?}"),
                        format!("{h:?}"),
                    )),
                    _ => None,
                };
                if let Some((v, l, h)) = outside {
                    let tn = self.tname(t);
                    self.err(diagnostics::will_raise_constraint_error(
                        ex.span, &v, &tn, &l, &h,
                    ));
                }
                let span = ex.span;
                return self.mk(ExKind::RangeCheck(bx(ex), t), t, span);
            }
            ex.ty = t;
            return ex;
        }
        if ex.ty != t
            && let Some(want) = self
                .tables
                .types
                .discriminant_constraint(t)
                .map(|c| c.to_vec())
        {
            // A discriminant check (RM 4.6(51)), unless the discriminants
            // are statically those of the subtype.
            let want: Vec<Option<Static>> = want.iter().map(|w| self.static_value(w)).collect();
            let have = self.static_discriminants(&ex);
            if let Some(have) = have
                && want.iter().all(Option::is_some)
            {
                let bad = want
                    .iter()
                    .zip(&have)
                    .position(|(w, h)| h.as_ref().is_some_and(|h| w.as_ref() != Some(h)));
                if let Some(i) = bad {
                    let name = self.tables.types.discriminants(t)[i].name.clone();
                    self.err(diagnostics::wrong_discriminant_value(
                        ex.span,
                        &name,
                        &self.tname(t),
                    ));
                } else if have.iter().all(Option::is_some) {
                    ex.ty = t;
                    return ex;
                }
            }
            let span = ex.span;
            return self.mk(ExKind::RangeCheck(bx(ex), t), t, span);
        }
        if let Some((_, _, Some(_))) = self.tables.types.array(t)
            && ex.ty != t
        {
            let span = ex.span;
            return self.mk(ExKind::ArrayConvert(bx(ex), t), t, span);
        }
        ex
    }

    /// The discriminants of a record value, where the checker knows them:
    /// an aggregate's static ones, or those of a constrained subtype.
    fn static_discriminants(&self, ex: &Ex) -> Option<Vec<Option<Static>>> {
        let n = self.tables.types.discriminants(ex.ty).len();
        if n == 0 {
            return None;
        }
        if let ExKind::RecordAgg(fields) = &ex.kind {
            return Some(
                fields
                    .get(..n)?
                    .iter()
                    .map(|f| self.static_value(f))
                    .collect(),
            );
        }
        let c = self.tables.types.discriminant_constraint(ex.ty)?;
        Some(c.iter().map(|f| self.static_value(f)).collect())
    }

    fn found_desc(&self, t: TypeId) -> String {
        match self.tables.types.kind(t) {
            TypeKind::UnivInt => "an integer literal".into(),
            TypeKind::UnivReal => "a real literal".into(),
            TypeKind::AnyComposite => "an aggregate".into(),
            TypeKind::Null => "`null`".into(),
            _ => format!("`{}`", self.tables.types.name(t)),
        }
    }

    /// Chooses one type for several expressions that must share one.
    pub(in crate::check) fn common_type(&mut self, es: &[&ast::Expr], default: TypeId) -> TypeId {
        let mut univ = None;
        for e in es {
            for t in self.interps(e) {
                if !self.tables.types.is_universal(t)
                    && !matches!(
                        self.tables.types.kind(t),
                        TypeKind::Null | TypeKind::AnyComposite | TypeKind::Error
                    )
                {
                    if es.iter().all(|x| self.fits(x, t)) {
                        return t;
                    }
                } else if univ.is_none() {
                    univ = Some(t);
                }
            }
        }
        match univ {
            Some(UNIV_REAL) => FLOAT,
            Some(UNIV_INT) => default,
            _ => default,
        }
    }

    /// Can `e` have type `t`?
    pub(in crate::check) fn fits(&mut self, e: &ast::Expr, t: TypeId) -> bool {
        if t == ERROR {
            return true;
        }
        match &e.kind {
            ExprKind::Str(_) => {
                self.tables.types.array(t).is_some_and(|(i, el, _)| {
                    i.len() == 1 && self.tables.types.base(el) == CHARACTER
                })
            }
            ExprKind::Aggregate(_) => matches!(
                self.tables.types.kind(t),
                TypeKind::Array { .. } | TypeKind::Record(_)
            ),
            ExprKind::Allocator(..) | ExprKind::Null => self.tables.types.is_access(t),
            ExprKind::Paren(x) => self.fits(x, t),
            ExprKind::If { arms, .. } => arms.first().is_none_or(|a| self.fits(&a.1, t)),
            _ => {
                let is = self.interps(e);
                is.is_empty()
                    || is
                        .iter()
                        .any(|u| *u == ERROR || self.tables.types.compatible(*u, t))
            }
        }
    }

    /// The base range of a floating point type (RM 3.5.7): single precision
    /// up to 6 digits, as GNAT; `Duration`'s own.
    fn float_base_range(&self, t: TypeId) -> Option<(f64, f64)> {
        let base = self.tables.types.base(t);
        if base == DURATION {
            return self.tables.types.get(base).static_frange;
        }
        let max = if self.tables.types.digits(t) <= 6 {
            f32::MAX as f64
        } else {
            f64::MAX
        };
        Some((-max, max))
    }
}
