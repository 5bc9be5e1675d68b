with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;

--  A selective accept whose guards are all closed and that has no else
--  part raises Program_Error in the task executing it (here handled there
--  and reported by a rendezvous). With an else part it takes the else. A
--  closed delay or terminate alternative counts as closed too.
procedure Task_Program_Error is
   task Server is
      entry A;
      entry B;
      entry Result (Text : out String; Len : out Natural);
   end Server;

   task body Server is
      Open_A : Boolean := False;
      Open_B : Boolean := False;
      Msg : String (1 .. 40) := (others => ' ');
      L : Natural := 0;

      procedure Add (S : String) is
      begin
         Msg (L + 1 .. L + S'Length) := S;
         L := L + S'Length;
      end Add;
   begin
      begin
         select
            when Open_A => accept A;
         or
            when Open_B => accept B;
         end select;
         Add ("no error (wrong)");
      exception
         when E : Program_Error =>
            Add (Exception_Name (E));
      end;
      select
         when Open_A => accept A;
      or
         when Open_B => accept B;
      else
         Add (" else");
      end select;
      begin
         select
            when Open_A => accept A;
         or
            when Open_B => delay 0.01;
         end select;
         Add (" no error (wrong)");
      exception
         when Program_Error =>
            Add (" again");
      end;
      Open_B := True;
      select
         when Open_A => accept A;
      or
         when Open_B => accept B;
      end select;
      Add (" B");
      accept Result (Text : out String; Len : out Natural) do
         Text := Msg;
         Len := L;
      end Result;
   end Server;

   Text : String (1 .. 40);
   Len : Natural;
begin
   Server.B;
   Server.Result (Text, Len);
   Put_Line ("server says: " & Text (1 .. Len));
end Task_Program_Error;
