--  Float division by zero and overflow follow IEEE as in GNAT
--  (Float'Machine_Overflows is False): infinities and NaN, printed by
--  'Image and Float_Text_IO.Put as GNAT prints them; converting one to
--  Integer raises Constraint_Error.
with Ada.Text_IO; use Ada.Text_IO;
with Ada.Float_Text_IO; use Ada.Float_Text_IO;
procedure Float_Ieee is
   Zero : Float := 0.0;
   X    : Float;
   N    : Integer;
begin
   X := 1.0 / Zero;
   Put_Line (Float'Image (X));
   Put_Line (Float'Image (-X));
   Put_Line (Float'Image (Zero / Zero));
   Put (X); New_Line;
   Put (-X, 3, 2, 0); New_Line;
   Put (Zero / Zero); New_Line;
   Put (X, Fore => 1, Aft => 1, Exp => 2); New_Line;
   if X > 1.0E30 and then -X < -1.0E30 then
      Put_Line ("ordered");
   end if;
   begin
      N := Integer (X);
      Put_Line (Integer'Image (N));
   exception
      when Constraint_Error => Put_Line ("Integer of +Inf: Constraint_Error");
   end;
end Float_Ieee;
