with Ada.Text_IO; use Ada.Text_IO;

procedure Min_Max is
   type Level is (Low, Medium, High, Critical);
   A : constant Integer := 17;
   B : constant Integer := -4;
   X : constant Float := 2.5;
   Y : constant Float := -7.25;
   Best : Integer := Integer'First;
   Worst : Integer := Integer'Last;
   Data : constant array (1 .. 8) of Integer := (5, -3, 12, 0, 12, -8, 7, 3);
begin
   Put_Line ("Min (A, B) =" & Integer'Image (Integer'Min (A, B)));
   Put_Line ("Max (A, B) =" & Integer'Image (Integer'Max (A, B)));
   Put_Line ("Min (3, 3) =" & Integer'Image (Integer'Min (3, 3)));
   Put_Line ("Float Min =" & Float'Image (Float'Min (X, Y)));
   Put_Line ("Float Max =" & Float'Image (Float'Max (X, Y)));
   Put_Line ("Level Max = " & Level'Image (Level'Max (Medium, High)));
   Put_Line ("Level Min = " & Level'Image (Level'Min (Critical, Low)));
   Put_Line ("Nested =" & Integer'Image (Integer'Max (Integer'Min (A, 10), B)));
   for I in Data'Range loop
      Best := Integer'Max (Best, Data (I));
      Worst := Integer'Min (Worst, Data (I));
      Put_Line ("step" & Integer'Image (I) & ":" & Integer'Image (Best) & Integer'Image (Worst));
   end loop;
   Put_Line ("Clamp 150 =" & Integer'Image (Integer'Max (0, Integer'Min (100, 150))));
   Put_Line ("Clamp -20 =" & Integer'Image (Integer'Max (0, Integer'Min (100, -20))));
   Put_Line ("Clamp 42 =" & Integer'Image (Integer'Max (0, Integer'Min (100, 42))));
   Put_Line ("Extremes =" & Integer'Image (Integer'Min (Integer'First, Integer'Last))
             & Integer'Image (Integer'Max (Integer'First, Integer'Last)));
   Put_Line ("Char max = " & Character'Image (Character'Max ('a', 'Z')));
end Min_Max;
