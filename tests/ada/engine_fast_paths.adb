--  The compiled engine's inline paths (issue 32's speed work): integer
--  `*`, `mod` and `rem` done inline with their overflow and sign rules,
--  every comparison on integers, reals and enumerations, the four plain
--  Float operations, elements of Float, Integer, Character and Boolean
--  arrays read and written (one and two indices, index checks), record
--  aggregates with and without discriminants, calls of `F (N - 1)`.
with Ada.Text_IO; use Ada.Text_IO;

procedure Engine_Fast_Paths is
   type Color is (Red, Green, Blue);
   type Grid is array (1 .. 3, 0 .. 2) of Float;
   type Ints is array (-2 .. 2) of Integer;
   type Flags is array (1 .. 4) of Boolean;
   type Pair is record
      A : Integer;
      B : Float;
   end record;
   type Shape (N : Natural) is record
      V : Ints;
      S : String (1 .. N);
   end record;

   function Fib (N : Integer) return Integer is
   begin
      if N < 2 then
         return N;
      end if;
      return Fib (N - 1) + Fib (N - 2);
   end Fib;

   function Down (N : Integer) return Integer is
   begin
      if N <= Integer'First + 1 then
         return N;
      end if;
      return Down (N - 1);
   end Down;

   procedure Cmp (X, Y : Integer) is
   begin
      Put_Line (Integer'Image (X) & Integer'Image (Y) & " "
                & Boolean'Image (X = Y) & Boolean'Image (X /= Y)
                & Boolean'Image (X < Y) & Boolean'Image (X <= Y)
                & Boolean'Image (X > Y) & Boolean'Image (X >= Y));
   end Cmp;

   procedure Cmp_F (X, Y : Float) is
   begin
      Put_Line (Boolean'Image (X = Y) & Boolean'Image (X /= Y)
                & Boolean'Image (X < Y) & Boolean'Image (X <= Y)
                & Boolean'Image (X > Y) & Boolean'Image (X >= Y));
   end Cmp_F;

   procedure Cmp_C (X, Y : Color) is
   begin
      Put_Line (Boolean'Image (X < Y) & Boolean'Image (X <= Y)
                & Boolean'Image (X > Y) & Boolean'Image (X >= Y));
   end Cmp_C;

   procedure Div (A, B : Integer) is
   begin
      Put_Line (Integer'Image (A) & Integer'Image (B) & " mod" & Integer'Image (A mod B)
                & " rem" & Integer'Image (A rem B) & " *" & Integer'Image (A * B));
   exception
      when Constraint_Error =>
         Put_Line (Integer'Image (A) & Integer'Image (B) & " Constraint_Error");
   end Div;

   G : Grid := (others => (others => 0.0));
   V : Ints := (others => 0);
   F : Flags := (others => False);
   S : String := "abcde";
   P : Pair;
   Q : Shape (3);
   K : Integer := 5;
   Big : Integer := 46_341;
   X, Y : Float;
   I : Integer;
begin
   Cmp (1, 2);
   Cmp (2, 2);
   Cmp (3, 2);
   Cmp (-5, 5);
   Cmp_F (1.5, 2.5);
   Cmp_F (2.5, 2.5);
   Cmp_F (-0.0, 0.0);
   Cmp_C (Red, Blue);
   Cmp_C (Green, Green);
   Cmp_C (Blue, Green);
   Div (7, 3);
   Div (-7, 3);
   Div (7, -3);
   Div (-7, -3);
   Div (0, 4);
   Div (13, 13);
   Div (-13, 13);
   Div (Big, Big - 1);
   Div (Big, Big);
   Div (-Big, Big);
   Div (Integer'Last, 1);
   Div (Integer'First, 1);
   Div (Integer'First, -1);
   Div (5, 0);
   begin
      K := Integer'Last;
      K := K * 2;
      Put_Line ("no overflow");
   exception
      when Constraint_Error =>
         Put_Line ("overflow caught");
   end;
   X := 1.5;
   Y := 0.25;
   Put_Line (Float'Image (X + Y) & Float'Image (X - Y) & Float'Image (X * Y)
             & Float'Image (X / Y) & Float'Image (Y - X));
   for R in 1 .. 3 loop
      for C in 0 .. 2 loop
         G (R, C) := G (R, C) + Float (R) * 10.0 + Float (C);
      end loop;
   end loop;
   Put_Line (Float'Image (G (1, 0)) & Float'Image (G (2, 1)) & Float'Image (G (3, 2)));
   for J in V'Range loop
      V (J) := J * J - 1;
   end loop;
   Put_Line (Integer'Image (V (-2)) & Integer'Image (V (0)) & Integer'Image (V (2)));
   F (2) := True;
   F (4) := F (2) and not F (1);
   Put_Line (Boolean'Image (F (1)) & Boolean'Image (F (2)) & Boolean'Image (F (4)));
   S (2) := 'X';
   S (5) := S (1);
   Put_Line (S & Character'Image (S (2)));
   I := 4;
   begin
      G (I, 0) := 1.0;
      Put_Line ("no index check");
   exception
      when Constraint_Error =>
         Put_Line ("index check on a store");
   end;
   begin
      X := G (1, I);
      Put_Line ("no index check");
   exception
      when Constraint_Error =>
         Put_Line ("index check on a load");
   end;
   begin
      I := V (I - 1);
      Put_Line ("no index check");
   exception
      when Constraint_Error =>
         Put_Line ("index check on a vector");
   end;
   P := (A => 3, B => 0.5);
   Put_Line (Integer'Image (P.A) & Float'Image (P.B));
   Q := (N => 3, V => V, S => "xyz");
   Put_Line (Integer'Image (Q.N) & Integer'Image (Q.V (1)) & " " & Q.S);
   begin
      Q := (N => 3, V => V, S => S (1 .. 3));
      Put_Line (Q.S);
   exception
      when Constraint_Error =>
         Put_Line ("discriminant check");
   end;
   Put_Line (Integer'Image (Fib (20)));
   Put_Line (Integer'Image (Down (Integer'First + 5)));
end Engine_Fast_Paths;
