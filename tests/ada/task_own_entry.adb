--  Inside task B's body, B.E names B's own entry E (not an expanded name
--  of the body): a conditional call of it is not taken (B is not accepting).
with Ada.Text_IO; use Ada.Text_IO;
procedure Task_Own_Entry is
   task B is
      entry E;
      entry F;
   end B;
   task body B is
   begin
      select
         B.E;
      else
         Put_Line ("own entry not open");
      end select;
      accept F;
      Put_Line ("F accepted");
   end B;
begin
   B.F;
end Task_Own_Entry;
