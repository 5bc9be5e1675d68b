with Ada.Text_IO; use Ada.Text_IO;

procedure Enum_Attributes is
   type Color is (Red, Green, Blue, Yellow, Black);
   type Day is (Mon, Tue, Wed, Thu, Fri, Sat, Sun);
   subtype Weekday is Day range Mon .. Fri;
   C : Color := Red;
   D : Day;
begin
   Put_Line ("Color'First = " & Color'Image (Color'First));
   Put_Line ("Color'Last = " & Color'Image (Color'Last));
   Put_Line ("Weekday'Last = " & Weekday'Image (Weekday'Last));
   for X in Color loop
      Put_Line (Color'Image (X) & " pos" & Integer'Image (Color'Pos (X)));
   end loop;
   for I in 0 .. 6 loop
      Put (Day'Image (Day'Val (I)) & " ");
   end loop;
   New_Line;
   C := Color'Succ (C);
   Put_Line ("Succ (Red) = " & Color'Image (C));
   C := Color'Pred (Color'Last);
   Put_Line ("Pred (Last) = " & Color'Image (C));
   Put_Line ("Object image: " & C'Image);
   D := Day'Value ("wed");
   Put_Line ("Value (wed) = " & Day'Image (D));
   D := Day'Value ("  SuN  ");
   Put_Line ("Value (  SuN  ) = " & Day'Image (D));
   D := Day'Value ("fRi");
   Put_Line ("Value (fRi) pos =" & Integer'Image (Day'Pos (D)));
   Put_Line ("Succ (Wed) = " & Day'Image (Day'Succ (Day'Value ("Wed"))));
   Put_Line ("Boolean'Image (True) = " & Boolean'Image (True));
   Put_Line ("Boolean'Value (false) = " & Boolean'Image (Boolean'Value ("false")));
   Put_Line ("Boolean'Pos (True) =" & Integer'Image (Boolean'Pos (True)));
   Put_Line ("Boolean'Succ (False) = " & Boolean'Image (Boolean'Succ (False)));
   Put_Line ("Image length:" & Integer'Image (Color'Image (Yellow)'Length));
   C := Color'Value ("blue");
   if Color'Pos (C) > Color'Pos (Green) and C > Green then
      Put_Line ("Blue > Green");
   end if;
   begin
      D := Day'Value ("Funday");
      Put_Line ("not reached " & Day'Image (D));
   exception
      when Constraint_Error =>
         Put_Line ("Day'Value (Funday) raised Constraint_Error");
   end;
   begin
      D := Day'Succ (Day'Value ("sun"));
      Put_Line ("not reached " & Day'Image (D));
   exception
      when Constraint_Error =>
         Put_Line ("Day'Succ (Sun) raised Constraint_Error");
   end;
   begin
      C := Color'Pred (C);
      C := Color'Pred (C);
      Put_Line ("now " & Color'Image (C));
      C := Color'Pred (C);
      Put_Line ("not reached " & Color'Image (C));
   exception
      when Constraint_Error =>
         Put_Line ("Color'Pred (Red) raised Constraint_Error");
   end;
end Enum_Attributes;
