with Ada.Text_IO; use Ada.Text_IO;

--  Masters: a block, a subprogram and the main program wait for the tasks
--  they declare before they are left, so the line after each block is
--  printed only when its tasks are done. Task activation happens at the
--  `begin` of the declaring body.
procedure Task_Master_Wait is
   task type Worker is
      entry Start (Name : Character; Steps : Integer);
   end Worker;

   task body Worker is
      N : Integer;
      C : Character;
   begin
      accept Start (Name : Character; Steps : Integer) do
         C := Name;
         N := Steps;
      end Start;
      for I in 1 .. N loop
         delay 0.005;
      end loop;
      Put_Line ("worker " & C & " finished" & Integer'Image (N) & " steps");
   end Worker;

   procedure Run_One is
      W : Worker;
   begin
      W.Start ('P', 3);
      --  returning waits for W
   end Run_One;

   Started : Boolean := False;

   task Finisher is
      entry Go;
   end Finisher;
   task body Finisher is
   begin
      accept Go;
      delay 0.02;
      Put_Line ("Finisher: done after the main program's last statement");
   end Finisher;
begin
   Put_Line ("main: before the block");
   declare
      T : Worker;
   begin
      T.Start ('A', 4);
   end;
   Put_Line ("main: after the block");
   Run_One;
   Put_Line ("main: after Run_One");
   declare
      task Activated;
      task body Activated is
      begin
         Started := True;
      end Activated;
   begin
      null;
   end;
   Put_Line ("main: Activated ran: " & Boolean'Image (Started));
   Put_Line ("main: end");
   Finisher.Go;
   --  The main program's own master waits for Finisher here.
end Task_Master_Wait;
