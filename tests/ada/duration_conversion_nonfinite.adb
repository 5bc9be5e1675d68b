--  RM 4.6(28), 3.5.9: a fixed point type holds neither NaN nor an
--  infinity, so converting one to Duration raises Constraint_Error (a
--  robot program that computes a motion time in Float and passes
--  Time => Duration (T)).
with Ada.Text_IO; use Ada.Text_IO;
with Ada.Numerics.Elementary_Functions; use Ada.Numerics.Elementary_Functions;
procedure Duration_Conversion_Nonfinite is
   X : Float := Exp (1000.0);
   Y : Float := X - X;
   T : Duration;
begin
   Put_Line (Boolean'Image (X > Float'Last));
   begin
      T := Duration (X);
      Put_Line ("inf converted" & Duration'Image (T));
   exception
      when Constraint_Error => Put_Line ("inf: CONSTRAINT_ERROR");
   end;
   begin
      T := Duration (Y);
      Put_Line ("nan converted" & Duration'Image (T));
   exception
      when Constraint_Error => Put_Line ("nan: CONSTRAINT_ERROR");
   end;
end Duration_Conversion_Nonfinite;
