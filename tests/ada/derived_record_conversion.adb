--  A tool frame is a pose of its own type, derived from the arm's pose:
--  conversions between them (both ways, and through a second derivation)
--  keep the components.
with Ada.Text_IO; use Ada.Text_IO;
procedure Derived_Record_Conversion is
   type Pose is record
      X, Y, Z : Float;
      Tag     : String (1 .. 4);
   end record;
   type Tool_Pose is new Pose;
   type Gripper_Pose is new Tool_Pose;
   type Joints is array (1 .. 3) of Float;
   type Tool_Joints is new Joints;

   procedure Show (P : Pose) is
   begin
      Put_Line (P.Tag & Float'Image (P.X) & Float'Image (P.Z));
   end Show;

   T : Tool_Pose := (X => 1.0, Y => 2.0, Z => 3.5, Tag => "TOOL");
   G : Gripper_Pose;
   P : Pose;
   J : Tool_Joints := (0.5, 1.5, 2.5);
begin
   P := Pose (T);
   Show (P);
   P.Tag := "BASE";
   T := Tool_Pose (P);
   G := Gripper_Pose (T);
   G.Z := G.Z * 2.0;
   Show (Pose (G));
   Put_Line (Boolean'Image (Tool_Pose (G) = T));
   Put_Line (Float'Image (Joints (J) (3)));
end Derived_Record_Conversion;
