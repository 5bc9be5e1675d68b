with Ada.Text_IO; use Ada.Text_IO;

procedure Param_Modes is
   type Pair is record
      A, B : Integer;
   end record;
   Global : Integer := 10;
   X, Y : Integer;
   P : Pair := (1, 2);

   procedure Swap (L, R : in out Integer) is
      T : constant Integer := L;
   begin
      L := R;
      R := T;
   end Swap;

   procedure Divide (N, D : in Integer; Q, R : out Integer) is
   begin
      Q := N / D;
      R := N rem D;
   end Divide;

   procedure Increment (V : in out Integer; By : Integer := 1) is
   begin
      V := V + By;
   end Increment;

   procedure Swap_Pair (Q : in out Pair) is
   begin
      Swap (Q.A, Q.B);
   end Swap_Pair;

   procedure Bump_Global_And (V : in out Integer) is
   begin
      V := V + 100;
      Put_Line ("  inside: V =" & Integer'Image (V) & " Global =" & Integer'Image (Global));
   end Bump_Global_And;

   procedure Fail_After_Write (V : in out Integer) is
   begin
      V := -999;
      raise Constraint_Error;
   end Fail_After_Write;

   procedure Init (V : out Pair) is
   begin
      V.A := 7;
      V.B := V.A * 2;
   end Init;
begin
   X := 3;
   Y := 4;
   Swap (X, Y);
   Put_Line ("after Swap: X =" & Integer'Image (X) & " Y =" & Integer'Image (Y));
   Divide (17, 5, X, Y);
   Put_Line ("17 / 5: Q =" & Integer'Image (X) & " R =" & Integer'Image (Y));
   Divide (D => 4, N => -17, Q => X, R => Y);
   Put_Line ("-17 / 4: Q =" & Integer'Image (X) & " R =" & Integer'Image (Y));
   Increment (X);
   Increment (Y, 10);
   Increment (By => -5, V => Global);
   Put_Line ("X =" & Integer'Image (X) & " Y =" & Integer'Image (Y) & " Global =" & Integer'Image (Global));
   Swap_Pair (P);
   Put_Line ("P =" & Integer'Image (P.A) & Integer'Image (P.B));
   Swap (P.A, P.B);
   Put_Line ("P =" & Integer'Image (P.A) & Integer'Image (P.B));
   Bump_Global_And (Global);
   Put_Line ("after: Global =" & Integer'Image (Global));
   X := 42;
   begin
      Fail_After_Write (X);
   exception
      when Constraint_Error =>
         Put_Line ("after failed call X =" & Integer'Image (X));
   end;
   Init (P);
   Put_Line ("Init: P =" & Integer'Image (P.A) & Integer'Image (P.B));
end Param_Modes;
