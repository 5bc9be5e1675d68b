with Ada.Text_IO; use Ada.Text_IO;

procedure Exceptions_User is
   Gripper_Jam : exception;
   Out_Of_Reach : exception;
   Depth : Integer := 0;

   procedure Move (Distance : Integer) is
   begin
      Put_Line ("  Move" & Integer'Image (Distance));
      if Distance > 100 then
         raise Out_Of_Reach;
      elsif Distance < 0 then
         raise Gripper_Jam;
      end if;
      Put_Line ("  Move done");
   end Move;

   procedure Job (Distance : Integer) is
   begin
      Put_Line (" Job start");
      Move (Distance);
      Put_Line (" Job end");
   exception
      when Gripper_Jam =>
         Put_Line (" Job: recovered from jam");
   end Job;

   procedure Recurse (N : Integer) is
   begin
      Depth := Depth + 1;
      if N = 0 then
         raise Gripper_Jam;
      end if;
      Recurse (N - 1);
      Put_Line ("never printed");
   end Recurse;
begin
   for D in -1 .. 2 loop
      begin
         Job (D * 80);
         Put_Line ("Main: job" & Integer'Image (D) & " finished");
      exception
         when Out_Of_Reach =>
            Put_Line ("Main: out of reach for" & Integer'Image (D));
      end;
   end loop;
   begin
      Recurse (5);
   exception
      when Gripper_Jam =>
         Put_Line ("Recursion unwound after depth" & Integer'Image (Depth));
   end;
   begin
      raise Out_Of_Reach;
   exception
      when Gripper_Jam | Out_Of_Reach =>
         Put_Line ("choice list caught it");
   end;
   begin
      begin
         raise Gripper_Jam;
      exception
         when Out_Of_Reach =>
            Put_Line ("wrong handler");
      end;
   exception
      when others =>
         Put_Line ("outer others caught it");
   end;
   Put_Line ("done");
end Exceptions_User;
