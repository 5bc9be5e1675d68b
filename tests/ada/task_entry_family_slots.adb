with Ada.Text_IO; use Ada.Text_IO;

--  A pallet with four slots. The loader task accepts one fill per slot,
--  in slot order (a loop of accepts over the family index Fill (1 .. 4));
--  a protected rack keeps the parts, one entry per slot whose barrier
--  reads the index (Take (for S in Slot) when Full (S)). A slot number
--  outside the family is Constraint_Error at the call, for the task's
--  entry and for the protected one.
procedure Task_Entry_Family_Slots is
   Slots : constant := 4;
   subtype Slot is Integer range 1 .. Slots;
   type Flags is array (Slot) of Boolean;
   type Codes is array (Slot) of Natural;

   protected Rack is
      procedure Put (S : Slot; Code : Natural);
      entry Take (Slot) (Code : out Natural);
      function Waiting (S : Slot) return Natural;
   private
      Full : Flags := (others => False);
      Part : Codes := (others => 0);
   end Rack;

   protected body Rack is
      procedure Put (S : Slot; Code : Natural) is
      begin
         Full (S) := True;
         Part (S) := Code;
      end Put;

      entry Take (for S in Slot) (Code : out Natural) when Full (S) is
      begin
         Code := Part (S) + S * 1000;
         Full (S) := False;
      end Take;

      function Waiting (S : Slot) return Natural is
      begin
         return Take (S)'Count;
      end Waiting;
   end Rack;

   task Loader is
      entry Fill (1 .. Slots) (Code : in Natural);
   end Loader;

   task body Loader is
   begin
      for S in 1 .. Slots loop
         accept Fill (S) (Code : in Natural) do
            Put_Line ("slot" & Integer'Image (S) & " filled with" & Natural'Image (Code));
            Rack.Put (S, Code);
         end Fill;
      end loop;
   end Loader;

   task type Picker is
      entry Start (S : Slot);
   end Picker;

   task body Picker is
      Mine : Slot;
      Code : Natural;
   begin
      accept Start (S : Slot) do
         Mine := S;
      end Start;
      Rack.Take (Mine) (Code);
      Put_Line ("picked" & Natural'Image (Code) & " from slot" & Integer'Image (Mine));
   end Picker;

   Pickers : array (Slot) of Picker;
   Bad : Integer := Slots + 1;
   Code : Natural;
begin
   --  Pickers wait at slots 3 and 1.
   Pickers (3).Start (3);
   Pickers (1).Start (1);
   delay 0.1;
   Put_Line ("waiting at slots:" & Natural'Image (Rack.Waiting (1))
             & Natural'Image (Rack.Waiting (2)) & Natural'Image (Rack.Waiting (3)));
   --  The loader takes slot 1 first: a call for slot 2 now times out.
   select
      Loader.Fill (2) (20);
      Put_Line ("slot 2 filled early");
   or
      delay 0.2;
      Put_Line ("slot 2 not ready yet");
   end select;
   select
      Loader.Fill (3) (30);
   else
      Put_Line ("slot 3 not ready yet");
   end select;
   begin
      Loader.Fill (Bad) (50);
      Put_Line ("slot 5 filled?");
   exception
      when Constraint_Error =>
         Put_Line ("no slot" & Integer'Image (Bad) & " on the loader: Constraint_Error");
   end;
   for S in Slot loop
      Loader.Fill (S) (S * 10 + 1);
      delay 0.1;
   end loop;
   Pickers (2).Start (2);
   Pickers (4).Start (4);
   delay 0.1;
   Rack.Put (2, 7);
   Rack.Take (2) (Code);
   Put_Line ("main picked" & Natural'Image (Code) & " from slot 2");
   Rack.Take (Bad) (Code);
   Put_Line ("slot 5 taken?");
exception
   when Constraint_Error =>
      Put_Line ("no slot" & Integer'Image (Bad) & " in the rack: Constraint_Error");
end Task_Entry_Family_Slots;
