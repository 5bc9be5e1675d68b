with Ada.Text_IO; use Ada.Text_IO;

procedure Overload_Result is
   type Color is (Red, Green, Blue);
   type Light is (Off, Red, Amber, Green);
   function Default return Integer is
   begin
      return 7;
   end Default;
   function Default return Float is
   begin
      return 0.5;
   end Default;
   function Default return Boolean is
   begin
      return True;
   end Default;
   function Parse (S : String) return Integer is
   begin
      return Integer'Value (S);
   end Parse;
   function Parse (S : String) return Color is
   begin
      return Color'Value (S);
   end Parse;
   I : Integer;
   F : Float;
   B : Boolean;
   C : Color;
   L : Light;
begin
   I := Default;
   F := Default;
   B := Default;
   Put_Line ("I =" & Integer'Image (I) & " F =" & Float'Image (F) & " B = " & Boolean'Image (B));
   Put_Line ("Integer'(Default) + 1 =" & Integer'Image (Integer'(Default) + 1));
   Put_Line ("Float'(Default) * 4.0 =" & Float'Image (Float'(Default) * 4.0));
   I := Parse ("123") + 1;
   C := Parse ("blue");
   Put_Line ("I =" & Integer'Image (I) & " C = " & Color'Image (C));
   Put_Line ("Integer'(Parse (""9"")) =" & Integer'Image (Integer'(Parse ("9"))));
   Put_Line ("Color'(Parse (""green"")) = " & Color'Image (Color'(Parse ("green"))));
   C := Red;
   L := Red;
   Put_Line ("C = " & Color'Image (C) & " L = " & Light'Image (L));
   Put_Line ("Color'Pos (Green) =" & Integer'Image (Color'Pos (Green)) & " Light'Pos (Green) =" & Integer'Image (Light'Pos (Green)));
   Put_Line ("Light'(Red) pos =" & Integer'Image (Light'Pos (Light'(Red))));
   for X in Light loop
      Put (Light'Image (X) & " ");
   end loop;
   New_Line;
   L := Light'Succ (Red);
   Put_Line ("Light'Succ (Red) = " & Light'Image (L));
end Overload_Result;
