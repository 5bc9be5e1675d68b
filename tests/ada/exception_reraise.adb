with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;

procedure Exception_Reraise is
   Motor_Stall : exception;
   Log_Count : Natural := 0;

   procedure Log (S : String) is
   begin
      Log_Count := Log_Count + 1;
      Put_Line ("log" & Integer'Image (Log_Count) & ": " & S);
   end Log;

   procedure Drive (Speed : Integer) is
   begin
      if Speed > 5 then
         raise Motor_Stall with "speed" & Integer'Image (Speed);
      end if;
      Log ("drive at" & Integer'Image (Speed));
   end Drive;

   procedure Controller (Speed : Integer) is
   begin
      Drive (Speed);
   exception
      when E : Motor_Stall =>
         Log ("controller saw " & Exception_Message (E));
         raise;
   end Controller;

   procedure Supervisor (Speed : Integer) is
   begin
      Controller (Speed);
      Log ("supervisor ok");
   exception
      when E : others =>
         Log ("supervisor saw " & Exception_Name (E) & ": " & Exception_Message (E));
         raise Program_Error with "escalated from " & Exception_Message (E);
   end Supervisor;
begin
   Supervisor (3);
   begin
      Supervisor (8);
   exception
      when E : Program_Error =>
         Log ("main: " & Exception_Name (E) & " [" & Exception_Message (E) & "]");
   end;
   begin
      begin
         Drive (9);
      exception
         when Motor_Stall =>
            Log ("inner handler, re-raising");
            raise;
      end;
   exception
      when E : Motor_Stall =>
         Log ("outer got it again: " & Exception_Message (E));
   end;
   begin
      begin
         raise Constraint_Error with "first";
      exception
         when Constraint_Error =>
            raise Motor_Stall with "second";
      end;
   exception
      when E : others =>
         Log ("replaced: " & Exception_Name (E) & " " & Exception_Message (E));
   end;
   Log ("end");
end Exception_Reraise;
