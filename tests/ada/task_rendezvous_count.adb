with Ada.Text_IO; use Ada.Text_IO;

--  10,000 rendezvous between two tasks and the main program: a producer
--  task and main both call the counter; main prints only the totals.
procedure Task_Rendezvous_Count is
   task Counter is
      entry Add (N : Integer);
      entry Total (Calls, Sum : out Integer);
   end Counter;

   task body Counter is
      C, S : Integer := 0;
   begin
      loop
         select
            accept Add (N : Integer) do
               S := S + N;
            end Add;
            C := C + 1;
         or
            when C = 10_000 =>
               accept Total (Calls, Sum : out Integer) do
                  Calls := C;
                  Sum := S;
               end Total;
               exit;
         end select;
      end loop;
   end Counter;

   task Helper;
   task body Helper is
   begin
      for I in 1 .. 5_000 loop
         Counter.Add (2);
      end loop;
   end Helper;

   Calls, Sum : Integer;
begin
   for I in 1 .. 5_000 loop
      Counter.Add (1);
   end loop;
   Counter.Total (Calls, Sum);
   Put_Line ("rendezvous:" & Integer'Image (Calls));
   Put_Line ("sum:" & Integer'Image (Sum));
end Task_Rendezvous_Count;
