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
        if (self.native_calls)(f) {
            let ops = self.arg_operands(all);
            let outs = self.out_slots(all);
            self.ops.push(Op::CallNative(Box::new(NativeOp {
                f,
                ops: ops.into(),
                outs: outs.clone().into(),
                dst,
                span,
            })));
            self.copy_back(all, &outs);
            return;
        }
        if let [a] = all
            && a.mode == Mode::In
            && a.value.span.context == span.context
            && let ExKind::IntBin(op @ (IntOp::Add | IntOp::Sub), x, k) = &a.value.kind
            && let ExKind::Int(k) = k.kind
            && let Ok(add) = i32::try_from(if *op == IntOp::Sub {
                -(k as i128)
            } else {
                k as i128
            })
        {
            let x = self.expr(x);
            let at = [a.value.span.start, a.value.span.end];
            let dst = dst.unwrap_or(NO_VAR);
            self.ops.push(Op::CallK {
                f,
                x,
                add,
                dst,
                span,
                arg_at: at,
            });
            return;
        }
        let mut ops = self.arg_operands(all);
        ops.extend(dst);
        let outs = self.out_slots(all);
        let back = (!outs.is_empty()).then(|| Box::new(Box::from(&outs[..])));
        self.ops.push(Op::Call {
            function: dst.is_some(),
            f,
            outs: back,
            ops: ops.into(),
            span,
        });
        self.copy_back(all, &outs);
    }

    /// The operands of a call's arguments, each read before the next is
    /// evaluated (copied to a temporary when a later one may change it).
    fn arg_operands(&mut self, all: &[Arg]) -> Vec<Var> {
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
        ops
    }

    /// A slot for each `out` and `in out` argument's value after the call.
    fn out_slots(&mut self, all: &[Arg]) -> Vec<(u32, Var)> {
        let mut outs = Vec::new();
        for (k, a) in all.iter().enumerate() {
            if a.mode != Mode::In {
                self.holds(a.value.ty);
                outs.push((k as u32, self.temp()));
            }
        }
        outs
    }

    /// After a call: each `out` value, checked against the actual's
    /// subtype, is assigned to the actual, in order.
    pub(in crate::interp::vm) fn copy_back(&mut self, all: &[Arg], outs: &[(u32, Var)]) {
        for &(k, v) in outs {
            let a = &all[k as usize];
            if let Some(t) = a.back_check {
                self.ops.push(Op::RangeCheck(v, t, a.value.span));
            }
            self.assign_from(&a.value, v);
        }
    }
}
