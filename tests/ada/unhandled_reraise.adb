with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;

procedure Unhandled_Reraise is
   Sensor_Lost : exception;
   procedure Read (Channel : Integer) is
   begin
      if Channel = 3 then
         raise Sensor_Lost with "channel 3";
      end if;
      Put_Line ("read channel" & Integer'Image (Channel));
   end Read;
begin
   for C in 1 .. 5 loop
      Read (C);
   end loop;
   Put_Line ("never printed");
exception
   when E : Sensor_Lost =>
      Put_Line ("cleanup after " & Exception_Name (E) & ": " & Exception_Message (E));
      raise;
end Unhandled_Reraise;
