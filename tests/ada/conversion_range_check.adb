--  A conversion to an integer type of a value of another integer type
--  checks the target's range (RM 4.6(28)): it used to pass 20 into a
--  type of 1 .. 10 unchecked.
with Ada.Text_IO; use Ada.Text_IO;
procedure Conversion_Range_Check is
   type Speed is range 1 .. 10;
   subtype Slow is Speed range 1 .. 3;
   I : Integer := 20;
   S : Speed;
begin
   begin
      S := Speed (I);
      Put_Line ("converted" & Speed'Image (S));
   exception
      when Constraint_Error => Put_Line ("Speed (20) raised Constraint_Error");
   end;
   I := 7;
   S := Speed (I);
   Put_Line ("Speed (7) =" & Speed'Image (S));
   begin
      Put_Line ("slow" & Slow'Image (Slow (S)));
   exception
      when Constraint_Error => Put_Line ("Slow (7) raised Constraint_Error");
   end;
   Put_Line ("back" & Integer'Image (Integer (S) * 1000));
end Conversion_Range_Check;
