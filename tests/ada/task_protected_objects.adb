with Ada.Text_IO; use Ada.Text_IO;

--  Protected objects: a single protected counter with a procedure and a
--  function, shared by four tasks (10,000 increments, none lost); a
--  protected type with an entry whose barrier opens a gate, E'Count in a
--  function and in the entry body, and the rule that calls already queued
--  on an open entry are served before anybody else gets in.
procedure Task_Protected_Objects is
   protected Counter is
      procedure Increment (By : Integer := 1);
      function Value return Integer;
   private
      Total : Integer := 0;
   end Counter;

   protected body Counter is
      procedure Increment (By : Integer := 1) is
      begin
         Total := Total + By;
      end Increment;
      function Value return Integer is
      begin
         return Total;
      end Value;
   end Counter;

   protected type Gate is
      entry Wait (Ticket : out Integer);
      procedure Open_Gate;
      function Waiting return Natural;
      function Passed return Natural;
      function Is_Open return Boolean;
   private
      Open : Boolean := False;
      Through : Natural := 0;
   end Gate;

   protected body Gate is
      entry Wait (Ticket : out Integer) when Open is
      begin
         Through := Through + 1;
         Ticket := Through;
         if Wait'Count = 0 then
            Open := False;       --  the last queued caller shuts the gate
         end if;
      end Wait;
      procedure Open_Gate is
      begin
         Open := True;
      end Open_Gate;
      function Waiting return Natural is
      begin
         return Wait'Count;
      end Waiting;
      function Passed return Natural is
      begin
         return Through;
      end Passed;
      function Is_Open return Boolean is
      begin
         return Open;
      end Is_Open;
   end Gate;

   G : Gate;

   task type Adder;
   task body Adder is
   begin
      for I in 1 .. 2500 loop
         Counter.Increment;
      end loop;
   end Adder;

   task type Visitor;
   task body Visitor is
      T : Integer;
   begin
      G.Wait (T);
      Counter.Increment (By => T * 100_000);
   end Visitor;

begin
   declare
      Adders : array (1 .. 4) of Adder;
   begin
      null;
   end;                                   --  all four adders are done here
   Put_Line ("counter after 4 x 2500:" & Integer'Image (Counter.Value));

   declare
      Visitors : array (1 .. 3) of Visitor;
   begin
      while G.Waiting < 3 loop
         delay 0.001;
      end loop;
      Put_Line ("waiting at the gate:" & Integer'Image (G.Waiting));
      Put_Line ("open: " & Boolean'Image (G.Is_Open));
      G.Open_Gate;
      --  The three queued calls were served inside Open_Gate's protected
      --  action, before this task could call again: the gate is shut.
      Put_Line ("passed:" & Integer'Image (G.Passed)
                & ", waiting:" & Integer'Image (G.Waiting)
                & ", open: " & Boolean'Image (G.Is_Open));
   end;
   --  Tickets 1, 2 and 3 were handed out: 600,000 more.
   Put_Line ("counter after visitors:" & Integer'Image (Counter.Value));
end Task_Protected_Objects;
