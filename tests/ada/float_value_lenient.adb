with Ada.Text_IO; use Ada.Text_IO;
procedure Float_Value_Lenient is
   procedure T (S : String) is
   begin
      Put_Line ("[" & S & "] =" & Float'Image (Float'Value (S)));
   exception
      when Constraint_Error => Put_Line ("[" & S & "] Constraint_Error");
   end T;
begin
   T (".5"); T ("5."); T ("-.5"); T ("5.e2"); T (".5e1"); T ("+.25"); T ("."); T ("-."); T ("e5"); T (".e5"); T ("1.5"); T ("7"); T ("16#A.8#"); T ("16#.8#"); T ("1..5");
end Float_Value_Lenient;
