--  A `digits N` type's 'Image shows N significant digits, 'Digits is N,
--  and 'Last is that of GNAT's representation (single precision up to 6
--  digits).
with Ada.Text_IO; use Ada.Text_IO;
procedure Float_Digits_Types is
   type R3 is digits 3;
   type R6 is digits 6;
   type R9 is digits 9 range -1.0 .. 1.0E6;
   type R12 is digits 12;
   A : R3 := 3.14159;
   B : R9 := 2.0 / 3.0;
   C : R12 := 123.456789;
begin
   Put_Line (R3'Image (A));
   Put_Line (R9'Image (B));
   Put_Line (R12'Image (C));
   Put_Line (A'Image & B'Image);
   Put_Line (Integer'Image (R3'Digits) & Integer'Image (R12'Digits) & Integer'Image (Float'Digits));
   Put_Line (R6'Image (R6'Last));
   Put_Line (R9'Image (R9'Last));
end Float_Digits_Types;
