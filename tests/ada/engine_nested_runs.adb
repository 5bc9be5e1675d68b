--  Code that runs inside one instruction: barriers (with a family index
--  and a call of a protected function), and the type table's expressions
--  (defaults, dynamic bounds, discriminant constraints) read in nested and
--  recursive scopes.
with Ada.Text_IO; use Ada.Text_IO;
procedure Engine_Nested_Runs is
   Limit : Integer := 2;

   protected Gate is
      entry Pass (1 .. 3);
      procedure Open (K : Integer);
      function Opened return Integer;
   private
      Level : Integer := 0;
   end Gate;

   protected body Gate is
      entry Pass (for I in 1 .. 3) when I <= Opened and then I <= Limit + 1 is
      begin
         Put_Line ("pass" & Integer'Image (I));
      end Pass;
      procedure Open (K : Integer) is
      begin
         Level := K;
      end Open;
      function Opened return Integer is
      begin
         return Level;
      end Opened;
   end Gate;

   task Runner;
   task body Runner is
   begin
      Gate.Pass (3);
      Gate.Pass (1);
   end Runner;

   Count : Integer := 0;

   function Next (Step : Integer) return Integer is
   begin
      Count := Count + Step;
      return Count;
   end Next;

   procedure Walk (Depth : Integer) is
      N : Integer := Depth * 2;
      type Row is array (1 .. N) of Integer;
      type Cell is record
         Id  : Integer := Next (Depth);
         Tag : String (1 .. Depth) := (others => Character'Val (64 + Depth));
      end record;
      subtype Len is Integer range 0 .. 20;
      type Shape (Size : Len := N + 1) is record
         Items : Row;
         Last  : String (1 .. Size);
      end record;
      R : Row := (others => Depth);
      C : Cell;
      S : Shape;
      subtype Small is Shape (Depth);
      T : Small;
   begin
      if Depth < 3 then
         Walk (Depth + 1);
      end if;
      Put_Line ("depth" & Integer'Image (Depth) & " row" & Integer'Image (R'Length)
                & " id" & Integer'Image (C.Id) & " tag " & C.Tag
                & " size" & Integer'Image (S.Size) & Integer'Image (S.Last'Length)
                & " small" & Integer'Image (T.Size) & Integer'Image (T.Items'Last));
   end Walk;
begin
   Walk (1);
   Gate.Open (1);
   delay 0.01;
   Gate.Open (3);
   delay 0.01;
   Put_Line ("count" & Integer'Image (Count));
end Engine_Nested_Runs;
