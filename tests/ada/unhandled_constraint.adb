with Ada.Text_IO; use Ada.Text_IO;

procedure Unhandled_Constraint is
   type Buffer is array (1 .. 4) of Integer;
   B : Buffer := (others => 0);
   procedure Fill (Count : Integer) is
   begin
      for I in 1 .. Count loop
         B (I) := I * 11;
         Put_Line ("B (" & Integer'Image (I) & " ) =" & Integer'Image (B (I)));
      end loop;
   end Fill;
begin
   Put_Line ("start");
   Put_Line ("filling 3");
   Fill (3);
   Put_Line ("filling 6");
   Fill (6);
   Put_Line ("never printed");
end Unhandled_Constraint;
