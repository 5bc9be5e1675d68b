--  A tray of parts and a request queue: a renaming of an element, a
--  slice and a dereference evaluates its index and access values once, at
--  its declaration. Changing the index afterwards does not move the
--  renaming; a function in the renamed name is called once.
with Ada.Text_IO; use Ada.Text_IO;
procedure Renaming_Evaluated_Once is
   type Part is record
      Id     : Natural;
      Weight : Integer;
   end record;
   type Tray is array (1 .. 6) of Part;

   type Request;
   type Request_Ref is access Request;
   type Request is record
      Slot : Positive;
      Next : Request_Ref;
   end record;

   Parts : Tray := (others => (Id => 0, Weight => 0));
   I     : Positive := 2;
   Calls : Natural := 0;

   function Next_Free return Positive is
   begin
      Calls := Calls + 1;
      Put_Line ("  Next_Free called");
      return 5;
   end Next_Free;

   Queue : Request_Ref := new Request'(Slot => 3, Next => null);
   Code  : String (1 .. 8) := "GRIP-A01";
begin
   for K in Parts'Range loop
      Parts (K) := (Id => 100 + K, Weight => 10 * K);
   end loop;
   declare
      Slot   : Part renames Parts (I);
      Weight : Integer renames Parts (I).Weight;
      Free   : Part renames Parts (Next_Free);
      Head   : Request renames Queue.all;
      First  : Positive renames Queue.Slot;
      Suffix : String renames Code (I + 4 .. 8);
   begin
      I := 4;                                   --  does not move Slot
      Put_Line ("slot id" & Natural'Image (Slot.Id)
                & " weight" & Integer'Image (Weight));
      Slot.Weight := 99;
      Put_Line ("parts (2) weight" & Integer'Image (Parts (2).Weight)
                & " parts (4) weight" & Integer'Image (Parts (4).Weight));
      Weight := Weight + 1;
      Put_Line ("slot weight" & Integer'Image (Slot.Weight));
      Free.Id := 500;
      Free.Id := Free.Id + 1;
      Put_Line ("calls" & Natural'Image (Calls)
                & " parts (5) id" & Natural'Image (Parts (5).Id));
      Queue := new Request'(Slot => 6, Next => Queue);   --  Head stays
      Put_Line ("head slot" & Positive'Image (Head.Slot)
                & " first" & Positive'Image (First)
                & " queue slot" & Positive'Image (Queue.Slot));
      Head.Slot := 1;
      Put_Line ("old request slot" & Positive'Image (Queue.Next.Slot)
                & " first" & Positive'Image (First));
      Put_Line ("suffix " & Suffix & " length" & Natural'Image (Suffix'Length)
                & " first" & Positive'Image (Suffix'First));
      Suffix := "B02";
      Put_Line ("code " & Code);
      Code (6) := 'C';
      Put_Line ("suffix " & Suffix & " " & Suffix (7 .. 8));
   end;
   --  An index out of range is found at the renaming's elaboration.
   I := 7;
   declare
      Beyond : Part renames Parts (I);
   begin
      Put_Line ("not reached" & Natural'Image (Beyond.Id));
   exception
      when Constraint_Error => Put_Line ("not here");
   end;
exception
   when Constraint_Error => Put_Line ("index 7 refused at the renaming");
end Renaming_Evaluated_Once;
