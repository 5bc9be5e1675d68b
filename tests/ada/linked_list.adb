with Ada.Text_IO; use Ada.Text_IO;

procedure Linked_List is
   type Node;
   type Node_Ptr is access Node;
   type Node is record
      Value : Integer;
      Next  : Node_Ptr;
   end record;
   Head : Node_Ptr := null;
   Tail, P : Node_Ptr;

   procedure Push_Front (List : in out Node_Ptr; V : Integer) is
   begin
      List := new Node'(Value => V, Next => List);
   end Push_Front;

   function Length (List : Node_Ptr) return Natural is
   begin
      return (if List = null then 0 else 1 + Length (List.Next));
   end Length;

   function Sum (List : Node_Ptr) return Integer is
      Cur : Node_Ptr := List;
      S   : Integer := 0;
   begin
      while Cur /= null loop
         S := S + Cur.all.Value;
         Cur := Cur.Next;
      end loop;
      return S;
   end Sum;

   procedure Print (List : Node_Ptr) is
      Cur : Node_Ptr := List;
   begin
      Put ("[");
      while Cur /= null loop
         Put (Integer'Image (Cur.Value));
         Cur := Cur.Next;
      end loop;
      Put_Line (" ]");
   end Print;

   function Reverse_List (List : Node_Ptr) return Node_Ptr is
      Result : Node_Ptr := null;
      Cur    : Node_Ptr := List;
   begin
      while Cur /= null loop
         Result := new Node'(Cur.Value, Result);
         Cur := Cur.Next;
      end loop;
      return Result;
   end Reverse_List;
begin
   Print (Head);
   Put_Line ("Length:" & Integer'Image (Length (Head)));
   for I in 1 .. 5 loop
      Push_Front (Head, I * I);
   end loop;
   Print (Head);
   Put_Line ("Length:" & Integer'Image (Length (Head)) & " Sum:" & Integer'Image (Sum (Head)));
   Tail := Head;
   while Tail.Next /= null loop
      Tail := Tail.Next;
   end loop;
   Tail.Next := new Node'(Value => 100, Next => null);
   Print (Head);
   P := Head.Next;
   P.all.Value := -4;
   Print (Head);
   P := Head;
   Head := Reverse_List (Head);
   Print (Head);
   Print (P);
   P.Next := P.Next.Next;
   Print (P);
   Put_Line ("Aliased: " & Boolean'Image (P = Head) & " " & Boolean'Image (P.Next.Next = P.Next.Next));
end Linked_List;
