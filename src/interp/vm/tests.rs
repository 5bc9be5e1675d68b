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
        let native_calls = |_| false;
        let own = f.nslots.max(f.params.len() as u32);
        let mut c = Compiler::new(f.level, own, &native_calls, prog.types);
        c.body(body);
        let code = c.finish(None, true, true);
        code.ops
            .iter()
            .map(|op| match op {
                Op::CallK { .. } => "CallK".to_string(),
                Op::ReturnIntBin { .. } => "ReturnIntBin".to_string(),
                Op::Call { .. } => "Call".to_string(),
                other => format!("{other:?}"),
            })
            .collect()
    }

    /// An aggregate of literals with static bounds is made once per run
    /// (`Cached`); one whose component subtype depends on a parameter, or
    /// with a component that is not a literal, is made each time.
    #[test]
    fn static_aggregates_are_made_once() {
        let src = "procedure P is\n\
               type Mat is array (1 .. 2, 1 .. 3) of Float;\n\
               function F return Mat is\n\
                  M : Mat := (others => (others => 0.5));\n\
               begin\n   return M;\nend F;\n\
               procedure G (N : Integer) is\n\
                  subtype Small is Integer range 1 .. N;\n\
                  type Smalls is array (1 .. 3) of Small;\n\
                  S : Smalls := (5, 5, 5);\n\
               begin\n   null;\nend G;\n\
               procedure H (N : Integer) is\n\
                  type Row is array (1 .. 3) of Integer;\n\
                  R : Row := (1, N, 3);\n\
               begin\n   null;\nend H;\n\
               procedure K is\n\
                  type Row is array (1 .. 3) of Integer;\n\
                  subtype Digit is Integer range 0 .. 9;\n\
                  type Digit_Row is array (1 .. 3) of Digit;\n\
                  R : Row := (1, 2, 3);\n\
                  D : Digit_Row := (others => 7);\n\
               begin\n   null;\nend K;\n\
            begin\n   null;\nend P;\n";
        let cached = |name| {
            ops_of(src, name)
                .iter()
                .filter(|o| o.starts_with("Cached"))
                .count()
        };
        assert_eq!(cached("F"), 1, "{:?}", ops_of(src, "F"));
        assert_eq!(cached("G"), 0, "{:?}", ops_of(src, "G"));
        assert_eq!(cached("H"), 0, "{:?}", ops_of(src, "H"));
        assert_eq!(cached("K"), 2, "{:?}", ops_of(src, "K"));
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
    use super::super::Compiler;

    /// The instructions of the body of `name` in `src` that carry a
    /// checked tree (an expression or statement inside the instruction).
    fn tree_ops(src: &str, name: &str) -> Vec<String> {
        let checked = crate::check::checked_for_tests(src);
        let prog = checked.program();
        let f = prog
            .funcs
            .iter()
            .find(|f| f.name.eq_ignore_ascii_case(name))
            .expect("the function");
        // `Get_Line` is called as the engine calls natives.
        let natives = |g: crate::check::ir::FuncId| prog.funcs[g as usize].name == "Get_Line";
        let own = f.nslots.max(f.params.len() as u32);
        let mut c = Compiler::new(f.level, own, &natives, prog.types);
        c.body(f.body.as_deref().expect("its body"));
        c.finish(None, true, false)
            .ops
            .iter()
            .map(|op| format!("{op:?}"))
            .filter(|op| op.contains("Ex {") || op.contains("Stmt {"))
            .collect()
    }

    /// Aggregates (positional, named, `others`, ranges whose value has a
    /// call, two-dimensional, records with discriminants and a
    /// discriminant-dependent string) and allocators (with an initial
    /// value, of a record, of tasks inside an aggregate) have instructions
    /// of their own.
    #[test]
    fn aggregates_and_allocators_are_compiled() {
        let src = "procedure P is\n\
            type Vec is array (Positive range <>) of Integer;\n\
            type Grid is array (1 .. 2, 1 .. 3) of Integer;\n\
            type Tag (Len : Natural := 4) is record\n\
               Name : String (1 .. Len);\n\
               Id : Integer := 0;\n\
            end record;\n\
            type Tag_Ref is access Tag;\n\
            type Int_Ref is access Integer;\n\
            task type Axis;\n\
            type Axis_Ref is access Axis;\n\
            type Pair is array (1 .. 2) of Axis_Ref;\n\
            task body Axis is begin null; end Axis;\n\
            Count : Integer := 0;\n\
            function Next return Integer is begin Count := Count + 1; return Count; end Next;\n\
            function F (N : Integer) return Integer is\n\
               A : Vec (1 .. 5) := (1, 2, others => N);\n\
               B : Vec (1 .. 6) := (1 .. 2 => Next, 4 => N, others => Next);\n\
               G : Grid := ((1, 2, 3), (others => N));\n\
               T : Tag := (Len => 3, Name => \"abc\", Id => N);\n\
               R : Tag_Ref := new Tag'(T);\n\
               I : Int_Ref := new Integer'(N + 1);\n\
               S : Pair := (new Axis, new Axis);\n\
            begin\n\
               return A (3) + B (6) + G (2, 1) + R.Id + I.all;\n\
            end F;\n\
            begin\n   null;\nend P;\n";
        let left = tree_ops(src, "F");
        assert!(left.is_empty(), "{left:#?}");
        // The test sees a tree inside an instruction by its printed form.
        let checked = crate::check::checked_for_tests(src);
        let e = checked.program().funcs.iter().find_map(|f| {
            match &f.body.as_deref()?.stmts.first()?.kind {
                crate::check::ir::StmtKind::Init(_, e) => Some(format!("{e:?}")),
                _ => None,
            }
        });
        assert!(e.is_some_and(|e| e.contains("Ex {")));
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
        let left = tree_ops(src, "F");
        assert!(left.is_empty(), "{left:#?}");
    }

    /// The `out` and `in out` values of a call (of a subprogram with a
    /// body, a function, a native, a task's entry) are stored into their actuals by
    /// instructions: a variable, a component, an element, a slice, through
    /// an access value.
    #[test]
    fn out_parameters_and_natives_are_compiled() {
        let src = "procedure P is\n\
            procedure Get_Line (S : out String; Last : out Natural) is\n\
            begin Last := 0; end Get_Line;\n\
            type Arr is array (1 .. 4) of Integer;\n\
            type Rec is record S : String (1 .. 4); N : Integer; A : Arr; end record;\n\
            type Ref is access Rec;\n\
            procedure Bump (X : in out Integer) is begin X := X + 1; end Bump;\n\
            procedure Fill (S : out String) is begin for I in S'Range loop S (I) := 'x'; end loop; end Fill;\n\
            function Take (X : in out Integer) return Integer is begin X := 0; return 1; end Take;\n\
            task Server is entry Get (X : out Integer; S : in out String); end Server;\n\
            task body Server is begin\n\
               accept Get (X : out Integer; S : in out String) do X := 1; S (S'First) := 'y'; end Get;\n\
            end Server;\n\
            procedure F (R : in out Rec; Q : Ref) is\n\
               Line : String (1 .. 10);\n\
               Last : Natural;\n\
               K : Integer := 3;\n\
            begin\n\
               Bump (R.N);\n\
               Bump (R.A (K));\n\
               Fill (R.S (2 .. 3));\n\
               Bump (Q.N);\n\
               K := Take (K) + Take (R.A (1));\n\
               Get_Line (Line, Last);\n\
               Server.Get (R.A (2), R.S (1 .. 2));\n\
               Fill (Line (1 .. Last));\n\
            end F;\n\
            begin\n   null;\nend P;\n";
        let left = tree_ops(src, "F");
        assert!(left.is_empty(), "{left:#?}");
    }
}

