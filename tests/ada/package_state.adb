with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;

procedure Package_State is
   package Stack is
      Capacity : constant := 5;
      Overflow, Underflow : exception;
      procedure Push (V : Integer);
      function Pop return Integer;
      function Size return Natural;
   end Stack;

   package body Stack is
      Data : array (1 .. Capacity) of Integer;
      Top  : Natural := 0;
      procedure Push (V : Integer) is
      begin
         if Top = Capacity then
            raise Overflow with "stack full at" & Integer'Image (V);
         end if;
         Top := Top + 1;
         Data (Top) := V;
      end Push;
      function Pop return Integer is
      begin
         if Top = 0 then
            raise Underflow;
         end if;
         Top := Top - 1;
         return Data (Top + 1);
      end Pop;
      function Size return Natural is
      begin
         return Top;
      end Size;
   end Stack;

   use Stack;
begin
   Put_Line ("Capacity:" & Integer'Image (Stack.Capacity));
   for I in 1 .. 7 loop
      begin
         Push (I * 3);
         Put_Line ("pushed" & Integer'Image (I * 3) & ", size" & Integer'Image (Size));
      exception
         when E : Overflow =>
            Put_Line (Exception_Name (E) & ": " & Exception_Message (E));
      end;
   end loop;
   while Stack.Size > 2 loop
      Put_Line ("popped" & Integer'Image (Pop));
   end loop;
   Push (100);
   Put_Line ("size" & Integer'Image (Size));
   begin
      loop
         Put_Line ("pop" & Integer'Image (Stack.Pop));
      end loop;
   exception
      when E : Stack.Underflow =>
         Put_Line ("empty: " & Exception_Name (E));
   end;
end Package_State;
