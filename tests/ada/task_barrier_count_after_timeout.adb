--  RM 9.5.3(20), 9.7.2: a timed protected entry call that times out is
--  taken off its queue as a protected action, and the entry queues are
--  then serviced: a barrier that reads that entry's 'Count (a spare
--  station that may only go while no station waits at the gate) opens
--  when the waiting station gives up.
with Ada.Text_IO; use Ada.Text_IO;
with Ada.Calendar; use Ada.Calendar;
procedure Task_Barrier_Count_After_Timeout is
   Start : constant Time := Clock;

   protected Gate is
      entry Wait;
      entry Spare;
   end Gate;

   protected body Gate is
      entry Wait when False is
      begin
         null;
      end Wait;
      entry Spare when Wait'Count = 0 is
      begin
         null;
      end Spare;
   end Gate;

   task Station;
   task body Station is
   begin
      select
         Gate.Wait;
      or
         delay 0.2;
      end select;
   end Station;

   task Spare_Station;
   task body Spare_Station is
   begin
      delay 0.05;
      Gate.Spare;
      Put_Line ("spare through after the station gave up: "
                & Boolean'Image (Clock - Start >= 0.2));
   end Spare_Station;
begin
   null;
end Task_Barrier_Count_After_Timeout;
