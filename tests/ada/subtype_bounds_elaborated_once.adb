--  Bounds that are not static are evaluated once, when their declaration
--  is elaborated (RM 3.2.2), not at each check against the subtype.
with Ada.Text_IO; use Ada.Text_IO;
procedure Subtype_Bounds_Elaborated_Once is
   Hi : Integer := 5;
   Calls : Integer := 0;
   function Top return Integer is
   begin
      Calls := Calls + 1;
      return 3;
   end Top;
   subtype S is Integer range 1 .. Hi;
   subtype T is Integer range 1 .. Top;
   type Arr is array (1 .. Hi) of Integer;
   A : Arr := (others => 0);
   N : Integer range 1 .. Hi := 4;
   Name : String (1 .. Hi) := "abcde";
   type R is record
      S : String (1 .. Hi);
      K : Integer range 0 .. Hi;
   end record;
   RX : R;
   procedure Nested is
      W : S := 5;
   begin
      Put_Line ("nested S'Last =" & Integer'Image (S'Last) & Integer'Image (W));
   end Nested;
begin
   Hi := 10;
   Put_Line ("S'Last =" & Integer'Image (S'Last));
   Put_Line ("Arr'Last =" & Integer'Image (Arr'Last) & Integer'Image (A'Length));
   Put_Line ("Name'Length =" & Integer'Image (Name'Length) & " " & Name);
   declare
      X : T := 2;
      Y : T := 3;
   begin
      Put_Line ("calls =" & Integer'Image (Calls) & Integer'Image (X + Y));
   end;
   Nested;
   begin
      N := 7;
      Put_Line ("N accepted 7");
   exception
      when Constraint_Error => Put_Line ("N: Constraint_Error");
   end;
   begin
      declare
         Z : S := 7;
      begin
         Put_Line ("Z accepted" & Integer'Image (Z));
      end;
   exception
      when Constraint_Error => Put_Line ("Z: Constraint_Error");
   end;
   declare
      B : Arr;
   begin
      Put_Line ("B'Length =" & Integer'Image (B'Length));
   end;
   declare
      RY : R;
   begin
      Put_Line ("R.S'Length =" & Integer'Image (RX.S'Length) & Integer'Image (RY.S'Length));
      RY.K := 7;
      Put_Line ("K accepted 7");
   exception
      when Constraint_Error => Put_Line ("K: Constraint_Error");
   end;
   for I in 1 .. 2 loop
      declare
         subtype U is Integer range 1 .. Hi + I;
      begin
         Hi := Hi + 100;
         Put_Line ("U'Last =" & Integer'Image (U'Last));
      end;
   end loop;
end Subtype_Bounds_Elaborated_Once;
