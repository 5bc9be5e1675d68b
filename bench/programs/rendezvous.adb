--  10,000 rendezvous between two tasks (issue 10's figure): the main
--  program calls the server's entry 10,000 times with an `in out` value.
with Ada.Text_IO; use Ada.Text_IO;
procedure Rendezvous is
   N : constant := 10_000;
   task Server is
      entry Add (X : in out Integer);
   end Server;
   task body Server is
   begin
      for I in 1 .. N loop
         accept Add (X : in out Integer) do
            X := X + 1;
         end Add;
      end loop;
   end Server;
   V : Integer := 0;
begin
   for I in 1 .. N loop
      Server.Add (V);
   end loop;
   Put_Line (Integer'Image (V));
end Rendezvous;
