--  Assignments the compiled engine now makes itself: components of
--  records, elements of arrays of records, nested paths, slices, whole
--  arrays that slide into their target's bounds, through .all and through
--  an implicit dereference, and the checks each one makes.
with Ada.Text_IO; use Ada.Text_IO;
procedure Engine_Stores is
   type Point is record
      X, Y, Z : Integer;
   end record;
   type Path is array (1 .. 4) of Point;
   type Station is record
      Tag   : String (1 .. 4);
      Waypt : Path;
      Count : Natural;
   end record;
   type Cell is array (Positive range <>) of Station;
   type Station_Ref is access Station;
   type Node;
   type Node_Ref is access Node;
   type Node is record
      Id   : Integer;
      Next : Node_Ref;
   end record;

   Line : Cell (1 .. 3);
   S : Station_Ref := new Station;
   Head : Node_Ref := null;
   Buffer : String (1 .. 12) := (others => '.');
   Window : String (21 .. 24);
   K : Integer := 2;

   procedure Show (C : Cell) is
   begin
      for I in C'Range loop
         Put (C (I).Tag & ":" & Integer'Image (C (I).Count));
         for J in Path'Range loop
            Put (Integer'Image (C (I).Waypt (J).X + C (I).Waypt (J).Y * 10
                                + C (I).Waypt (J).Z * 100));
         end loop;
         New_Line;
      end loop;
   end Show;
begin
   for I in Line'Range loop
      Line (I).Tag := "ST0" & Character'Val (Character'Pos ('0') + I);
      Line (I).Count := 0;
      for J in Path'Range loop
         Line (I).Waypt (J) := (X => I, Y => J, Z => 0);
         Line (I).Waypt (J).Z := I + J;
      end loop;
   end loop;
   Line (K).Waypt (K + 1).Y := 7;
   Line (K + 1).Tag (4) := 'X';
   Line (1).Tag (2 .. 3) := "AB";
   Line (3).Count := Line (3).Count + Line (2).Waypt (3).Y;
   Show (Line);

   --  whole arrays slide into their target's bounds
   Window := Buffer (5 .. 8);
   Buffer (1 .. 4) := "ABCD";
   Buffer (3 .. 6) := Buffer (1 .. 4);
   Window (22 .. 23) := Buffer (5 .. 6);
   Put_Line (Buffer & " " & Window);
   begin
      Buffer (1 .. 3) := Window;
      Put_Line ("no length check?");
   exception
      when Constraint_Error => Put_Line ("length check caught");
   end;
   begin
      Line (K + 2).Count := 1;
      Put_Line ("no index check?");
   exception
      when Constraint_Error => Put_Line ("index check caught");
   end;

   --  through .all and implicit dereference
   S.all := Line (2);
   S.Tag := "HOME";
   S.Waypt (1).X := -1;
   S.all.Count := 42;
   Put_Line (S.Tag & Integer'Image (S.Count) & Integer'Image (S.Waypt (1).X)
             & " line:" & Line (2).Tag & Integer'Image (Line (2).Waypt (1).X));
   for I in 1 .. 4 loop
      Head := new Node'(Id => I, Next => Head);
   end loop;
   Head.Next.Id := 30;
   Head.Next.Next.all.Id := 20;
   declare
      P : Node_Ref := Head;
   begin
      while P /= null loop
         Put (Integer'Image (P.Id));
         P := P.Next;
      end loop;
      New_Line;
      P.Id := 5;
      Put_Line ("no access check?");
   exception
      when Constraint_Error => Put_Line ("null access caught");
   end;
end Engine_Stores;
