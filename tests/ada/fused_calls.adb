with Ada.Text_IO; use Ada.Text_IO;

--  Calls whose one argument is `X op K`, and returns of `X op Y`: the
--  compiled engine runs each as one instruction.
procedure Fused_Calls is
   Total : Integer := 0;
   Big_Value : Integer := Integer'Last;
   Zero : Integer := 0;

   function Fib (N : Integer) return Integer is
   begin
      if N < 2 then
         return N;
      end if;
      return Fib (N - 1) + Fib (N - 2);
   end Fib;

   procedure Count (N : Integer) is
   begin
      Total := Total + N;
      if N > 0 then
         Count (N - 1);
      end if;
   end Count;

   --  A nested function puts a call's result into its parent's variable
   --  and calls a function of the outer level.
   function Outer (N : Integer) return Integer is
      R : Integer := 0;
      function Inner (M : Integer) return Integer is
      begin
         R := Fib (M + 2);
         return R * 2;
      end Inner;
   begin
      return Inner (N - 1) + R;
   end Outer;

   function Twice (N : Integer) return Integer is
   begin
      return N * 2;
   end Twice;

   function Mul (A, B : Integer) return Integer is
   begin
      return A * B;
   end Mul;

   function Div (A, B : Integer) return Integer is
   begin
      return A / B;
   end Div;

   function Modulo (A, B : Integer) return Integer is
   begin
      return A mod B;
   end Modulo;

   function Next (N : Integer) return Integer is
   begin
      return Twice (N + 1);
   end Next;

   function Id (N : Natural) return Integer is
   begin
      return N;
   end Id;

   function Sum_Down (N : Integer) return Integer is
   begin
      if N = 0 then
         return 0;
      end if;
      return N + Sum_Down (N - 1);
   end Sum_Down;

   Three : Integer := 3;
begin
   Put_Line (Integer'Image (Fib (20)));
   Count (10);
   Put_Line (Integer'Image (Total));
   Put_Line (Integer'Image (Outer (5)));
   Put_Line (Integer'Image (Next (20)));
   Put_Line (Integer'Image (Sum_Down (100)));
   Put_Line (Integer'Image (Modulo (-7, 3)) & Integer'Image (Mul (-4, 5)));
   begin
      Put_Line (Integer'Image (Twice (Big_Value + 1)));
   exception
      when Constraint_Error =>
         Put_Line ("overflow in an argument");
   end;
   begin
      Put_Line (Integer'Image (Next (Big_Value / 2)));
   exception
      when Constraint_Error =>
         Put_Line ("overflow in a callee");
   end;
   begin
      Put_Line (Integer'Image (Mul (Big_Value, 2)));
   exception
      when Constraint_Error =>
         Put_Line ("overflow in a return");
   end;
   begin
      Put_Line (Integer'Image (Div (1, Zero)));
   exception
      when Constraint_Error =>
         Put_Line ("division by zero in a return");
   end;
   begin
      Put_Line (Integer'Image (Id (Three - 5)));
   exception
      when Constraint_Error =>
         Put_Line ("range check of an argument");
   end;
   Put_Line (Integer'Image (Twice (Big_Value - 1)));
end Fused_Calls;
