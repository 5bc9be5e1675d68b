--  'Succ and 'Pred work on the base type: past its bounds they fail
--  GNAT's overflow check; within it a subtype's bound is no limit.
with Ada.Text_IO; use Ada.Text_IO;
procedure Succ_Overflow is
   type Day is (Mon, Tue, Sun);
   subtype Small is Integer range 1 .. 10;
   D : Day := Day'Value ("sun");
   I : Integer := Integer'Value ("2147483647");
   S : Small := Small'Value ("10");
   J : Integer;
begin
   J := Small'Succ (S);
   Put_Line (Integer'Image (J));
   begin
      S := Small'Succ (S);
   exception
      when Constraint_Error => Put_Line ("Small'Succ (10) into Small: Constraint_Error");
   end;
   begin
      I := Integer'Succ (I);
   exception
      when Constraint_Error => Put_Line ("Integer'Succ (Integer'Last): Constraint_Error");
   end;
   Put_Line (Day'Image (Day'Pred (D)));
   D := Day'Succ (D);
end Succ_Overflow;
