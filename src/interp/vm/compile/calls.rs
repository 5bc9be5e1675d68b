//! Compiling calls.

use super::*;

impl<'r> Compiler<'r> {
    pub(in crate::interp::vm) fn call(
        &mut self,
        f: FuncId,
        args: Option<&[Arg]>,
        dst: Option<Var>,
        span: Span,
    ) {
        let all: &[Arg] = args.unwrap_or_default();
        if (self.walker_calls)(f) {
            // The walker copies `out` values back into their targets.
            if all.iter().any(|a| a.mode != Mode::In) {
                self.scalar = false;
            }
            // `in` arguments with calls in them are computed here, so that
            // those calls run compiled.
            if all.iter().any(|a| effects(&a.value))
                && all.iter().all(|a| a.mode == Mode::In || !effects(&a.value))
            {
                let owned: Vec<Arg> = all
                    .iter()
                    .map(|a| {
                        if a.mode != Mode::In {
                            return a.clone();
                        }
                        let t = self.temp();
                        self.expr_into(&a.value, t);
                        Arg {
                            mode: a.mode,
                            value: Ex {
                                kind: ExKind::Var(t),
                                ty: a.value.ty,
                                span: a.value.span,
                            },
                            back_check: a.back_check,
                        }
                    })
                    .collect();
                self.ops.push(Op::CallWalker(f, owned.into(), dst, span));
            } else {
                self.ops.push(Op::CallWalker(f, all.into(), dst, span));
            }
            return;
        }
        if let [a] = all
            && a.mode == Mode::In
            && a.value.span.context == span.context
            && let ExKind::IntBin(op, x, k) = &a.value.kind
            && let ExKind::Int(k) = k.kind
            && let Ok(k) = i32::try_from(k)
        {
            let x = self.expr(x);
            let at = [a.value.span.start, a.value.span.end];
            let dst = dst.unwrap_or(NO_VAR);
            self.ops.push(Op::CallK {
                f,
                x,
                op: *op,
                k,
                dst,
                span,
                arg_at: at,
            });
            return;
        }
        let mut ops = Vec::with_capacity(all.len() + 1);
        for (k, a) in all.iter().enumerate() {
            let later = all[k + 1..].iter().any(|b| effects(&b.value));
            let mut v = self.expr(&a.value);
            if later && !self.is_temp(v) {
                self.holds(a.value.ty);
                let t = self.temp();
                self.ops.push(Op::Move(t, v));
                v = t;
            }
            ops.push(v);
        }
        ops.extend(dst);
        // The copy-back needs the arguments (see `call_site`).
        let args = all
            .iter()
            .any(|a| a.mode != Mode::In)
            .then(|| Box::new(Box::from(all)));
        self.ops
            .push(Op::Call(dst.is_some(), f, args, ops.into(), span));
    }
}
