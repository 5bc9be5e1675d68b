--  1,000 tasks created and finished (issue 10's figure): an array of
--  1,000 workers, each told its number by a rendezvous and ending; the
--  block waits for all of them.
with Ada.Text_IO; use Ada.Text_IO;
procedure Tasks1000 is
   Sum : Integer := 0;
   task type Worker is
      entry Start (N : Integer);
   end Worker;
   task body Worker is
      Mine : Integer;
   begin
      accept Start (N : Integer) do
         Mine := N;
      end Start;
      Sum := Sum + Mine;
   end Worker;
begin
   declare
      W : array (1 .. 1_000) of Worker;
   begin
      for I in W'Range loop
         W (I).Start (I);
      end loop;
   end;
   Put_Line (Integer'Image (Sum));
end Tasks1000;
