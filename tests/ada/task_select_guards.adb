with Ada.Text_IO; use Ada.Text_IO;

--  A bounded buffer written as a task: select with guarded accept
--  alternatives. A producer task puts 12 values; main takes them out and
--  prints them, so the printed order is the buffer's FIFO order. The buffer
--  also records the largest fill level it saw, which must stay within its
--  size whatever the timing.
procedure Task_Select_Guards is
   Size : constant := 3;

   task Buffer is
      entry Put (Item : in Integer);
      entry Get (Item : out Integer);
      entry Stats (Max_Fill : out Integer);
   end Buffer;

   task Producer;

   task body Buffer is
      Store : array (0 .. Size - 1) of Integer := (others => 0);
      Head, Count, Max_Seen : Integer := 0;
      Done : Boolean := False;
   begin
      while not Done loop
         select
            when Count < Size =>
               accept Put (Item : in Integer) do
                  Store ((Head + Count) mod Size) := Item;
               end Put;
               Count := Count + 1;
               if Count > Max_Seen then
                  Max_Seen := Count;
               end if;
         or
            when Count > 0 =>
               accept Get (Item : out Integer) do
                  Item := Store (Head);
               end Get;
               Head := (Head + 1) mod Size;
               Count := Count - 1;
         or
            when Count = 0 =>
               accept Stats (Max_Fill : out Integer) do
                  Max_Fill := Max_Seen;
               end Stats;
               Done := True;
         end select;
      end loop;
   end Buffer;

   task body Producer is
   begin
      for I in 1 .. 12 loop
         Buffer.Put (I * I);
      end loop;
   end Producer;

   V, Max : Integer;
   Sum : Integer := 0;
begin
   for I in 1 .. 12 loop
      Buffer.Get (V);
      Put (Integer'Image (V));
      Sum := Sum + V;
   end loop;
   New_Line;
   Put_Line ("sum" & Integer'Image (Sum));
   Buffer.Stats (Max);
   Put_Line ("fill stayed within size: " & Boolean'Image (Max >= 1 and Max <= Size));
end Task_Select_Guards;
