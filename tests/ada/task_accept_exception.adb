with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;

--  An exception raised in an accept body is raised both in the caller (at
--  the call) and in the server (at the accept statement). Handled inside
--  the accept body, it goes nowhere. Raised in a protected operation, it
--  goes to the caller. The server prints only inside rendezvous, so every
--  line is ordered by a rendezvous.
procedure Task_Accept_Exception is
   Bad_Value : exception;

   task Checker is
      entry Check (V : Integer);
      entry Report (Server_Saw : out Integer);
   end Checker;

   task body Checker is
      Caught : Integer := 0;
   begin
      for Round in 1 .. 3 loop
         begin
            accept Check (V : Integer) do
               begin
                  if V < 0 then
                     raise Bad_Value with "negative";
                  elsif V = 0 then
                     raise Constraint_Error with "zero, handled inside";
                  end if;
                  Put_Line ("Checker: value" & Integer'Image (V) & " ok");
               exception
                  when Constraint_Error =>
                     Put_Line ("Checker: handled zero inside the accept body");
               end;
            end Check;
         exception
            when Bad_Value =>
               Caught := Caught + 1;
         end;
      end loop;
      accept Report (Server_Saw : out Integer) do
         Server_Saw := Caught;
      end Report;
      --  Unhandled: the exception reaches the caller and ends this task.
      accept Check (V : Integer) do
         raise Program_Error with "server gives up";
      end Check;
   end Checker;

   protected Vault is
      procedure Store (V : Integer);
      function Content return Integer;
   private
      Value : Integer := 0;
   end Vault;

   protected body Vault is
      procedure Store (V : Integer) is
      begin
         if V > 99 then
            raise Bad_Value with "too big for the vault";
         end if;
         Value := V;
      end Store;
      function Content return Integer is
      begin
         return Value;
      end Content;
   end Vault;

   procedure Call (V : Integer) is
   begin
      Checker.Check (V);
      Put_Line ("Main: call with" & Integer'Image (V) & " returned");
   exception
      when E : Tasking_Error =>        --  GNAT's message names its runtime
         Put_Line ("Main: call with" & Integer'Image (V) & " raised "
                   & Exception_Name (E));
      when E : others =>
         Put_Line ("Main: call with" & Integer'Image (V) & " raised "
                   & Exception_Name (E) & " (" & Exception_Message (E) & ")");
   end Call;

   N : Integer;
begin
   Call (5);
   Call (-1);
   Call (0);
   Checker.Report (N);
   Put_Line ("Main: the server caught" & Integer'Image (N));
   Call (7);
   while not Checker'Terminated loop
      delay 0.001;
   end loop;
   Put_Line ("Main: Checker terminated: " & Boolean'Image (Checker'Terminated));
   Call (8);

   Vault.Store (42);
   begin
      Vault.Store (100);
   exception
      when E : Bad_Value =>
         Put_Line ("Main: Vault raised " & Exception_Name (E)
                   & " (" & Exception_Message (E) & ")");
   end;
   Put_Line ("Main: the vault still holds" & Integer'Image (Vault.Content));
end Task_Accept_Exception;
