with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;

--  RM 9.2(3, 5): a task whose declarative part raises fails its
--  activation; Tasking_Error is raised at the begin of the body or block
--  that activated it, once all of its tasks have been activated, and the
--  activations are part of its handled sequence of statements, so the
--  handler of that same body or block catches it. The other task
--  activated there is unaffected: it runs and the handler can still call
--  it, and the body is left only when it has ended (RM 9.3).
procedure Task_Activation_Failure_Block is
   Bad_Offset : Integer := -1;

   procedure Start_Cell is
      task Conveyor is
         entry Ready (Parts : out Natural);
      end Conveyor;
      task body Conveyor is
      begin
         accept Ready (Parts : out Natural) do
            Put_Line ("Conveyor: running, 12 parts on the belt");
            Parts := 12;
         end Ready;
      end Conveyor;

      task Gripper;
      task body Gripper is
         Opening : Positive := 10 + Bad_Offset * 20;   --  Constraint_Error
      begin
         Put_Line ("Gripper: not reached (wrong)" & Integer'Image (Opening));
      end Gripper;

      N : Natural := 0;
   begin
      Put_Line ("Start_Cell: body reached (wrong)");
   exception
      when E : Tasking_Error =>
         Put_Line ("Start_Cell handler: " & Exception_Name (E));
         Conveyor.Ready (N);
         Put_Line ("Start_Cell handler: conveyor has" & Natural'Image (N)
                   & " parts");
   end Start_Cell;

begin
   Put_Line ("Main: starting the cell");
   Start_Cell;
   Put_Line ("Main: Start_Cell returned normally");

   declare
      task Sensor;
      task body Sensor is
         Level : Natural := Bad_Offset;              --  Constraint_Error
      begin
         Put_Line ("Sensor: not reached (wrong)" & Integer'Image (Level));
      end Sensor;
   begin
      Put_Line ("block: body reached (wrong)");
   exception
      when E : Tasking_Error =>
         Put_Line ("block handler: " & Exception_Name (E));
   end;
   Put_Line ("Main: done");
exception
   when E : others =>
      Put_Line ("Main handler (wrong): " & Exception_Name (E));
end Task_Activation_Failure_Block;
