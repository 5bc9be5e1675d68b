with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;

procedure Null_Access is
   type Cell is record
      Key   : Integer := 0;
      Count : Integer := 1;
   end record;
   type Cell_Ptr is access Cell;
   type Int_Ptr is access Integer;
   C : Cell_Ptr;
   D : Cell_Ptr := new Cell;
   N : constant Int_Ptr := new Integer'(41);
   M : Int_Ptr;
   function Value_Of (P : Int_Ptr) return Integer is
   begin
      return P.all;
   end Value_Of;
   function Get (P : Cell_Ptr) return Integer is
   begin
      return P.Key;
   end Get;
begin
   Put_Line ("C = null: " & Boolean'Image (C = null));
   Put_Line ("D.Key =" & Integer'Image (D.Key) & " D.Count =" & Integer'Image (D.Count));
   N.all := N.all + 1;
   Put_Line ("N.all =" & Integer'Image (N.all));
   M := N;
   M.all := 7;
   Put_Line ("N.all after M.all := 7:" & Integer'Image (N.all));
   M := new Integer'(N.all * 3);
   Put_Line ("M.all =" & Integer'Image (M.all) & " N.all =" & Integer'Image (N.all));
   begin
      Put_Line ("Get (C) =" & Integer'Image (Get (C)));
   exception
      when E : Constraint_Error =>
         Put_Line ("Get (null) raised " & Exception_Name (E));
   end;
   begin
      C.all := (Key => 1, Count => 2);
      Put_Line ("not reached");
   exception
      when Constraint_Error =>
         Put_Line ("C.all := ... raised Constraint_Error");
   end;
   C := new Cell'(Key => 5, Count => 6);
   Put_Line ("Get (C) =" & Integer'Image (Get (C)));
   D := C;
   C := null;
   Put_Line ("D.Count =" & Integer'Image (D.Count) & " C = null: " & Boolean'Image (C = null));
   M := null;
   begin
      N.all := Value_Of (M);
      Put_Line ("not reached");
   exception
      when others =>
         Put_Line ("M.all raised, N.all still" & Integer'Image (N.all));
   end;
end Null_Access;
