--  A robot cell's 16-bit status register, as handbook appendix C reads
--  one: a modular type, so bits are set, cleared and tested with
--  `or`, `and` and `not`, and a cycle counter wraps around.
with Ada.Text_IO; use Ada.Text_IO;
procedure Modular_Register is
   type Word is mod 2**16;
   type Byte is mod 256;
   type Ring is mod 10;                   --  not a power of two
   subtype Low_Word is Word range 0 .. 16#FF#;
   type Long_Word is mod 2**32;           --  a 32-bit register

   Gripper_Closed : constant Word := 16#0001#;
   Part_Present   : constant Word := 16#0004#;
   Fault          : constant Word := 16#8000#;

   Status  : Word := 0;
   Counter : Byte := 250;
   Slot    : Ring := 7;
   History : array (1 .. 3) of Word := (others => 0);

   procedure Set (R : in out Word; Bits : Word) is
   begin
      R := R or Bits;
   end Set;

   procedure Clear (R : in out Word; Bits : Word) is
   begin
      R := R and not Bits;
   end Clear;

   function Is_Set (R : Word; Bits : Word) return Boolean is
   begin
      return (R and Bits) = Bits;
   end Is_Set;

   function Hex (W : Word) return String is
      Digits_Of : constant String := "0123456789ABCDEF";
      Result    : String (1 .. 4);
      V         : Word := W;
   begin
      for I in reverse Result'Range loop
         Result (I) := Digits_Of (Integer (V mod 16) + 1);
         V := V / 16;
      end loop;
      return "16#" & Result & "#";
   end Hex;

   Raw : Integer;
   Big : Long_Word := 16#FFFF_FFFF#;
   Small : Low_Word;
begin
   Set (Status, Gripper_Closed);
   Set (Status, Part_Present);
   Put_Line ("status " & Hex (Status));
   Put_Line ("gripper closed: " & Boolean'Image (Is_Set (Status, Gripper_Closed)));
   Clear (Status, Gripper_Closed);
   Put_Line ("after clear " & Hex (Status)
             & " gripper closed: " & Boolean'Image (Is_Set (Status, Gripper_Closed)));
   Status := Status xor Fault;
   Put_Line ("fault toggled " & Hex (Status) & " not: " & Hex (not Status));
   History (1) := Status;

   --  A cycle counter that wraps past its last value.
   for Cycle in 1 .. 8 loop
      Counter := Counter + 1;
   end loop;
   Put_Line ("counter" & Byte'Image (Counter));
   Counter := Counter - 3;
   Put_Line ("counter" & Byte'Image (Counter) & Byte'Image (-Counter));
   Put_Line ("byte product" & Byte'Image (Byte'(200) * 3) & Byte'Image (Byte'(3) ** 7));
   Put_Line ("slot" & Ring'Image (Slot + 5) & Ring'Image (not Slot)
             & Ring'Image (Slot xor 9) & Ring'Image (Ring'Succ (9)));

   Put_Line ("modulus" & Integer'Image (Word'Modulus) & Integer'Image (Byte'Modulus)
             & Integer'Image (Ring'Modulus));
   Put_Line ("range" & Word'Image (Word'First) & " .." & Word'Image (Word'Last));
   Put_Line ("wrap" & Word'Image (Word'Last + 1) & Word'Image (Word'First - 1));
   Put_Line ("value" & Word'Image (Word'Value ("4660")) & Integer'Image (Word'Pos (Fault)));
   History (2) := Word'Val (16#1234#);
   History (3) := History (1) / History (2) + History (2) rem 7 + History (2) mod 5;
   for I in History'Range loop
      Put (" " & Hex (History (I)));
   end loop;
   New_Line;
   for S in Ring'Range loop
      Put (Ring'Image (S * 3));
   end loop;
   New_Line;

   --  Checked conversions: an integer outside 0 .. Modulus - 1 raises.
   Raw := 70_000;
   begin
      Status := Word (Raw);
      Put_Line ("converted" & Word'Image (Status));
   exception
      when Constraint_Error =>
         Put_Line ("Word (70000) raised Constraint_Error");
   end;
   Raw := -1;
   begin
      Counter := Byte (Raw);
      Put_Line ("converted" & Byte'Image (Counter));
   exception
      when Constraint_Error =>
         Put_Line ("Byte (-1) raised Constraint_Error");
   end;
   Raw := 255;
   Counter := Byte (Raw);
   Put_Line ("Byte (255) =" & Byte'Image (Counter));
   begin
      Counter := Byte (Status);
      Put_Line ("converted" & Byte'Image (Counter));
   exception
      when Constraint_Error =>
         Put_Line ("Byte (Status) raised Constraint_Error");
   end;
   begin
      Small := Status;
      Put_Line ("small" & Word'Image (Small));
   exception
      when Constraint_Error =>
         Put_Line ("Low_Word := Status raised Constraint_Error");
   end;
   Small := 16#FF#;
   Raw := Integer (Small) + Integer (Word'Last);
   Put_Line ("back to Integer" & Integer'Image (Raw));
   begin
      Status := Status / (Status - Status);
   exception
      when Constraint_Error =>
         Put_Line ("division by zero raised Constraint_Error");
   end;
   Put_Line ("long" & Long_Word'Image (Big * Big) & Long_Word'Image (Big + 2)
             & Long_Word'Image (Big ** 5) & Long_Word'Image (not 0)
             & Long_Word'Image (Long_Word'Value ("4000000000")));
   begin
      Raw := Integer (Big);
      Put_Line ("converted" & Integer'Image (Raw));
   exception
      when Constraint_Error =>
         Put_Line ("Integer (Big) raised Constraint_Error");
   end;
   begin
      Put_Line (Word'Image (Word'Value ("65536")));
   exception
      when Constraint_Error =>
         Put_Line ("Word'Value (""65536"") raised Constraint_Error");
   end;
end Modular_Register;
