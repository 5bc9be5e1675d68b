with Ada.Text_IO; use Ada.Text_IO;

procedure For_Enum_Range is
   type Joint is (Base, Shoulder, Elbow, Wrist, Flange);
   subtype Arm_Joint is Joint range Shoulder .. Wrist;
   type Angles is array (Joint) of Integer;
   type Small_Table is array (3 .. 6) of Character;
   A : Angles := (others => 0);
   T : constant Small_Table := ('p', 'q', 'r', 's');
   Total : Integer := 0;
begin
   for J in Joint loop
      A (J) := (Joint'Pos (J) + 1) * 15;
      Put_Line (Joint'Image (J) & " =" & Integer'Image (A (J)));
   end loop;
   for J in reverse Joint loop
      Put (Joint'Image (J) & " ");
   end loop;
   New_Line;
   for J in Arm_Joint loop
      Total := Total + A (J);
   end loop;
   Put_Line ("arm total =" & Integer'Image (Total));
   for J in Arm_Joint'Range loop
      Put (Joint'Image (J) & " ");
   end loop;
   New_Line;
   for J in Elbow .. Flange loop
      Put (Integer'Image (Joint'Pos (J)));
   end loop;
   New_Line;
   for J in A'Range loop
      if A (J) > 40 then
         Put_Line (Joint'Image (J) & " above 40");
      end if;
   end loop;
   for I in T'Range loop
      Put (Integer'Image (I) & "=" & T (I));
   end loop;
   New_Line;
   for I in reverse T'Range loop
      Put (T (I));
   end loop;
   New_Line;
   for B in Boolean loop
      Put_Line (Boolean'Image (B) & Integer'Image (Boolean'Pos (B)));
   end loop;
   for J in Joint range Base .. Shoulder loop
      Put_Line ("range " & Joint'Image (J));
   end loop;
end For_Enum_Range;
