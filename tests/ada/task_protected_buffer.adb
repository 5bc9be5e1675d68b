with Ada.Text_IO; use Ada.Text_IO;

--  A bounded buffer as a protected type (entries with barriers) between
--  two producers and one consumer, and a counting semaphore as a protected
--  type guarding a section that at most two workers may be in at once.
procedure Task_Protected_Buffer is
   Size : constant := 4;
   type Item_Array is array (0 .. Size - 1) of Integer;

   protected type Buffer is
      entry Put (Item : in Integer);
      entry Get (Item : out Integer);
      function Max_Fill return Natural;
   private
      Store : Item_Array := (others => 0);
      Head : Natural := 0;
      Count : Natural := 0;
      Max : Natural := 0;
   end Buffer;

   protected body Buffer is
      entry Put (Item : in Integer) when Count < Size is
      begin
         Store ((Head + Count) mod Size) := Item;
         Count := Count + 1;
         if Count > Max then
            Max := Count;
         end if;
      end Put;
      entry Get (Item : out Integer) when Count > 0 is
      begin
         Item := Store (Head);
         Head := (Head + 1) mod Size;
         Count := Count - 1;
      end Get;
      function Max_Fill return Natural is
      begin
         return Max;
      end Max_Fill;
   end Buffer;

   B : Buffer;

   --  Producer P puts P * 1000 + 1 .. P * 1000 + 50.
   task type Producer is
      entry Start (P : Integer);
   end Producer;
   task body Producer is
      Base : Integer;
   begin
      accept Start (P : Integer) do
         Base := P * 1000;
      end Start;
      for I in 1 .. 50 loop
         B.Put (Base + I);
      end loop;
   end Producer;

   protected type Semaphore is
      entry Seize;
      procedure Release;
      procedure Set (Permits : Natural);
   private
      Free : Natural := 0;
   end Semaphore;

   protected body Semaphore is
      entry Seize when Free > 0 is
      begin
         Free := Free - 1;
      end Seize;
      procedure Release is
      begin
         Free := Free + 1;
      end Release;
      procedure Set (Permits : Natural) is
      begin
         Free := Permits;
      end Set;
   end Semaphore;

   S : Semaphore;

   protected Room is
      procedure Enter;
      procedure Leave;
      function Most return Natural;
      function Visits return Natural;
   private
      Inside, Peak, Total : Natural := 0;
   end Room;

   protected body Room is
      procedure Enter is
      begin
         Inside := Inside + 1;
         Total := Total + 1;
         if Inside > Peak then
            Peak := Inside;
         end if;
      end Enter;
      procedure Leave is
      begin
         Inside := Inside - 1;
      end Leave;
      function Most return Natural is
      begin
         return Peak;
      end Most;
      function Visits return Natural is
      begin
         return Total;
      end Visits;
   end Room;

   task type Worker;
   task body Worker is
   begin
      for Round in 1 .. 3 loop
         S.Seize;
         Room.Enter;
         delay 0.002;
         Room.Leave;
         S.Release;
      end loop;
   end Worker;

   V : Integer;
   Last : array (1 .. 2) of Integer := (1000, 2000);
   In_Order : Boolean := True;
   Sum : Integer := 0;
begin
   declare
      Producers : array (1 .. 2) of Producer;
   begin
      Producers (1).Start (1);
      Producers (2).Start (2);
      for I in 1 .. 100 loop
         B.Get (V);
         Sum := Sum + V;
         if V / 1000 in 1 .. 2 then
            if V <= Last (V / 1000) then
               In_Order := False;
            end if;
            Last (V / 1000) := V;
         else
            In_Order := False;
         end if;
      end loop;
   end;
   Put_Line ("consumed sum" & Integer'Image (Sum));
   Put_Line ("each producer's items in order: " & Boolean'Image (In_Order));
   Put_Line ("last items" & Integer'Image (Last (1)) & Integer'Image (Last (2)));
   Put_Line ("fill within 1 .. size: " & Boolean'Image (B.Max_Fill in 1 .. Size));

   S.Set (2);
   declare
      Crew : array (1 .. 5) of Worker;
   begin
      null;
   end;
   Put_Line ("visits" & Integer'Image (Room.Visits));
   Put_Line ("never more than two inside: " & Boolean'Image (Room.Most in 1 .. 2));
end Task_Protected_Buffer;
