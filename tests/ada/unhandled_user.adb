with Ada.Text_IO; use Ada.Text_IO;

procedure Unhandled_User is
   Gripper_Jam : exception;
   procedure Grip (Force : Integer) is
   begin
      Put_Line ("grip with force" & Integer'Image (Force));
      if Force > 30 then
         raise Gripper_Jam with "force" & Integer'Image (Force) & " too high";
      end if;
   end Grip;
   procedure Cycle (N : Integer) is
   begin
      for I in 1 .. N loop
         Put_Line ("cycle" & Integer'Image (I));
         Grip (I * 10);
      end loop;
      Put_Line ("cycles done");
   end Cycle;
begin
   Put_Line ("start");
   Cycle (2);
   begin
      Cycle (5);
   exception
      when Constraint_Error =>
         Put_Line ("not this handler");
   end;
   Put_Line ("never printed");
end Unhandled_User;
