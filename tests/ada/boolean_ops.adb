with Ada.Text_IO; use Ada.Text_IO;

procedure Boolean_Ops is
   Calls : Natural := 0;
   function Probe (Result : Boolean) return Boolean is
   begin
      Calls := Calls + 1;
      return Result;
   end Probe;
   function Safe_Div (A, B : Integer) return Boolean is
   begin
      return B /= 0 and then A / B > 2;
   end Safe_Div;
   B : Boolean;
begin
   for A in Boolean loop
      for C in Boolean loop
         Put_Line (Boolean'Image (A) & " " & Boolean'Image (C)
                   & " and=" & Boolean'Image (A and C)
                   & " or=" & Boolean'Image (A or C)
                   & " xor=" & Boolean'Image (A xor C)
                   & " not A=" & Boolean'Image (not A)
                   & " A=C " & Boolean'Image (A = C)
                   & " A<C " & Boolean'Image (A < C));
      end loop;
   end loop;
   Calls := 0;
   B := Probe (False) and Probe (True);
   Put_Line ("and evaluates both: calls =" & Integer'Image (Calls) & " result " & Boolean'Image (B));
   Calls := 0;
   B := Probe (False) and then Probe (True);
   Put_Line ("and then short-circuits: calls =" & Integer'Image (Calls) & " result " & Boolean'Image (B));
   Calls := 0;
   B := Probe (True) or Probe (False);
   Put_Line ("or evaluates both: calls =" & Integer'Image (Calls) & " result " & Boolean'Image (B));
   Calls := 0;
   B := Probe (True) or else Probe (False);
   Put_Line ("or else short-circuits: calls =" & Integer'Image (Calls) & " result " & Boolean'Image (B));
   Calls := 0;
   B := Probe (False) or else Probe (True);
   Put_Line ("or else second: calls =" & Integer'Image (Calls) & " result " & Boolean'Image (B));
   Put_Line ("Safe_Div (10, 0) = " & Boolean'Image (Safe_Div (10, 0)));
   Put_Line ("Safe_Div (10, 3) = " & Boolean'Image (Safe_Div (10, 3)));
   Put_Line ("Safe_Div (10, 4) = " & Boolean'Image (Safe_Div (10, 4)));
   B := not Probe (True) xor Probe (True);
   Put_Line ("not T xor T = " & Boolean'Image (B));
   B := Probe (True) and Probe (True) and Probe (False);
   Put_Line ("T and T and F = " & Boolean'Image (B));
   B := Probe (False) or Probe (False) or Probe (True);
   Put_Line ("F or F or T = " & Boolean'Image (B));
   Put_Line ("True > False = " & Boolean'Image (Probe (True) > Probe (False)));
   Put_Line ("Boolean'Image (not B) = " & Boolean'Image (not B));
   Put_Line ("B'Image = " & B'Image);
end Boolean_Ops;
