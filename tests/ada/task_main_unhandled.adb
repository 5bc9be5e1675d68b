with Ada.Text_IO; use Ada.Text_IO;

--  An exception that leaves the main program while a task is still
--  running: the main program's master first waits for the task (which
--  finishes its work and prints), then the run ends with exit status 1.
--  Standard error (the exception report) is not compared.
procedure Task_Main_Unhandled is
   Emergency_Stop : exception;

   task Conveyor is
      entry Start (Parts : Integer);
   end Conveyor;

   task body Conveyor is
      N : Integer;
   begin
      accept Start (Parts : Integer) do
         N := Parts;
         Put_Line ("Conveyor: moving" & Integer'Image (N) & " parts");
      end Start;
      for I in 1 .. N loop
         delay 0.01;
         Put_Line ("Conveyor: part" & Integer'Image (I) & " delivered");
      end loop;
      Put_Line ("Conveyor: stopped");
   end Conveyor;
begin
   Put_Line ("Main: starting the conveyor");
   Conveyor.Start (3);
   raise Emergency_Stop with "operator pressed the button";
end Task_Main_Unhandled;
