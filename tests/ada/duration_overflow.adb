with Ada.Text_IO; use Ada.Text_IO;

--  Duration is GNAT's 64-bit fixed point: a value past Duration'Last is
--  Constraint_Error (an overflow check), not a saturated value.
procedure Duration_Overflow is
   D : Duration := 1.0;
begin
   for I in 1 .. 12 loop
      D := D * 10;
      Put_Line (Duration'Image (D));
   end loop;
exception
   when Constraint_Error =>
      Put_Line ("Constraint_Error after" & Duration'Image (D));
end Duration_Overflow;
