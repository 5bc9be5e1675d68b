with Ada.Text_IO; use Ada.Text_IO;

--  Entry calls whose out and in out parameters are components, elements
--  and slices of the caller's data: a tool-changer task hands out tools,
--  a protected rack lends slots (through a requeue), and a value that does
--  not fit the actual's subtype raises Constraint_Error in the caller
--  after the rendezvous (RM 6.4.1(17), 9.5.4).
procedure Task_Entry_Out_Actuals is
   subtype Slot_No is Integer range 1 .. 8;
   type Tool is record
      Name : String (1 .. 4);
      Slot : Integer;
      Wear : Integer;
   end record;
   type Tool_Array is array (1 .. 3) of Tool;
   type Tool_Ref is access Tool;

   task Changer is
      entry Hand_Out (T : out Tool; Code : in out String);
      entry Slot_Of (N : Integer; S : out Integer);
   end Changer;

   task body Changer is
      Count : Integer := 0;
   begin
      for I in 1 .. 3 loop
         accept Hand_Out (T : out Tool; Code : in out String) do
            Count := Count + 1;
            T := ("T00" & Character'Val (Character'Pos ('0') + Count), Count, Count * 10);
            Code (Code'First) := 'X';
         end Hand_Out;
      end loop;
      accept Slot_Of (N : Integer; S : out Integer) do
         S := N * 3;
      end Slot_Of;
   end Changer;

   protected Rack is
      entry Lend (S : out Integer; Label : in out String);
      entry Later (S : out Integer; Label : in out String);
   private
      Free : Integer := 4;
   end Rack;

   protected body Rack is
      entry Lend (S : out Integer; Label : in out String) when True is
      begin
         requeue Later;
      end Lend;
      entry Later (S : out Integer; Label : in out String) when Free > 0 is
      begin
         S := Free;
         Free := Free - 1;
         Label (Label'Last) := '!';
      end Later;
   end Rack;

   Tools : Tool_Array := (others => ("----", 0, 0));
   Spare : Tool_Ref := new Tool'("none", 0, 0);
   Codes : String (1 .. 6) := "abcdef";
   Slots : array (1 .. 2) of Integer := (0, 0);
   Kept : Slot_No := 5;
begin
   Changer.Hand_Out (Tools (2), Codes (2 .. 3));
   Changer.Hand_Out (Spare.all, Codes (5 .. 6));
   Changer.Hand_Out (Tools (3), Codes (1 .. 1));
   Put_Line (Tools (2).Name & Integer'Image (Tools (2).Wear) & " " & Spare.Name
             & Integer'Image (Tools (3).Slot) & " " & Codes);
   Rack.Lend (Slots (2), Codes (3 .. 4));
   Rack.Lend (Tools (1).Wear, Tools (1).Name);
   Put_Line (Integer'Image (Slots (2)) & Integer'Image (Tools (1).Wear) & " "
             & Tools (1).Name & " " & Codes);
   begin
      Changer.Slot_Of (4, Kept);
      Put_Line ("kept" & Integer'Image (Kept));
   exception
      when Constraint_Error =>
         Put_Line ("slot 12 does not fit; kept" & Integer'Image (Kept));
   end;
end Task_Entry_Out_Actuals;
