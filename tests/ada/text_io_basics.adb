with Ada.Text_IO; use Ada.Text_IO;

procedure Text_IO_Basics is
begin
   Put_Line ("first line");
   Put ("no newline, ");
   Put ("still same line");
   New_Line;
   Put ('C');
   Put ('h');
   New_Line;
   New_Line (2);
   Put_Line ("after two blank lines");
   New_Line (1);
   Put_Line ("");
   Put ("");
   Put_Line ("after empty puts");
   Ada.Text_IO.Put_Line ("fully qualified");
   Ada.Text_IO.Put ("qualified put");
   Ada.Text_IO.New_Line;
   Put_Line ("   leading and trailing blanks   ");
   Put_Line ("tab" & Character'Val (9) & "separated");
   for I in 1 .. 3 loop
      Put (Integer'Image (I));
      if I = 2 then
         New_Line (2);
      elsif I = 3 then
         New_Line (3);
      else
         New_Line;
      end if;
   end loop;
   Put_Line (Item => "named Item");
   Put (Item => "named put");
   New_Line (Spacing => 1);
   Put_Line ("end");
end Text_IO_Basics;
