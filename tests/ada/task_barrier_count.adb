with Ada.Text_IO; use Ada.Text_IO;

--  RM 9.5.3(7-8), 9.5.1(7): a protected entry's barrier is evaluated again
--  whenever a caller is queued on it, and at the end of every protected
--  action, so a barrier that reads its own entry's 'Count opens when the
--  last caller arrives. The classic cyclic barrier: three stations wait
--  at a synchronisation point; the third arrival releases all three, the
--  Releasing flag lets the queued callers through and closes again
--  behind the last one.
procedure Task_Barrier_Count is
   Stations : constant := 3;

   protected Sync_Point is
      entry Wait (Round : out Positive);
      function Rounds return Natural;
   private
      Releasing : Boolean := False;
      Done : Natural := 0;
   end Sync_Point;

   protected body Sync_Point is
      entry Wait (Round : out Positive)
        when Wait'Count = Stations or Releasing is
      begin
         if not Releasing then
            Done := Done + 1;
         end if;
         Round := Done;
         Releasing := Wait'Count > 0;
      end Wait;
      function Rounds return Natural is (Done);
   end Sync_Point;

   protected Tally is
      procedure Add (R : Positive);
      function Total return Natural;
   private
      Sum : Natural := 0;
   end Tally;
   protected body Tally is
      procedure Add (R : Positive) is
      begin
         Sum := Sum + R;
      end Add;
      function Total return Natural is (Sum);
   end Tally;

   task type Station;
   task body Station is
      R : Positive;
   begin
      for Cycle in 1 .. 4 loop
         Sync_Point.Wait (R);
         Tally.Add (R);
      end loop;
   end Station;

begin
   declare
      Cell : array (1 .. Stations) of Station;
   begin
      null;
   end;
   --  4 rounds, 3 stations each: 3 * (1 + 2 + 3 + 4) = 30
   Put_Line ("rounds:" & Natural'Image (Sync_Point.Rounds));
   Put_Line ("sum of rounds seen:" & Natural'Image (Tally.Total));
end Task_Barrier_Count;
