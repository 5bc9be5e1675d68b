with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;
with Ada.Numerics.Elementary_Functions; use Ada.Numerics.Elementary_Functions;

--  RM A.5.1: an argument outside a function's domain raises
--  Argument_Error, a pole of the function Constraint_Error.
procedure Elementary_Function_Errors is
   Z : Float := 0.0;
   One : Float := 1.0;
   R : Float;
   procedure Try (Label : String; Which : Integer) is
   begin
      case Which is
         when 1 => R := Arctan (Z, Z);
         when 2 => R := Z ** (-2.0);
         when 3 => R := Log (Z, 10.0);
         when 4 => R := Cot (Z);
         when 5 => R := Log (Z);
         when 6 => R := (-One) ** 0.5;
         when 7 => R := Z ** Z;
         when 8 => R := Log (One, One);
         when 9 => R := Arctan (One, Z);
         when others => R := Z ** 2.0;
      end case;
      Put_Line (Label & " =" & Float'Image (R));
   exception
      when E : others =>
         Put_Line (Label & " raises " & Exception_Name (E));
   end Try;
begin
   Try ("Arctan (0.0, 0.0)", 1);
   Try ("0.0 ** (-2.0)", 2);
   Try ("Log (0.0, 10.0)", 3);
   Try ("Cot (0.0)", 4);
   Try ("Log (0.0)", 5);
   Try ("(-1.0) ** 0.5", 6);
   Try ("0.0 ** 0.0", 7);
   Try ("Log (1.0, 1.0)", 8);
   Try ("Arctan (1.0, 0.0)", 9);
   Try ("0.0 ** 2.0", 10);
end Elementary_Function_Errors;
