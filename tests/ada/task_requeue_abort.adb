with Ada.Text_IO; use Ada.Text_IO;

--  A safety gate lets robots into the cell once it is open. Its entry
--  Enter requeues every caller to the private entry Hold, closed until
--  the operator opens the gate: `requeue Hold with abort` lets a timed
--  call's timeout still cancel the wait; plain `requeue Hold` does not
--  (the caller waits for the gate, its timeout passed). A conditional
--  call requeued with abort to a closed entry is cancelled at once. The
--  same with a tool changer task: its accept requeues with abort to the
--  changer's own entry, which it accepts only later.
procedure Task_Requeue_Abort is
   protected Gate is
      entry Enter (Robot : Positive);
      entry Enter_Or_Give_Up (Robot : Positive);
      procedure Open;
      function Inside return Natural;
   private
      entry Hold (Robot : Positive);
      Is_Open : Boolean := False;
      Count : Natural := 0;
   end Gate;

   protected body Gate is
      entry Enter (Robot : Positive) when True is
      begin
         requeue Hold;
      end Enter;

      entry Enter_Or_Give_Up (Robot : Positive) when True is
      begin
         requeue Hold with abort;
      end Enter_Or_Give_Up;

      entry Hold (Robot : Positive) when Is_Open is
      begin
         Count := Count + 1;
      end Hold;

      procedure Open is
      begin
         Is_Open := True;
      end Open;

      function Inside return Natural is
      begin
         return Count;
      end Inside;
   end Gate;

   task Operator;
   task body Operator is
   begin
      delay 1.0;
      Put_Line ("operator opens the gate");
      Gate.Open;
   end Operator;

   task Changer is
      entry Change (Tool : Natural);
      entry Mount (Tool : Natural);
   end Changer;

   task body Changer is
   begin
      accept Change (Tool : Natural) do
         requeue Mount with abort;
      end Change;
      accept Change (Tool : Natural) do
         requeue Mount;
      end Change;
      delay 2.0;
      accept Mount (Tool : Natural) do
         Put_Line ("changer mounts tool" & Natural'Image (Tool));
      end Mount;
   end Changer;
begin
   select
      Gate.Enter_Or_Give_Up (1);
      Put_Line ("robot 1 entered");
   or
      delay 0.2;
      Put_Line ("robot 1 gave up waiting");
   end select;
   select
      Gate.Enter_Or_Give_Up (2);
      Put_Line ("robot 2 entered");
   else
      Put_Line ("robot 2: the gate is closed");
   end select;
   select
      Gate.Enter (3);
      Put_Line ("robot 3 entered (after its timeout)");
   or
      delay 0.2;
      Put_Line ("robot 3 gave up waiting");
   end select;
   Put_Line ("inside:" & Natural'Image (Gate.Inside));
   select
      Gate.Enter (4);
      Put_Line ("robot 4 entered");
   else
      Put_Line ("robot 4: the gate is closed");
   end select;
   select
      Changer.Change (7);
      Put_Line ("tool 7 mounted");
   or
      delay 0.5;
      Put_Line ("tool 7 not mounted in time");
   end select;
   select
      Changer.Change (8);
      Put_Line ("tool 8 mounted (after its timeout)");
   or
      delay 0.5;
      Put_Line ("tool 8 not mounted in time");
   end select;
end Task_Requeue_Abort;
