with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;

procedure Exception_Info is
   Sensor_Fault : exception;
   Bad_Input : exception;

   procedure Check (Value : Integer) is
   begin
      if Value < 0 then
         raise Bad_Input with "negative value:" & Integer'Image (Value);
      elsif Value > 9 then
         raise Sensor_Fault with "sensor" & Integer'Image (Value) & " failed";
      end if;
      Put_Line ("value" & Integer'Image (Value) & " ok");
   end Check;

   procedure Report (E : Exception_Occurrence) is
   begin
      Put_Line ("name: " & Exception_Name (E));
      Put_Line ("message: [" & Exception_Message (E) & "]");
   end Report;
begin
   for V in -1 .. 1 loop
      begin
         Check (V * 10);
      exception
         when E : others =>
            Report (E);
      end;
   end loop;
   begin
      raise Constraint_Error with "custom constraint message";
   exception
      when E : Constraint_Error =>
         Report (E);
   end;
   begin
      raise Program_Error with "";
   exception
      when E : others =>
         Report (E);
   end;
   begin
      raise Sensor_Fault with "quote "" inside";
   exception
      when Err : Sensor_Fault =>
         Put_Line (Exception_Name (Err) & " / " & Exception_Message (Err));
   end;
   declare
      Msg : constant String := "built at run time";
   begin
      raise Bad_Input with Msg & "!";
   exception
      when X : Bad_Input =>
         Put_Line ("Bad_Input: " & Exception_Message (X));
   end;
end Exception_Info;
