with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;
procedure Value_Errors is
   procedure Show (E : Exception_Occurrence) is
   begin
      Put_Line (Exception_Name (E) & ": [" & Exception_Message (E) & "]");
   end Show;
   I : Integer := 0;
   F : Float := 0.0;
   B : Boolean := False;
   C : Character := 'a';
   type Color is (Red, Green);
   K : Color := Red;
   Big : Float := 1.0E20;
   Neg : Float := -3.0E10;
begin
   begin I := Integer'Value ("12x"); exception when E : others => Show (E); end;
   begin I := Integer'Value ("99999999999"); exception when E : others => Show (E); end;
   begin I := Integer'Value (""); exception when E : others => Show (E); end;
   begin I := Integer'Value ("  7 "); Put_Line (Integer'Image (I)); exception when E : others => Show (E); end;
   begin F := Float'Value ("abc"); exception when E : others => Show (E); end;
   begin B := Boolean'Value ("maybe"); exception when E : others => Show (E); end;
   begin C := Character'Value ("ab"); exception when E : others => Show (E); end;
   begin K := Color'Value ("Blue"); exception when E : others => Show (E); end;
   begin I := Integer (Big); exception when E : others => Show (E); end;
   begin I := Integer (Neg); exception when E : others => Show (E); end;
   declare
      subtype Small is Integer range 1 .. 10;
      S : Small := 1;
   begin
      S := Small (F + 20.0);
   exception when E : others => Show (E);
   end;
end Value_Errors;
