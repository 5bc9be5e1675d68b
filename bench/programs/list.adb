with Ada.Text_IO; use Ada.Text_IO;
procedure List is
   type Node;
   type Node_Ptr is access Node;
   type Node is record
      Value : Integer;
      Next  : Node_Ptr;
   end record;
   Head : Node_Ptr := null;
   P    : Node_Ptr;
   Sum  : Integer := 0;
   Count : Integer := 0;
begin
   for I in 1 .. 100_000 loop
      Head := new Node'(Value => I mod 1000, Next => Head);
   end loop;
   P := Head;
   while P /= null loop
      Sum := Sum + P.Value;
      Count := Count + 1;
      P := P.Next;
   end loop;
   Put_Line (Integer'Image (Count) & Integer'Image (Sum));
end List;
