with Ada.Text_IO; use Ada.Text_IO;

--  E'Count: the server waits (polling its own entry's count) until three
--  callers are queued, then serves them one by one and prints the count
--  after each rendezvous. The callers' identities are not printed: the
--  order in which they queue is up to the scheduler.
procedure Task_Entry_Count is
   task Server is
      entry Request (Id : Integer);
      entry Report (Count_Before, Total : out Integer);
   end Server;

   task type Client is
      entry Start (Id : Integer);
   end Client;

   task body Server is
      Sum : Integer := 0;
      Before : Integer := 0;
   begin
      while Request'Count < 3 loop
         delay 0.001;
      end loop;
      Before := Request'Count;
      for I in 1 .. 3 loop
         accept Request (Id : Integer) do
            Sum := Sum + Id;
         end Request;
         Put_Line ("served one, still queued:" & Integer'Image (Request'Count));
      end loop;
      accept Report (Count_Before, Total : out Integer) do
         Count_Before := Before;
         Total := Sum;
      end Report;
   end Server;

   task body Client is
      My_Id : Integer;
   begin
      accept Start (Id : Integer) do
         My_Id := Id;
      end Start;
      Server.Request (My_Id);
   end Client;

   Clients : array (1 .. 3) of Client;
   C, S : Integer;
begin
   for I in Clients'Range loop
      Clients (I).Start (I * 10);
   end loop;
   Server.Report (C, S);
   Put_Line ("queued at once:" & Integer'Image (C));
   Put_Line ("sum of ids:" & Integer'Image (S));
end Task_Entry_Count;
