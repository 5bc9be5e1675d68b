with Ada.Text_IO; use Ada.Text_IO;

--  A task made by an allocator belongs to the master of its access type,
--  even when another task runs the allocator: the block that declares the
--  type waits for it, and so does the main program for its own type.
procedure Task_Access_Master_Other_Thread is
   task type W;
   task body W is
   begin
      delay 0.2;
      Put_Line ("W done");
   end W;
   type Outer is access W;
   task Late;
   task body Late is
      P : Outer;
   begin
      delay 0.5;
      P := new W;
      Put_Line ("Late made a W of the main program's type");
      if P'Callable then
         null;
      end if;
   end Late;
begin
   declare
      type A is access W;
      task Creator;
      task body Creator is
         P : A;
      begin
         delay 0.1;
         P := new W;
         Put_Line ("Creator made a W");
         if P'Callable then
            null;
         end if;
      end Creator;
   begin
      null;
   end;
   Put_Line ("block left");
end Task_Access_Master_Other_Thread;
