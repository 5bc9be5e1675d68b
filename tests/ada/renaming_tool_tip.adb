--  A pick-and-place cell lowers its tool in steps: the tool tip's height
--  is a component of the pose record, renamed once and changed through
--  the new name; reads through either name see the same object.
with Ada.Text_IO; use Ada.Text_IO;
procedure Renaming_Tool_Tip is
   type Pose is record
      X, Y, Z : Float;
      Roll    : Float;
   end record;

   type Axis_Name is (Base, Shoulder, Elbow, Wrist);
   type Axis_Set is array (Axis_Name) of Integer;

   type Cell is record
      Tool  : Pose;
      Axes  : Axis_Set;
      Cycle : Natural;
   end record;

   Robot    : Cell := (Tool  => (X => 250.0, Y => 0.0, Z => 120.0, Roll => 0.0),
                       Axes  => (others => 0),
                       Cycle => 0);
   Tool_Tip : Float renames Robot.Tool.Z;
   Tool     : Pose renames Robot.Tool;
   Elbow_Steps : Integer renames Robot.Axes (Elbow);
   Cycles   : Natural renames Robot.Cycle;
   Count    : Natural renames Cycles;          --  a renaming of a renaming

   Step : constant Float := 25.0;
   Home : constant Pose := (X => 0.0, Y => 0.0, Z => 300.0, Roll => 0.0);
   Home_Z : Float renames Home.Z;              --  a constant view

   procedure Show (Label : String) is
   begin
      Put_Line (Label & ": tip" & Integer'Image (Integer (Tool_Tip))
                & " z" & Integer'Image (Integer (Robot.Tool.Z))
                & " elbow" & Integer'Image (Elbow_Steps)
                & " cycles" & Natural'Image (Count));
   end Show;

   procedure Lift (Height : in out Float; By : Float) is
   begin
      Height := Height + By;
   end Lift;
begin
   Show ("start");
   while Tool_Tip > 40.0 loop
      Tool_Tip := Tool_Tip - Step;
      Elbow_Steps := Elbow_Steps + 3;
      Cycles := Cycles + 1;
      Put_Line ("  lowered to" & Integer'Image (Integer (Robot.Tool.Z)));
   end loop;
   Show ("at part");
   Robot.Tool.Z := 200.0;                      --  the original changes the renaming
   Show ("reset");
   Lift (Tool_Tip, 15.5);                      --  an in out actual through the renaming
   Show ("lifted");
   Tool.Roll := 1.5;
   Tool := (X => Tool.X + 10.0, Y => Tool.Y, Z => Tool.Z, Roll => Tool.Roll);
   Put_Line ("tool x" & Integer'Image (Integer (Robot.Tool.X))
             & " roll" & Integer'Image (Integer (Robot.Tool.Roll * 10.0)));
   Put_Line ("home z" & Integer'Image (Integer (Home_Z)));
   Robot.Tool := Home;
   Show ("home");
end Renaming_Tool_Tip;
