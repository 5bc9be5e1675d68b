with Ada.Text_IO; use Ada.Text_IO;
procedure Modular_Conversion_Universal is
   type Ring is mod 10;
   type Small is range 0 .. 99;
   S : String (1 .. 4) := "a" & Character'Val (5) & "cd";
   N : Ring;
   M : Small;
begin
   N := Ring (Character'Pos (S (2)));
   Put_Line (Ring'Image (N));
   M := Small (Character'Pos (S (1)));
   Put_Line (Small'Image (M));
   begin
      N := Ring (Character'Pos (S (3)));
      Put_Line ("not raised" & Ring'Image (N));
   exception
      when Constraint_Error => Put_Line ("Ring: Constraint_Error");
   end;
   begin
      M := Small (Character'Pos (S (4)) + 1);
      Put_Line ("not raised" & Small'Image (M));
   exception
      when Constraint_Error => Put_Line ("Small: Constraint_Error");
   end;
end Modular_Conversion_Universal;
