with Ada.Text_IO; use Ada.Text_IO;

--  A weld cell's scheduler task takes jobs. An accept body that cannot
--  finish a job itself requeues its caller: to one of its own entries
--  (served later, the job's in out value as the first accept left it), to
--  a member of the welder's entry family Weld (Seam_Kind), or to an entry
--  without parameters. The caller stays blocked until the last entry has
--  served its call; the scheduler is free at once, and a requeue in a
--  select alternative goes on with the alternative's statements.
procedure Task_Requeue_Rendezvous is
   type Seam_Kind is (Spot, Seam, Stitch);

   task Welder is
      entry Weld (Seam_Kind) (Job : in out Integer);
      entry Stop;
   end Welder;

   task body Welder is
      Welds : Natural := 0;
   begin
      delay 0.2;
      loop
         select
            accept Weld (Stitch) (Job : in out Integer) do
               Put_Line ("welder: stitch job" & Integer'Image (Job));
               Job := Job + 3000;
            end Weld;
         or
            accept Weld (Spot) (Job : in out Integer) do
               Put_Line ("welder: spot job" & Integer'Image (Job));
               Job := Job + 1000;
            end Weld;
         or
            accept Stop;
            exit;
         end select;
         Welds := Welds + 1;
      end loop;
      Put_Line ("welder made" & Natural'Image (Welds) & " welds");
   end Welder;

   task Scheduler is
      entry Submit (Job : in out Integer);
      entry Later (Job : in out Integer);
      entry Ping;
      entry Done;
   end Scheduler;

   task body Scheduler is
      Jobs : Natural := 0;
      Pings : Natural := 0;
   begin
      for Round in 1 .. 5 loop
         select
            accept Submit (Job : in out Integer) do
               Jobs := Jobs + 1;
               Job := Job * 10;
               if Job mod 20 = 0 then
                  requeue Later;
               elsif Job mod 30 = 0 then
                  declare
                     Kind : constant Seam_Kind := Stitch;
                  begin
                     requeue Welder.Weld (Kind);
                  exception
                     when others =>
                        Put_Line ("never");
                  end;
               elsif Job > 60 then
                  requeue Ping;
               end if;
               requeue Welder.Weld (Spot);
            end Submit;
            Put_Line ("scheduler: job" & Natural'Image (Jobs) & " passed on");
         or
            accept Ping do
               Pings := Pings + 1;
            end Ping;
         end select;
      end loop;
      accept Later (Job : in out Integer) do
         Put_Line ("scheduler: later job" & Integer'Image (Job));
         Job := Job + 200;
      end Later;
      accept Ping do
         Put_Line ("scheduler: ping");
      end Ping;
      accept Done;
   end Scheduler;

   task type Robot is
      entry Start (Job : Integer);
      entry Report (Result : out Integer);
   end Robot;

   task body Robot is
      J : Integer;
   begin
      accept Start (Job : Integer) do
         J := Job;
      end Start;
      Scheduler.Submit (J);
      accept Report (Result : out Integer) do
         Result := J;
      end Report;
   end Robot;

   Robots : array (1 .. 4) of Robot;
   Jobs : constant array (1 .. 4) of Integer := (1, 2, 3, 7);
   R : Integer;
begin
   for I in Robots'Range loop
      Robots (I).Start (Jobs (I));
      delay 0.05;
   end loop;
   delay 0.5;
   Put_Line ("main: late jobs");
   Scheduler.Ping;
   Scheduler.Done;
   for I in Robots'Range loop
      Robots (I).Report (R);
      Put_Line ("robot" & Integer'Image (I) & " job" & Integer'Image (Jobs (I))
                & " ->" & Integer'Image (R));
   end loop;
   Welder.Stop;
end Task_Requeue_Rendezvous;
