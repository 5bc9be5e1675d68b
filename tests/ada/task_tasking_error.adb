with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;

--  Tasking_Error: a call (plain, conditional or timed) to a task that has
--  ended; a call queued on a task that ends without accepting it; a task
--  ended by an unhandled exception (silently: it is just terminated); a
--  task that fails in its activation.
procedure Task_Tasking_Error is
   task Short is
      entry First;
      entry Second;
   end Short;
   task body Short is
   begin
      accept First;
   end Short;

   task Crasher is
      entry Go (Divisor : Integer);
      entry After;
   end Crasher;
   task body Crasher is
      D : Integer := 0;
      X : Integer := 0;
   begin
      accept Go (Divisor : Integer) do
         D := Divisor;
      end Go;
      X := 100 / D;                 --  Constraint_Error ends the task
      accept After;
      Put_Line ("Crasher: not reached (wrong)" & Integer'Image (X));
   end Crasher;

   Zero : Integer := 0;

   procedure Try (What : String; Which : Integer) is
   begin
      case Which is
         when 1 => Short.Second;
         when 2 =>
            select
               Short.Second;
               Put_Line ("  conditional call accepted (wrong)");
            else
               Put_Line ("  else taken (wrong)");
            end select;
         when 3 =>
            select
               Short.First;
               Put_Line ("  timed call accepted (wrong)");
            or
               delay 0.01;
               Put_Line ("  timed out (wrong)");
            end select;
         when others => Crasher.After;
      end case;
      Put_Line (What & ": no exception (wrong)");
   exception
      when E : Tasking_Error =>
         Put_Line (What & ": " & Exception_Name (E));
   end Try;

begin
   Short.First;
   --  Short is ending or has ended: a call to Second can never be accepted.
   Try ("call to an ending task", 1);
   while not Short'Terminated loop     --  completed; terminated very soon
      delay 0.001;
   end loop;
   Put_Line ("Short terminated: " & Boolean'Image (Short'Terminated));
   Try ("conditional call to a terminated task", 2);
   Try ("timed call to a terminated task", 3);

   Crasher.Go (0);
   while not Crasher'Terminated loop
      delay 0.001;
   end loop;
   Put_Line ("Crasher terminated: " & Boolean'Image (Crasher'Terminated)
             & ", callable: " & Boolean'Image (Crasher'Callable));
   Try ("call to a task ended by an exception", 4);

   --  Activation failure: the task's declarations raise Constraint_Error;
   --  the master gets Tasking_Error when it activates the task.
   begin
      declare
         task Fragile;
         task body Fragile is
            P : Positive := Zero;
         begin
            Put_Line ("Fragile: not reached (wrong)" & Integer'Image (P));
         end Fragile;
      begin
         Put_Line ("block body: not reached (wrong)");
      end;
   exception
      when E : others =>
         Put_Line ("activation failure: " & Exception_Name (E));
   end;

   declare
      task type Fragile_Type;
      task body Fragile_Type is
         P : Positive := Zero;
      begin
         Put_Line ("Fragile_Type: not reached (wrong)" & Integer'Image (P));
      end Fragile_Type;
      type Fragile_Ref is access Fragile_Type;
      R : Fragile_Ref;
   begin
      R := new Fragile_Type;
      Put_Line ("after allocator: not reached (wrong)");
   exception
      when E : others =>
         Put_Line ("allocator activation failure: " & Exception_Name (E)
                   & ", R is null: " & Boolean'Image (R = null));
   end;
   Put_Line ("done");
end Task_Tasking_Error;
