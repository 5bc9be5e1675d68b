with Ada.Text_IO; use Ada.Text_IO;

--  Parts arrive at a dispatcher one at a time. A robot asking for a kind
--  that is out of stock is requeued, within the protected action, to the
--  private entry family Wait_For (Kind), whose barrier opens when a part
--  of its kind arrives; the robot stays blocked in its call until then.
--  Robots order through a front desk task, whose accept requeues each
--  caller to the dispatcher: the desk is free for the next one at once.
procedure Task_Requeue_Dispatcher is
   type Part_Kind is (Bolt, Nut, Washer);
   type Counts is array (Part_Kind) of Natural;

   protected Dispatcher is
      entry Get (Kind : Part_Kind; Serial : out Positive);
      procedure Arrive (Kind : Part_Kind);
      function Waiting (Kind : Part_Kind) return Natural;
   private
      entry Wait_For (Part_Kind) (Kind : Part_Kind; Serial : out Positive);
      Stock : Counts := (others => 0);
      Next : Positive := 100;
   end Dispatcher;

   protected body Dispatcher is
      entry Get (Kind : Part_Kind; Serial : out Positive) when True is
      begin
         if Stock (Kind) = 0 then
            requeue Wait_For (Kind);
         end if;
         Stock (Kind) := Stock (Kind) - 1;
         Next := Next + 1;
         Serial := Next;
      end Get;

      entry Wait_For (for K in Part_Kind) (Kind : Part_Kind; Serial : out Positive)
        when Stock (K) > 0 is
      begin
         Stock (K) := Stock (K) - 1;
         Next := Next + 1;
         Serial := Next + 1000;
      end Wait_For;

      procedure Arrive (Kind : Part_Kind) is
      begin
         Stock (Kind) := Stock (Kind) + 1;
      end Arrive;

      function Waiting (Kind : Part_Kind) return Natural is
      begin
         return Wait_For (Kind)'Count;
      end Waiting;
   end Dispatcher;

   task Desk is
      entry Order (Kind : Part_Kind; Serial : out Positive);
      entry Close (Orders : out Natural);
   end Desk;

   task body Desk is
      Taken : Natural := 0;
   begin
      loop
         select
            accept Order (Kind : Part_Kind; Serial : out Positive) do
               Taken := Taken + 1;
               requeue Dispatcher.Get;
            end Order;
         or
            accept Close (Orders : out Natural) do
               Orders := Taken;
            end Close;
            exit;
         end select;
      end loop;
   end Desk;

   task type Robot is
      entry Start (Kind : Part_Kind);
      entry Report (Serial : out Positive);
   end Robot;

   task body Robot is
      K : Part_Kind;
      S : Positive;
   begin
      accept Start (Kind : Part_Kind) do
         K := Kind;
      end Start;
      Desk.Order (K, S);
      accept Report (Serial : out Positive) do
         Serial := S;
      end Report;
   end Robot;

   Robots : array (1 .. 4) of Robot;
   Kinds : constant array (1 .. 4) of Part_Kind := (Nut, Washer, Nut, Bolt);
   S : Positive;
   N : Natural;

   procedure Show (When_Text : String) is
   begin
      Put_Line (When_Text & ": waiting for bolt, nut, washer:"
                & Natural'Image (Dispatcher.Waiting (Bolt))
                & Natural'Image (Dispatcher.Waiting (Nut))
                & Natural'Image (Dispatcher.Waiting (Washer)));
   end Show;
begin
   for I in 1 .. 3 loop
      Robots (I).Start (Kinds (I));
      delay 0.05;
   end loop;
   Show ("three robots ordered");
   Dispatcher.Arrive (Washer);
   delay 0.05;
   Show ("a washer arrived");
   Dispatcher.Arrive (Bolt);
   Robots (4).Start (Bolt);
   delay 0.05;
   Show ("a bolt arrived, robot 4 ordered it");
   Dispatcher.Arrive (Nut);
   delay 0.05;
   Dispatcher.Arrive (Nut);
   delay 0.05;
   Show ("two nuts arrived");
   Dispatcher.Arrive (Bolt);
   Desk.Order (Bolt, S);
   Put_Line ("main got bolt" & Positive'Image (S));
   for I in Robots'Range loop
      Robots (I).Report (S);
      Put_Line ("robot" & Integer'Image (I) & " got " & Part_Kind'Image (Kinds (I))
                & Positive'Image (S));
   end loop;
   Desk.Close (N);
   Put_Line ("the desk took" & Natural'Image (N) & " orders");
end Task_Requeue_Dispatcher;
