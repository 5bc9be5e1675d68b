#[cfg(test)]
mod size_tests {
    /// A long program's main body is one compiled code (issue 14): an
    /// instruction of 48 bytes, not 64 (a call keeps its result slot among
    /// its operands).
    #[test]
    fn instructions_stay_small() {
        let op = std::mem::size_of::<super::super::Op>();
        assert!(op <= 48, "{op}");
    }
}

#[cfg(test)]
mod fused_tests {
    use super::super::{Compiler, Op};

    /// The instructions of the body of `name` in `src` (checked by a bare
    /// checker, without the stdlib, and read as the engine reads a
    /// program: not run). The tests of whole runs are in tests/engine.rs.
    fn ops_of(src: &str, name: &str) -> Vec<String> {
        let checked = crate::check::checked_for_tests(src);
        let prog = checked.program();
        let f = prog
            .funcs
            .iter()
            .find(|f| f.name.eq_ignore_ascii_case(name))
            .expect("the function");
        let body = f.body.as_deref().expect("its body");
        let walker_calls = |_| false;
        let own = f.nslots.max(f.params.len() as u32);
        let mut c = Compiler::new(f.level, own, &walker_calls, prog.types);
        c.body(body);
        let code = c.finish(None, true, true);
        code.ops
            .iter()
            .map(|op| match op {
                Op::CallK { .. } => "CallK".to_string(),
                Op::ReturnIntBin(..) => "ReturnIntBin".to_string(),
                Op::Call(..) => "Call".to_string(),
                other => format!("{other:?}"),
            })
            .collect()
    }

    /// `F (N - 1)` and `return X + Y` are one instruction each; an
    /// argument of a constrained subtype (a range check) or a literal
    /// argument is not fused.
    #[test]
    fn a_call_of_x_op_k_and_a_return_of_x_op_y_are_one_instruction() {
        let src = "procedure P is\n\
               function F (N : Integer) return Integer is\n\
               begin\n   if N < 2 then return N; end if;\n   return F (N - 1) + F (N - 2);\nend F;\n\
               function G (N : Natural) return Integer is\n\
               begin\n   if N = 0 then return 0; end if;\n   return G (N - 1) * 2 + F (3);\nend G;\n\
            begin\n   null;\nend P;\n";
        let f = ops_of(src, "F");
        assert_eq!(f.iter().filter(|o| *o == "CallK").count(), 2, "{f:?}");
        assert_eq!(
            f.iter().filter(|o| *o == "ReturnIntBin").count(),
            1,
            "{f:?}"
        );
        assert!(
            !f.iter().any(|o| o == "Call" || o.starts_with("IntBin")),
            "{f:?}"
        );
        // `G (N - 1)` converts to Natural (a range check): a plain call;
        // `... * 2 + F (3)` returns `IntBin` of a temporary and a call.
        let g = ops_of(src, "G");
        assert!(!g.iter().any(|o| o == "CallK"), "{g:?}");
        assert_eq!(g.iter().filter(|o| *o == "Call").count(), 2, "{g:?}");
        assert_eq!(
            g.iter().filter(|o| *o == "ReturnIntBin").count(),
            1,
            "{g:?}"
        );
    }
}

#[cfg(test)]
mod compiled_tests {
    use super::super::{Compiler, Op};

    /// Whether the body of `name` in `src` compiles to instructions only,
    /// none handed to the walker.
    fn walker_ops(src: &str, name: &str) -> Vec<String> {
        let checked = crate::check::checked_for_tests(src);
        let prog = checked.program();
        let f = prog
            .funcs
            .iter()
            .find(|f| f.name.eq_ignore_ascii_case(name))
            .expect("the function");
        let walker_calls = |_| false;
        let own = f.nslots.max(f.params.len() as u32);
        let mut c = Compiler::new(f.level, own, &walker_calls, prog.types);
        c.body(f.body.as_deref().expect("its body"));
        c.finish(None, true, false)
            .ops
            .iter()
            .filter(|op| matches!(op, Op::Eval(..) | Op::Exec(..)))
            .map(|op| format!("{op:?}"))
            .collect()
    }

    /// `abs`, real negation, rounding to an integer, `.all`, Boolean array
    /// operations, array conversions, `T'First`/`T'Last` of a dynamic
    /// subtype, membership tests, a default value, `raise` and `raise;`
    /// each have instructions of their own.
    #[test]
    fn unary_operations_memberships_and_raise_are_compiled() {
        let src = "procedure P is\n\
            type Mask is array (1 .. 4) of Boolean;\n\
            type Vec is array (Positive range <>) of Integer;\n\
            subtype Vec3 is Vec (1 .. 3);\n\
            type Ref is access Integer;\n\
            Jam : exception;\n\
            function F (N : Integer; R : Ref; M : Mask; V : Vec) return Integer is\n\
               subtype W is Integer range N .. N + 4;\n\
               K : Integer := abs N + Integer (-Float (N) * 0.5) + R.all;\n\
               B : Mask := (not M and (M or M)) xor M;\n\
               T : Vec3 := Vec3 (V);\n\
            begin\n\
               if N in W'First .. W'Last | 20 .. 30 or else N not in W then\n\
                  raise Jam with \"jam\";\n\
               end if;\n\
               if B (1) then raise Jam; end if;\n\
               return K + T (1);\n\
            exception\n\
               when Jam => raise;\n\
            end F;\n\
            begin\n   null;\nend P;\n";
        let left = walker_ops(src, "F");
        assert!(left.is_empty(), "{left:#?}");
    }
}
