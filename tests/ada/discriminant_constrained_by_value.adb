--  Objects of a type whose discriminant has no default are constrained
--  by their subtype or by their initial value (RM 3.3.1(9), 3.7.2): an
--  assignment of a message of another size raises Constraint_Error, in
--  the object itself, through an `in out` formal, through an access
--  value; a frame whose discriminant sizes both its header and its
--  payload, a component constrained by the enclosing discriminant.
with Ada.Text_IO; use Ada.Text_IO;
procedure Discriminant_Constrained_By_Value is
   type Message (Size : Natural) is record
      Text : String (1 .. Size);
   end record;
   type Frame (Length : Positive) is record
      Id : Positive := Length;
      Payload : Message (Length);
      Checksum : Natural := 0;
   end record;
   type Message_Ref is access Message;

   function Msg (S : String) return Message is
   begin
      return (Size => S'Length, Text => S);
   end Msg;

   procedure Replace (M : in out Message; S : String) is
   begin
      Put_Line ("replace" & Natural'Image (M.Size) & " by" & Natural'Image (S'Length)
                & ": " & Boolean'Image (M'Constrained));
      M := Msg (S);
      Put_Line ("  now " & M.Text);
   exception
      when Constraint_Error => Put_Line ("  kept " & M.Text);
   end Replace;

   Hello : Message := Msg ("HELLO");
   Empty : Message := Msg ("");
   F : Frame (3);
   G : Frame := (Length => 2, Id => 9, Payload => Msg ("OK"), Checksum => 7);
   P : Message_Ref := new Message'(Msg ("HEAP"));
begin
   Put_Line (Hello.Text & Natural'Image (Hello.Size) & Natural'Image (Empty.Size));
   Hello := Msg ("WORLD");
   Put_Line (Hello.Text);
   begin
      Hello := Msg ("HI");
   exception
      when Constraint_Error => Put_Line ("HELLO keeps five characters");
   end;
   Replace (Hello, "ABCDE");
   Replace (Hello, "ABC");
   Replace (Empty, "");
   Put_Line (Positive'Image (F.Id) & Natural'Image (F.Payload.Size) & Natural'Image (F.Payload.Text'Length));
   F.Payload := Msg ("XYZ");
   Put_Line (F.Payload.Text);
   begin
      F.Payload := Msg ("XY");
   exception
      when Constraint_Error => Put_Line ("the payload keeps the frame's length");
   end;
   Put_Line (G.Payload.Text & Positive'Image (G.Id) & Natural'Image (G.Checksum));
   begin
      G := (Length => 2, Id => 1, Payload => Msg ("TOO LONG"), Checksum => 0);
   exception
      when Constraint_Error => Put_Line ("a payload of another length");
   end;
   P.all := Msg ("PEAK");
   Put_Line (P.Text);
   begin
      P.all := Msg ("HEAPS");
   exception
      when Constraint_Error => Put_Line ("the heap message keeps four characters");
   end;
   Replace (P.all, "DONE");
   P := new Message'(Msg ("NEW ONE"));
   Put_Line (P.Text & Natural'Image (P.Size));
end Discriminant_Constrained_By_Value;
