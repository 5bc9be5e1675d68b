--  RM 4.9(38): a static real given to a constant of a floating point type
--  is that type's machine number (Float is a double in adair, 32 bits in
--  GNAT: every comparison below has the same answer for both), and one
--  given to Duration is a whole number of nanoseconds (GNAT truncates).
--  Named numbers stay exact.
with Ada.Text_IO; use Ada.Text_IO;

procedure Static_Real_Rounding is
   --  A conveyor cell: three pick slots share one metre of belt.
   Belt_Length : constant := 1.0;
   Slot_Share  : constant := Belt_Length / 3.0;          --  exact: a named number
   Slot_Pitch  : constant Float := Belt_Length / 3.0;    --  rounded: an object
   type Millimetres is digits 12;
   Pitch_Mm    : constant Millimetres := 1000.0 / 3.0;

   --  Gripper offsets measured in tenths.
   Approach : constant Float := 0.1;
   Lift     : constant Float := 0.2;
   Clear    : constant Float := 0.3;
   Raised   : constant Float := Approach + Lift;

   --  A cycle of three moves in two seconds.
   Move_Time : constant Duration := 2.0 / 3.0;
   Settle    : constant Duration := 0.0000000015;
   Cycle     : Duration := 2.0 / 3.0;

   procedure Report (What : String; Ok : Boolean) is
   begin
      Put_Line (What & ": " & Boolean'Image (Ok));
   end Report;
begin
   Report ("three slot shares fill the belt", Slot_Share * 3.0 = Belt_Length);
   Report ("three slot pitches fill the belt", Slot_Pitch * 3.0 = Belt_Length);
   Report ("three millimetre pitches fill the belt", Pitch_Mm * 3.0 = 1000.0);
   Report ("approach + lift = clear", Approach + Lift = Clear);
   Report ("raised = approach + lift", Raised = Approach + Lift);
   Report ("named 0.1 + 0.2 = 0.3", 0.1 + 0.2 = 0.3);
   Report ("three moves take two seconds", Move_Time * 3 = 2.0);
   Report ("a move is 0.666666666 s", Move_Time = 0.666666666);
   Put_Line ("move time:" & Duration'Image (Move_Time));
   Put_Line ("settle:" & Duration'Image (Settle));
   Put_Line ("cycle:" & Duration'Image (Cycle));
   Cycle := 0.0000000029;
   Put_Line ("cycle:" & Duration'Image (Cycle));
   Put_Line ("two thirds:" & Duration'Image (-2.0 / 3.0));
   if Slot_Pitch * 3.0 /= Belt_Length then
      Put_Line ("pitch rounded");
   end if;
end Static_Real_Rounding;
