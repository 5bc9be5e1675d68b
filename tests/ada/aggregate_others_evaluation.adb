with Ada.Text_IO; use Ada.Text_IO;
procedure Aggregate_Others_Evaluation is
   Count : Integer := 0;
   function Next return Integer is
   begin
      Count := Count + 1;
      return Count;
   end Next;
   type Vec is array (1 .. 5) of Integer;
   type Mat is array (1 .. 3, 1 .. 2) of Integer;
   type Ptr is access Integer;
   type Ptrs is array (1 .. 3) of Ptr;
   V : Vec := (others => Next);
   W : Vec := (1 => 10, others => Next);
   M : Mat := (others => (others => Next));
   Z : Mat := (others => (others => 7));
   P : Ptrs := (others => new Integer'(0));
   Q : Ptrs := (1 => null, others => new Integer'(1));
begin
   for I in V'Range loop
      Put (Integer'Image (V (I)));
   end loop;
   New_Line;
   for I in W'Range loop
      Put (Integer'Image (W (I)));
   end loop;
   New_Line;
   for I in 1 .. 3 loop
      for J in 1 .. 2 loop
         Put (Integer'Image (M (I, J)) & Integer'Image (Z (I, J)));
      end loop;
   end loop;
   New_Line;
   P (1).all := 5;
   Q (2).all := 6;
   --  Each component designates an object of its own.
   Put_Line (Integer'Image (P (2).all) & Integer'Image (P (3).all) & Integer'Image (Q (3).all));
   Put_Line (Integer'Image (Count));
end Aggregate_Others_Evaluation;
