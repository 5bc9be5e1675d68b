--  Limited private types with discriminants whose full views are a task
--  type (an axis driver, by axis number) and a protected type (a move
--  counter with a default start). Outside the package the discriminants
--  are read like a record's (`Driver.Axis`); the entries and protected
--  operations are reached through the package's subprograms.
with Ada.Text_IO; use Ada.Text_IO;

procedure Private_Discriminant_Drivers is
   package Axes is
      type Axis_Driver (Axis : Positive) is limited private;
      type Move_Counter (Start : Natural := 100) is limited private;

      procedure Move (D : in out Axis_Driver; To : Integer);
      procedure Stop (D : in out Axis_Driver);
      procedure Tally (C : in out Move_Counter);
      function Moves (C : Move_Counter) return Natural;
   private
      task type Axis_Driver (Axis : Positive) is
         entry Move (To : Integer);
         entry Stop;
      end Axis_Driver;

      protected type Move_Counter (Start : Natural := 100) is
         procedure Count;
         function Moves return Natural;
      private
         N : Natural := Start;
      end Move_Counter;
   end Axes;

   package body Axes is
      task body Axis_Driver is
         Position : Integer := 0;
      begin
         loop
            select
               accept Move (To : Integer) do
                  Position := To;
                  Put_Line ("axis" & Positive'Image (Axis) & " at"
                            & Integer'Image (Position));
               end Move;
            or
               accept Stop do
                  Put_Line ("axis" & Positive'Image (Axis) & " stopped");
               end Stop;
               exit;
            end select;
         end loop;
      end Axis_Driver;

      protected body Move_Counter is
         procedure Count is
         begin
            N := N + 1;
         end Count;
         function Moves return Natural is (N);
      end Move_Counter;

      procedure Move (D : in out Axis_Driver; To : Integer) is
      begin
         D.Move (To);
      end Move;

      procedure Stop (D : in out Axis_Driver) is
      begin
         D.Stop;
      end Stop;

      procedure Tally (C : in out Move_Counter) is
      begin
         C.Count;
      end Tally;

      function Moves (C : Move_Counter) return Natural is (C.Moves);
   end Axes;

   use Axes;

   Shoulder : Axis_Driver (1);
   Elbow    : Axis_Driver (Axis => 2);
   Total    : Move_Counter;
   Shift    : Move_Counter (Start => 0);

   procedure Report (D : Axis_Driver; C : Move_Counter) is
   begin
      Put_Line ("driver of axis" & Positive'Image (D.Axis) & ", counter from"
                & Natural'Image (C.Start) & " at" & Natural'Image (Moves (C)));
   end Report;
begin
   Move (Shoulder, 30);
   Tally (Total);
   Tally (Shift);
   Move (Elbow, -15);
   Tally (Total);
   Tally (Shift);
   Report (Shoulder, Total);
   Report (Elbow, Shift);
   Put_Line ("constrained: " & Boolean'Image (Total'Constrained)
             & " " & Boolean'Image (Shift'Constrained));
   Stop (Shoulder);
   Stop (Elbow);
end Private_Discriminant_Drivers;
