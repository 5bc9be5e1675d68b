--  A component's default, and an aggregate's expression for a range of
--  components, are evaluated once per component (RM 3.3.1, 4.3.3(23)).
with Ada.Text_IO; use Ada.Text_IO;
procedure Each_Component_Evaluated is
   Count : Integer := 0;
   function Next return Integer is
   begin
      Count := Count + 1;
      return Count;
   end Next;
   type Inner is record
      V : Integer := Next;
   end record;
   type Arr is array (1 .. 3) of Inner;
   X : Arr;
   type IP is access Integer;
   type Cell is record
      P : IP := new Integer'(0);
   end record;
   R : array (1 .. 2) of Cell;
   type Vec is array (1 .. 4) of Integer;
   V : Vec := (1 .. 2 => Next, 3 => 0, 4 => Next);
   W : Vec := (1 | 3 => Next, others => 0);
begin
   Put_Line (Integer'Image (X (1).V) & Integer'Image (X (2).V) & Integer'Image (X (3).V));
   R (1).P.all := 5;
   Put_Line (Integer'Image (R (1).P.all) & Integer'Image (R (2).P.all));
   for I in V'Range loop
      Put (Integer'Image (V (I)));
   end loop;
   New_Line;
   for I in W'Range loop
      Put (Integer'Image (W (I)));
   end loop;
   New_Line;
   Put_Line ("calls" & Integer'Image (Count));
end Each_Component_Evaluated;
