with Ada.Text_IO; use Ada.Text_IO;

--  One single task with entries of every parameter mode, accepted with and
--  without a body. Only the rendezvous order the entries impose is printed.
procedure Task_Entries_Params is
   task Axis is
      pragma Priority (10);
      entry Reset;
      entry Set (Target : in Integer);
      entry Get (Current : out Integer);
      entry Step (Value : in out Integer; Times : in Integer := 1);
      entry Stop;
   end Axis;

   task body Axis is
      Position : Integer := 0;
      Resets : Integer := 0;
   begin
      accept Reset;                       --  no body, no parameters
      Resets := Resets + 1;
      accept Set (Target : in Integer) do
         Put_Line ("Axis: set to" & Integer'Image (Target));
         Position := Target;
      end Set;
      accept Get (Current : out Integer) do
         Current := Position;
      end Get;
      for I in 1 .. 2 loop
         accept Step (Value : in out Integer; Times : in Integer := 1) do
            Put_Line ("Axis: step" & Integer'Image (Value)
                      & " x" & Integer'Image (Times));
            Position := Position + Value * Times;
            Value := Position;
         end Step;
      end loop;
      accept Get (Current : out Integer) do
         Current := Position * 100 + Resets;
      end Get;
      accept Stop do
         Put_Line ("Axis: stopping at" & Integer'Image (Position));
      end Stop;
   end Axis;

   V : Integer := 0;
begin
   Put_Line ("Main: reset");
   Axis.Reset;
   Axis.Set (42);
   Axis.Get (V);
   Put_Line ("Main: got" & Integer'Image (V));
   V := 5;
   Axis.Step (V);
   Put_Line ("Main: after step V =" & Integer'Image (V));
   V := -3;
   Axis.Step (Value => V, Times => 4);
   Put_Line ("Main: after step V =" & Integer'Image (V));
   Axis.Get (Current => V);
   Put_Line ("Main: encoded" & Integer'Image (V));
   Axis.Stop;
   Put_Line ("Main: done");
end Task_Entries_Params;
