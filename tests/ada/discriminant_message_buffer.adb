--  A controller's message buffer whose text is as long as its
--  discriminant says (RM 3.7, 3.7.1, 3.8): constrained objects and
--  subtypes, a non-static constraint, a component default that reads the
--  discriminant, aggregates and functions returning the unconstrained
--  type, the length check of the text and the discriminant check of an
--  assignment to a constrained object.
with Ada.Text_IO; use Ada.Text_IO;
procedure Discriminant_Message_Buffer is
   type Message (Size : Positive) is record
      Text : String (1 .. Size);
      Last : Natural := 0;
      Room : Natural := Size;
   end record;
   subtype Line is Message (8);
   M : Message (5);
   L : Line;
   N : Natural := 3;
   K : Message (N + 1);
   C : constant Message := (Size => 4, Text => "PICK", Last => 4, Room => 0);
   function Make (S : String) return Message is
   begin
      return (Size => S'Length, Text => S, Last => S'Length, Room => 0);
   end Make;
   procedure Show (X : Message) is
   begin
      Put_Line ("[" & X.Text (1 .. X.Last) & "]" & Positive'Image (X.Size)
                & Natural'Image (X.Room) & Integer'Image (X.Text'First)
                & Integer'Image (X.Text'Last));
   end Show;
   procedure Append (X : in out Message; Ch : Character) is
   begin
      X.Last := X.Last + 1;
      X.Text (X.Last) := Ch;
      X.Room := X.Room - 1;
   end Append;
begin
   Put_Line (Positive'Image (M.Size) & Natural'Image (M.Room) & Natural'Image (L.Room)
             & Natural'Image (K.Size) & Natural'Image (K.Text'Length));
   Append (M, 'G');
   Append (M, 'O');
   Show (M);
   Show (C);
   Show (Make ("PLACE"));
   declare
      D : Message := Make ("HOME");
   begin
      Show (D);
      D := C;
      Show (D);
      D.Text := "WAIT";
      Show (D);
   end;
   begin
      M := Make ("AB");
   exception
      when Constraint_Error => Put_Line ("size mismatch");
   end;
   M := Make ("ABCDE");
   Show (M);
   begin
      M.Text := "ABC";
   exception
      when Constraint_Error => Put_Line ("length mismatch");
   end;
   Put_Line (Boolean'Image (M = Make ("ABCDE")) & Boolean'Image (C = Make ("PICK")));
   begin
      L := (Size => 8, Text => "TOO LONG!", Last => 0, Room => 0);
   exception
      when Constraint_Error => Put_Line ("aggregate length");
   end;
end Discriminant_Message_Buffer;
