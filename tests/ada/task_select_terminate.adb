with Ada.Text_IO; use Ada.Text_IO;

--  Servers that loop on `select ... or terminate;`: when their master has
--  nothing left to do and every dependent task waits at a terminate
--  alternative, they all terminate together and the master goes on.
procedure Task_Select_Terminate is
   task type Logger is
      entry Log (Line : String);
      entry Lines (N : out Integer);
   end Logger;

   task body Logger is
      Count : Integer := 0;
   begin
      loop
         select
            accept Log (Line : String) do
               Count := Count + 1;
               Put_Line ("log" & Integer'Image (Count) & ": " & Line);
            end Log;
         or
            accept Lines (N : out Integer) do
               N := Count;
            end Lines;
         or
            terminate;
         end select;
      end loop;
   end Logger;

   N : Integer;
begin
   Put_Line ("before the block");
   declare
      L1, L2 : Logger;
   begin
      L1.Log ("first");
      L2.Log ("second");
      L1.Log ("third");
      L1.Lines (N);
      Put_Line ("L1 logged" & Integer'Image (N));
   end;                      --  waits here: both loggers choose terminate
   Put_Line ("after the block");
   declare
      task Once is
         entry Ping;
      end Once;
      task body Once is
      begin
         select
            accept Ping do
               Put_Line ("Once: pinged");
            end Ping;
         or
            terminate;
         end select;
         Put_Line ("Once: not reached when nobody pings (wrong)");
      end Once;
   begin
      Put_Line ("nobody pings Once");
   end;
   Put_Line ("done");
end Task_Select_Terminate;
