with Ada.Text_IO; use Ada.Text_IO;

procedure Unhandled_Partial_Line is
   Emergency_Stop : exception;
   Position : Integer := 0;
   procedure Step (Amount : Integer) is
   begin
      Position := Position + Amount;
      Put (Integer'Image (Position));
      if Position > 40 then
         raise Emergency_Stop with "position" & Integer'Image (Position);
      end if;
   end Step;
begin
   Put_Line ("moving in steps of 7");
   Put ("positions:");
   loop
      Step (7);
   end loop;
end Unhandled_Partial_Line;
