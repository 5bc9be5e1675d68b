with Ada.Text_IO; use Ada.Text_IO;

procedure Records_Defaults is
   type Mode is (Idle, Moving, Gripping);
   type Point is record
      X : Float := 0.0;
      Y : Float := 0.0;
   end record;
   type Tool is record
      Name   : String (1 .. 7) := "gripper";
      Id     : Integer := 1;
      State  : Mode := Idle;
      Offset : Point;
      Force  : Float := 5.0;
      Active : Boolean := False;
   end record;
   T1 : Tool;
   T2 : constant Tool := (Name => "welder ", Id => 2, State => Moving,
                 Offset => (X => 1.5, Y => -2.0), Force => 12.5, Active => True);
   procedure Print (T : Tool) is
   begin
      Put_Line (T.Name & " id" & Integer'Image (T.Id) & " " & Mode'Image (T.State)
                & " offset" & Float'Image (T.Offset.X) & Float'Image (T.Offset.Y)
                & " force" & Float'Image (T.Force) & " active " & Boolean'Image (T.Active));
   end Print;
begin
   Print (T1);
   Print (T2);
   T1.Id := 10;
   T1.Offset.Y := 3.25;
   T1.State := Gripping;
   Print (T1);
   T1.Offset := (others => 7.0);
   Print (T1);
   T1 := (Name => "drill  ", Id => 3, State => Idle, Offset => (0.5, 0.5), Force => 1.0, Active => False);
   Print (T1);
   declare
      P : Point;
      Q : constant Point := (Y => 4.0, X => 2.0);
   begin
      Put_Line ("P =" & Float'Image (P.X) & Float'Image (P.Y));
      Put_Line ("Q =" & Float'Image (Q.X) & Float'Image (Q.Y));
      P := Q;
      P.X := P.X + Q.Y;
      Put_Line ("P =" & Float'Image (P.X) & Float'Image (P.Y));
   end;
end Records_Defaults;
