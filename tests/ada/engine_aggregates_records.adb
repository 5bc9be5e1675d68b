with Ada.Text_IO; use Ada.Text_IO;

--  Aggregates and allocators of a robot cell's data: tags with strings,
--  station tables, a 2-D pallet, requests on a list. Choices whose value
--  calls a function are evaluated once per component (RM 4.3.3(23)).
procedure Engine_Aggregates_Records is
   subtype Length is Natural range 0 .. 16;
   type Tag (Len : Length := 4) is record
      Name : String (1 .. Len);
      Slot : Integer := 0;
   end record;

   type Request;
   type Request_Ref is access Request;
   type Request is record
      Id   : Integer;
      Part : String (1 .. 4);
      Next : Request_Ref;
   end record;

   type Table is array (Positive range <>) of Integer;
   type Pallet is array (1 .. 2, 1 .. 3) of Character;
   type Station is record
      Name  : String (1 .. 3);
      Axes  : Table (1 .. 3);
      Ready : Boolean;
   end record;
   type Stations is array (1 .. 2) of Station;
   subtype Table5 is Table (1 .. 5);
   subtype Table6 is Table (1 .. 6);

   Serial : Integer := 0;
   function Next_Serial return Integer is
   begin
      Serial := Serial + 1;
      return Serial * 10;
   end Next_Serial;

   function Part_Name (I : Integer) return String is
      S : String (1 .. 4) := "P000";
   begin
      S (4) := Character'Val (Character'Pos ('0') + I mod 10);
      return S;
   end Part_Name;

   procedure Show (T : Table) is
   begin
      for I in T'Range loop
         Put (Integer'Image (T (I)));
      end loop;
      New_Line;
   end Show;

   N : Natural := 5;
   Head : Request_Ref := null;
   Tags : array (1 .. 2) of Tag;
   P : Pallet := (('a', 'b', 'c'), (others => 'x'));
   Cell : Stations :=
     ((Name => "gr1", Axes => (1, 2, 3), Ready => True),
      (Name => "gr2", Axes => (others => Next_Serial), Ready => False));
   Long : Tag := (Len => 6, Name => "WELDER", Slot => 3);
begin
   Show (Table5'(1, 2, others => N));
   Show (Table6'(1 .. 2 => Next_Serial, 4 => N, others => Next_Serial));
   Show (Table'(1 .. N => Next_Serial));
   Show (Table'(3 .. 4 => 7));
   Show (Cell (2).Axes);
   Put_Line (Cell (1).Name & " " & Boolean'Image (Cell (1).Ready));
   Put_Line (P (1, 2) & P (2, 3));
   Tags := ((Len => 4, Name => "GRIP", Slot => 1), (Len => 4, Name => Part_Name (7), Slot => 2));
   Put_Line (Tags (1).Name & Tags (2).Name & Integer'Image (Tags (2).Slot));
   Put_Line (Long.Name & Integer'Image (Long.Len) & Integer'Image (Long.Slot));
   for I in 1 .. 4 loop
      Head := new Request'(Id => I, Part => Part_Name (I), Next => Head);
   end loop;
   declare
      R : Request_Ref := Head;
      Count : Natural := 0;
   begin
      while R /= null loop
         if R.Part (1 .. 3) = "P00" and then R.Part (4 .. 4) /= "2" then
            Count := Count + 1;
         end if;
         Put (Integer'Image (R.Id) & ":" & R.Part);
         R := R.Next;
      end loop;
      New_Line;
      Put_Line ("matched" & Natural'Image (Count));
   end;
   begin
      N := 2;
      declare
         T : Table (1 .. 3) := (1 .. N => Next_Serial);
      begin
         Show (T);
      end;
   exception
      when Constraint_Error =>
         Put_Line ("length check:" & Integer'Image (Serial));
   end;
   begin
      Tags (1) := (Len => 3, Name => "ABC", Slot => 9);
      Put_Line ("mutable: " & Tags (1).Name);
   exception
      when Constraint_Error => Put_Line ("discriminant check");
   end;
end Engine_Aggregates_Records;
