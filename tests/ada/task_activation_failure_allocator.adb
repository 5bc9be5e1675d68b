with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;

--  RM 9.2(5), 4.8(10): a task created by an allocator is activated by the
--  allocator, which waits for the activation to end. If the task's
--  declarative part raises, the allocator raises Tasking_Error, so the
--  assignment, call or aggregate it is part of does not happen, and the
--  task never runs its body. Wherever the allocator stands (an assignment,
--  an actual parameter, an aggregate), the tasks activated so far are
--  counted in their declarative parts, so the counts are exact at once.
procedure Task_Activation_Failure_Allocator is
   Limits : constant array (1 .. 8) of Integer := (5, 8, -1, 3, 6, -2, 4, -3);
   Next : Natural := 0;
   Activated : Natural := 0;

   function Next_Limit return Integer is
   begin
      Next := Next + 1;
      return Limits (Next);
   end Next_Limit;

   function Note_Activated return Boolean is
   begin
      Activated := Activated + 1;
      return True;
   end Note_Activated;

   task type Axis;
   type Axis_Ref is access Axis;

   task body Axis is
      Max : constant Positive := Next_Limit;   --  fails for a negative limit
      Noted : constant Boolean := Note_Activated;
   begin
      if not Noted or Max > 1_000 then
         Put_Line ("Axis: not reached (wrong)");
      end if;
   end Axis;

   Axes : array (1 .. 4) of Axis_Ref;
   Installed : Natural := 0;
   procedure Install (A : Axis_Ref) is
   begin
      Installed := Installed + 1;
   end Install;
   type Pair is array (1 .. 2) of Axis_Ref;
   Spare : Pair;

   procedure Show (What : String) is
   begin
      Put_Line (What & ": activated" & Natural'Image (Activated)
                & ", limits taken" & Natural'Image (Next));
   end Show;
begin
   for I in Axes'Range loop
      begin
         Axes (I) := new Axis;
         Show ("axis" & Integer'Image (I));
      exception
         when E : Tasking_Error =>
            Show ("axis" & Integer'Image (I) & " " & Exception_Name (E)
                  & ", still null " & Boolean'Image (Axes (I) = null));
      end;
   end loop;
   for I in 1 .. 2 loop
      begin
         Install (new Axis);
         Show ("install" & Integer'Image (I));
      exception
         when E : Tasking_Error =>
            Show ("install" & Integer'Image (I) & " " & Exception_Name (E));
      end;
   end loop;
   Put_Line ("installed" & Natural'Image (Installed));
   begin
      Spare := (new Axis, new Axis);
      Show ("spare pair");
   exception
      when E : Tasking_Error =>
         Show ("spare pair " & Exception_Name (E) & ", still null "
               & Boolean'Image (Spare (1) = null and Spare (2) = null));
   end;
end Task_Activation_Failure_Allocator;
