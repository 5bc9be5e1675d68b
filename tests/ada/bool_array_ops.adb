--  and, or, xor and not on one-dimensional Boolean arrays, component by
--  component (a 16-bit register as the handbook's t_16_bit, masked).
with Ada.Text_IO; use Ada.Text_IO;
procedure Bool_Array_Ops is
   type Bools is array (1 .. 4) of Boolean;
   type Word is array (0 .. 15) of Boolean;
   Bs : Bools := (True, False, True, False);
   W : Word := (others => False);
   M : Word := (0 .. 7 => True, others => False);
   procedure Show (X : Bools) is
   begin
      for B of X loop
         Put (if B then "1" else "0");
      end loop;
      New_Line;
   end Show;
   Ok : Boolean := True;
begin
   Show (Bs);
   Bs := not Bs;
   Show (Bs);
   Show (Bs and (True, True, False, False));
   Show (Bs or (True, False, False, False));
   Show (Bs xor (True, True, True, True));
   W := (W or M) and not Word'(0 => True, others => False);
   Put_Line (Boolean'Image (W (0)) & Boolean'Image (W (1)) & Boolean'Image (W (8)));
   Ok := not Ok and True;
   Put_Line (Boolean'Image (Ok));
   Show (Bs (1 .. 4) and Bs);
end Bool_Array_Ops;
