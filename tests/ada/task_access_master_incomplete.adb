with Ada.Text_IO; use Ada.Text_IO;
--  An access type declared before its designated type is completed with a
--  task component is a master too: the block waits for the task.
procedure Task_Access_Master_Incomplete is
   task type W;
   task body W is begin delay 0.2; Put_Line ("W done"); end W;
begin
   declare
      type R;
      type Local is access R;
      type R is record
         T : W;
      end record;
      L : Local := new R;
   begin
      null;
   end;
   Put_Line ("block left");
end Task_Access_Master_Incomplete;
