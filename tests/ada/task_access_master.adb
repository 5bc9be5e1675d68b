with Ada.Text_IO; use Ada.Text_IO;

--  The master of a task made by an allocator is the region that declares
--  the access type (RM 9.3(2)): a block that declares the type waits for
--  the task at its end; a block that only runs the allocator of an outer
--  access type does not, even when it is a master of its own tasks.
procedure Task_Access_Master is
   task type W;
   task body W is
   begin
      delay 0.2;
      Put_Line ("W done");
   end W;
   type Outer is access W;
   task type V;
   task body V is
   begin
      delay 0.1;
      Put_Line ("V done");
   end V;
   P : Outer;
begin
   declare
      type Local is access W;
      L : Local := new W;
   begin
      null;
   end;
   Put_Line ("block with its own access type left");
   declare
      Y : V;
   begin
      P := new W;
   end;
   Put_Line ("block with an outer access type left");
   if not P'Terminated then
      Put_Line ("P's task still runs");
   end if;
end Task_Access_Master;