#[cfg(test)]
mod fast_tests {
    use super::super::{Code, Op, fast};
    use crate::check::ir::{IntOp, Var};
    use crate::interp::stack::Stack;
    use crate::interp::value::{Array, Elems, Value};
    use std::sync::atomic::AtomicBool;

    /// Level-1 code of `ops`.
    fn code(ops: Vec<Op>) -> Code {
        Code {
            func: None,
            all_in: true,
            scalar: true,
            quick: true,
            level: 1,
            ops,
            temps: 0,
            frame: 0,
            regions: Vec::new(),
        }
    }

    /// `fast::run` over slots held in a vector.
    fn run(
        code: &Code,
        pc: usize,
        lvl: u16,
        fp: usize,
        stack: &mut Vec<Value>,
        stop: Option<&AtomicBool>,
    ) -> usize {
        let mut st = Stack::from(std::mem::take(stack));
        let r = fast::run(code, pc, lvl, fp, &mut st, stop.unwrap_or(&fast::NEVER));
        *stack = st.into_vec();
        r
    }

    fn v(slot: u32) -> Var {
        Var { level: 1, slot }
    }

    /// The inner loop (`fast.rs`) runs what it can finish and stops
    /// *before* anything else, with nothing of it done: an operation that
    /// overflows, an operand of another frame, an index out of range, a
    /// loop's step while the user's stop is set. The big loop then
    /// executes that instruction (and raises).
    #[test]
    fn the_inner_loop_stops_before_what_it_cannot_finish() {
        let span = crate::diag::span(0, 0, 0);
        let ops = code(vec![
            Op::Int(v(0), 7),
            Op::IntBinK {
                op: IntOp::Add,
                dst: v(1),
                x: v(0),
                k: 5,
                span,
            },
            Op::IntBinK {
                op: IntOp::Mul,
                dst: v(2),
                x: v(1),
                k: i32::MAX as i64,
                span,
            },
        ]);
        let mut stack = vec![Value::Undef; 4];
        assert_eq!(run(&ops, 0, 1, 0, &mut stack, None), 2);
        assert_eq!(stack[1], Value::Int(12));
        assert_eq!(stack[2], Value::Undef);
        // `mod` of a negative divisor is the big loop's.
        let ops = code(vec![Op::IntBinK {
            op: IntOp::Mod,
            dst: v(2),
            x: v(1),
            k: -5,
            span,
        }]);
        assert_eq!(run(&ops, 0, 1, 0, &mut stack, None), 0);
        let ops = code(vec![Op::IntBinK {
            op: IntOp::Mod,
            dst: v(2),
            x: v(0),
            k: 5,
            span,
        }]);
        assert_eq!(run(&ops, 0, 1, 0, &mut stack, None), 1);
        assert_eq!(stack[2], Value::Int(2));
        // An operand of an enclosing frame.
        let ops = code(vec![Op::Move(v(3), Var { level: 0, slot: 0 })]);
        assert_eq!(run(&ops, 0, 1, 0, &mut stack, None), 0);
        assert_eq!(stack[3], Value::Undef);
        // A frame that begins further up the stack.
        let ops = code(vec![Op::Move(v(1), v(0))]);
        assert_eq!(run(&ops, 0, 1, 2, &mut stack, None), 1);
        assert_eq!(stack[3], Value::Int(2));
        // Elements: in range, then out of range (nothing written).
        let arr = Array::from_elems(1, Elems::Reals(&[0.5, 1.5]));
        stack[3] = Value::Arr(arr);
        stack[0] = Value::Int(2);
        let ops = code(vec![
            Op::Index1 {
                dst: v(2),
                arr: v(3),
                i: v(0),
                span,
            },
            Op::StoreIndex1 {
                arr: v(3),
                i: v(1),
                src: v(2),
                span,
            },
        ]);
        stack[1] = Value::Int(3);
        assert_eq!(run(&ops, 0, 1, 0, &mut stack, None), 1);
        assert_eq!(stack[2], Value::Real(1.5));
        stack[1] = Value::Int(1);
        assert_eq!(run(&ops, 1, 1, 0, &mut stack, None), 2);
        let Value::Arr(a) = &stack[3] else { panic!() };
        assert_eq!(a.data(), Elems::Reals(&[1.5, 1.5]));
        // A loop's step while the user's stop is set.
        let stop = AtomicBool::new(true);
        let ops = code(vec![
            Op::Int(v(0), 1),
            Op::Int(v(1), 3),
            Op::ForNext {
                var: v(0),
                low: v(0),
                high: v(1),
                reverse: false,
                body: 0,
                span,
            },
        ]);
        assert_eq!(run(&ops, 0, 1, 0, &mut stack, Some(&stop)), 2);
        assert_eq!(stack[0], Value::Int(1));
        let go = AtomicBool::new(false);
        let ops = code(vec![
            Op::Int(v(1), 3),
            Op::ForNext {
                var: v(0),
                low: v(0),
                high: v(1),
                reverse: false,
                body: 1,
                span,
            },
        ]);
        stack[0] = Value::Int(1);
        assert_eq!(run(&ops, 0, 1, 0, &mut stack, Some(&go)), 2);
        assert_eq!(stack[0], Value::Int(3));
    }
}
