with Ada.Text_IO; use Ada.Text_IO;

--  `else` in a selective accept (poll for callers without waiting) and in
--  a conditional entry call (call only if the server is waiting for it
--  right now). The else branches taken below are forced by the program's
--  own synchronisation; where success depends on timing the program
--  retries and prints only that it eventually got through.
procedure Task_Select_Else is
   task Server is
      entry Poke;
      entry Start;
      entry Busy_Until_Released;
      entry Report (Polls_Empty : out Integer);
   end Server;

   task body Server is
      Empty : Integer := 0;
   begin
      accept Start;
      --  Main is blocked on Busy_Until_Released, so nobody can call Poke.
      select
         accept Poke;
         Put_Line ("Server: poked (wrong)");
      else
         Empty := Empty + 1;
         Put_Line ("Server: nobody there");
      end select;
      accept Busy_Until_Released do
         Put_Line ("Server: releasing main");
      end Busy_Until_Released;
      --  Wait for Poke to be queued, then the select with else accepts it.
      while Poke'Count = 0 loop
         delay 0.001;
      end loop;
      select
         accept Poke do
            Put_Line ("Server: poked");
         end Poke;
      else
         Put_Line ("Server: nobody there (wrong)");
      end select;
      --  Now wait in an accept: main's conditional calls get through.
      accept Poke;
      accept Report (Polls_Empty : out Integer) do
         Polls_Empty := Empty;
      end Report;
   end Server;

   Tries : Integer := 0;
   Waited : Integer := 0;
   Empty : Integer;
begin
   --  The server waits at accept Start, so a conditional call of Poke
   --  cannot be accepted.
   select
      Server.Poke;
      Put_Line ("Main: poke accepted (wrong)");
   else
      Put_Line ("Main: server not ready for Poke");
   end select;
   Server.Start;
   Server.Busy_Until_Released;
   Server.Poke;            --  an ordinary call: queued, then accepted
   loop
      Tries := Tries + 1;
      select
         Server.Poke;
         exit;
      else
         Waited := Waited + 1;
         delay 0.001;      --  not waiting yet: try again
      end select;
   end loop;
   Put_Line ("Main: conditional Poke got through after at least one try: "
             & Boolean'Image (Tries >= 1 and Waited = Tries - 1));
   Server.Report (Empty);
   Put_Line ("Main: empty polls" & Integer'Image (Empty));
end Task_Select_Else;
