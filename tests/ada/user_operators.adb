with Ada.Text_IO; use Ada.Text_IO;
procedure User_Operators is
   type Vec is record
      X, Y : Integer;
   end record;
   function "-" (V : Vec) return Vec is
   begin
      return (X => -V.X, Y => -V.Y);
   end "-";
   function "abs" (V : Vec) return Integer is
   begin
      return abs V.X + abs V.Y;
   end "abs";
   function "+" (A, B : Vec) return Vec is
   begin
      return (X => A.X + B.X, Y => A.Y + B.Y);
   end "+";
   function "=" (A, B : Vec) return Boolean is
   begin
      return A.X + A.Y = B.X + B.Y;
   end "=";
   P : Vec := (1, -2);
   Q : Vec := (3, 4);
   R : Vec;
begin
   R := -P;
   Put_Line (Integer'Image (R.X) & Integer'Image (R.Y));
   Put_Line (Integer'Image (abs P));
   R := "+" (P, Q);
   Put_Line (Integer'Image (R.X) & Integer'Image (R.Y));
   Put_Line (Integer'Image ("abs" (Q)));
   if P /= Q then
      Put_Line ("P /= Q");
   end if;
   if Vec'(2, 0) = Vec'(0, 2) then
      Put_Line ("equal by sum");
   end if;
   if not (Vec'(2, 0) /= Vec'(1, 1)) then
      Put_Line ("derived /= uses user =");
   end if;
end User_Operators;
