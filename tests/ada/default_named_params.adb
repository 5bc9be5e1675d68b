with Ada.Text_IO; use Ada.Text_IO;
with Ada.Float_Text_IO; use Ada.Float_Text_IO;

procedure Default_Named_Params is
   type Axis is (X_Axis, Y_Axis, Z_Axis);
   procedure Move_Tool (Distance : Float; Force : Float := 1.0;
                        Along : Axis := Z_Axis; Label : String := "move") is
   begin
      Put (Label & " " & Axis'Image (Along) & " distance ");
      Put (Distance, 1, 1, 0);
      Put (" force ");
      Put (Force, 1, 2, 0);
      New_Line;
   end Move_Tool;
   function Area (Width : Integer := 2; Height : Integer := 3) return Integer is
   begin
      return Width * Height;
   end Area;
   function Clamp (Value : Integer; Low : Integer := 0; High : Integer := 100) return Integer is
   begin
      if Value < Low then
         return Low;
      elsif Value > High then
         return High;
      else
         return Value;
      end if;
   end Clamp;
begin
   Move_Tool (20.0);
   Move_Tool (20.0, 5.0);
   Move_Tool (Distance => 20.0, Force => 5.0);
   Move_Tool (Force => 0.25, Distance => -3.5);
   Move_Tool (1.5, Along => X_Axis);
   Move_Tool (2.5, 3.0, Y_Axis, "jog");
   Move_Tool (Label => "named", Along => Y_Axis, Distance => 0.0);
   Put_Line ("Area =" & Integer'Image (Area));
   Put_Line ("Area (5) =" & Integer'Image (Area (5)));
   Put_Line ("Area (Height => 10) =" & Integer'Image (Area (Height => 10)));
   Put_Line ("Area (Height => 4, Width => 7) =" & Integer'Image (Area (Height => 4, Width => 7)));
   Put_Line ("Clamp (150) =" & Integer'Image (Clamp (150)));
   Put_Line ("Clamp (-5) =" & Integer'Image (Clamp (-5)));
   Put_Line ("Clamp (50, High => 40) =" & Integer'Image (Clamp (50, High => 40)));
   Put_Line ("Clamp (5, 10) =" & Integer'Image (Clamp (5, 10)));
   Put_Line ("Clamp (Low => -10, Value => -20) =" & Integer'Image (Clamp (Low => -10, Value => -20)));
   Put_Line ("Nested =" & Integer'Image (Clamp (Area (Width => 20, Height => 6), High => Area)));
end Default_Named_Params;
