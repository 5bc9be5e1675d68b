with Ada.Text_IO; use Ada.Text_IO;
with Ada.Float_Text_IO; use Ada.Float_Text_IO;

procedure Derived_Types is
   type Meters is new Float;
   type Count is new Integer range 0 .. 1000;
   type Index is range 1 .. 50;
   type Real is digits 6;
   type Ratio is digits 6 range 0.0 .. 1.0;
   type Angle is new Integer;
   Gain : constant := 2.5;
   Scale : constant := 1_000;
   Half : constant := Scale / 2;
   Tau : constant := 6.283_185_3;
   D : Meters := 12.5;
   C : Count := 10;
   I : Index := 1;
   R : Real := 0.25;
   Q : Ratio := 0.5;
   A : Angle := -90;
   function Id (X : Count) return Count is
   begin
      return X;
   end Id;
begin
   D := D * Meters (Gain);
   Put_Line ("D =" & Meters'Image (D));
   D := D + 0.5;
   Put ("D = ");
   Put (Float (D), 1, 2, 0);
   New_Line;
   C := C * 3 + 1;
   Put_Line ("C =" & Count'Image (C) & " Count'First =" & Count'Image (Count'First) & " Count'Last =" & Count'Image (Count'Last));
   Put_Line ("Integer (C) + 5 =" & Integer'Image (Integer (C) + 5));
   I := Index'Last - I;
   Put_Line ("I =" & Index'Image (I) & " Index'Last =" & Index'Image (Index'Last));
   R := R * Real (Gain) + 1.0;
   Put_Line ("R =" & Real'Image (R));
   Q := Q / 4.0;
   Put_Line ("Q =" & Ratio'Image (Q));
   A := A * 2 + 30;
   Put_Line ("A =" & Angle'Image (A) & " abs A =" & Angle'Image (abs A));
   Put_Line ("Gain * 2.0 =" & Float'Image (Gain * 2.0));
   Put_Line ("Scale + 1 =" & Integer'Image (Scale + 1) & " Half =" & Integer'Image (Half));
   Put_Line ("Tau =" & Float'Image (Tau));
   Put_Line ("Gain as Meters =" & Meters'Image (Gain));
   Put_Line ("Count (Half / 10) =" & Count'Image (Count (Half / 10)));
   begin
      C := Id (999) + Id (2);
      Put_Line ("not reached" & Count'Image (C));
   exception
      when Constraint_Error =>
         Put_Line ("Count overflow raised Constraint_Error, C =" & Count'Image (C));
   end;
   begin
      Q := Ratio (Float (Q) * 10.0);
      Put_Line ("not reached");
   exception
      when Constraint_Error =>
         Put_Line ("Ratio out of range raised Constraint_Error");
   end;
   for K in Index range 1 .. 3 loop
      Put (Index'Image (K));
   end loop;
   New_Line;
end Derived_Types;
