--  A controller's register banks as protected objects (RM 9.4, 3.7): the
--  bank's discriminants size its storage (a default of 4 registers) and
--  choose its bus; they are read inside the operations, in a component's
--  default and from outside. Banks of other sizes: constrained objects,
--  an array of them, allocators; an index past the bank's size raises
--  Constraint_Error inside the protected operation.
with Ada.Text_IO; use Ada.Text_IO;
procedure Protected_Discriminant_Registers is
   type Bus_Kind is (Local, Fieldbus, Serial);
   type Word is mod 2**16;
   type Word_Array is array (Natural range <>) of Word;

   protected type Register_Bank (Count : Positive := 4; Bus : Bus_Kind := Local) is
      procedure Write (Index : Natural; Value : Word);
      function Read (Index : Natural) return Word;
      function Describe return String;
      function Sum return Word;
   private
      Regs : Word_Array (1 .. Count) := (others => 16#FF#);
      Writes : Natural := Count * 10;
   end Register_Bank;

   protected body Register_Bank is
      procedure Write (Index : Natural; Value : Word) is
      begin
         Regs (Index) := Value;
         Writes := Writes + 1;
      end Write;
      function Read (Index : Natural) return Word is
      begin
         return Regs (Index);
      end Read;
      function Describe return String is
      begin
         case Bus is
            when Local => return "local bank of" & Positive'Image (Count)
                 & ", writes" & Natural'Image (Writes);
            when Fieldbus => return "fieldbus bank of" & Positive'Image (Regs'Length);
            when Serial => return "serial bank at" & Natural'Image (Regs'Last);
         end case;
      end Describe;
      function Sum return Word is
         S : Word := 0;
      begin
         for R of Regs loop
            S := S + R;
         end loop;
         return S;
      end Sum;
   end Register_Bank;

   type Bank_Ref is access Register_Bank;

   Io : Register_Bank;
   Drive : Register_Bank (8, Fieldbus);
   Probe : Register_Bank (Bus => Serial, Count => 2);
   Racks : array (1 .. 2) of Register_Bank (Count => 3, Bus => Local);
   Remote : constant Bank_Ref := new Register_Bank (Count => 16, Bus => Fieldbus);
   Default : constant Bank_Ref := new Register_Bank;
begin
   Put_Line (Io.Describe);
   Put_Line (Drive.Describe);
   Put_Line (Probe.Describe);
   Put_Line (Remote.Describe & " /" & Positive'Image (Remote.Count) & " "
             & Bus_Kind'Image (Remote.Bus));
   Put_Line (Default.Describe);
   for I in 1 .. Io.Count loop
      Io.Write (I, Word (I * 1000));
   end loop;
   Put_Line (Io.Describe & ", sum" & Word'Image (Io.Sum));
   Drive.Write (8, 16#FFFF#);
   Drive.Write (6, 2);
   Put_Line ("drive sum" & Word'Image (Drive.Sum) & ", reg 8" & Word'Image (Drive.Read (8)));
   for R in Racks'Range loop
      Racks (R).Write (Racks (R).Count, Word (R));
      Put_Line ("rack" & Integer'Image (R) & ": " & Racks (R).Describe
                & ", sum" & Word'Image (Racks (R).Sum));
   end loop;
   begin
      Probe.Write (3, 1);
      Put_Line ("probe took register 3?");
   exception
      when Constraint_Error => Put_Line ("probe has registers 1 .. 2 only");
   end;
   Put_Line (Probe.Describe & ", sum" & Word'Image (Probe.Sum));
end Protected_Discriminant_Registers;
