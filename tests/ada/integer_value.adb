with Ada.Text_IO; use Ada.Text_IO;

procedure Integer_Value is
   procedure Try (S : String) is
      N : Integer;
   begin
      N := Integer'Value (S);
      Put_Line ("Value (""" & S & """) =" & Integer'Image (N));
   exception
      when Constraint_Error =>
         Put_Line ("Value (""" & S & """) raised Constraint_Error");
   end Try;
begin
   Try ("42");
   Try ("-42");
   Try ("   17");
   Try ("17   ");
   Try ("  -5  ");
   Try ("+8");
   Try ("1_000_000");
   Try ("0007");
   Try ("-0012");
   Try ("0");
   Try ("2147483647");
   Try ("-2147483648");
   Try ("2147483648");
   Try ("12a");
   Try ("");
   Try ("1__0");
   Try ("_1");
   Try ("- 5");
   Try ("1.5");
   Try ("3e2");
   Try ("16#FF#");
   Put_Line ("Sum:" & Integer'Image (Integer'Value ("10") + Integer'Value (" 20 ")));
   Put_Line ("Round trip:" & Integer'Image (Integer'Value (Integer'Image (-99))));
   Put_Line ("Positive'Value:" & Positive'Image (Positive'Value ("5")));
   begin
      Put_Line ("Positive'Value (0):" & Positive'Image (Positive'Value ("0")));
   exception
      when Constraint_Error =>
         Put_Line ("Positive'Value (0) raised Constraint_Error");
   end;
end Integer_Value;
