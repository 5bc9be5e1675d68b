--  Array values as copies: a copy does not see later changes of the
--  original (or the other way), in-place growth by `&` on a variable no one
--  else holds, overlapping slice assignments, arrays of records with
--  strings, two-dimensional arrays, and arrays kept in records and behind
--  access values.
with Ada.Text_IO; use Ada.Text_IO;
procedure Array_Copies is
   type Vec is array (Positive range <>) of Integer;
   type Grid is array (1 .. 3, 1 .. 3) of Float;
   type Item is record
      Tag : String (1 .. 4);
      N   : Integer;
   end record;
   type Items is array (1 .. 3) of Item;
   type Holder is record
      V : Vec (1 .. 4);
   end record;
   type Holder_Ptr is access Holder;
   A : Vec (1 .. 4) := (1, 2, 3, 4);
   B : Vec (1 .. 4);
   S : String (1 .. 8) := "abcdefgh";
   T : String (1 .. 8);
   L : String (1 .. 0) := "";
   G, H : Grid := (others => (others => 0.0));
   I, J : Items;
   P, Q : Holder_Ptr;
   function Build (N : Natural) return String is
   begin
      if N = 0 then
         return "";
      end if;
      return Build (N - 1) & Character'Val (Character'Pos ('a') + N mod 26);
   end Build;
   procedure Show (X : Vec) is
   begin
      for K in X'Range loop
         Put (Integer'Image (X (K)));
      end loop;
      New_Line;
   end Show;
begin
   B := A;
   B (2) := 20;
   A (3) := 30;
   Show (A);
   Show (B);
   T := S;
   S (2 .. 5) := S (1 .. 4);
   Put_Line (S & " " & T);
   T (5 .. 8) := T (4 .. 7);
   Put_Line (T);
   declare
      function Grow (Acc : String; K : Natural) return String is
      begin
         if K = 0 then
            return Acc;
         end if;
         return Grow (Acc & Integer'Image (K), K - 1);
      end Grow;
      Old   : constant String := Grow ("", 3);
      New_S : constant String := Old & "!";
   begin
      Put_Line (Grow ("", 5) & "|" & Old & "|" & New_S & Integer'Image (New_S'Length));
   end;
   Put_Line (Build (30) & Integer'Image (Build (30)'Length) & L);
   G (2, 3) := 1.5;
   H := G;
   G (2, 3) := 2.5;
   Put_Line (Float'Image (G (2, 3)) & Float'Image (H (2, 3)) & Float'Image (H (1, 1)));
   I := (others => (Tag => "none", N => 0));
   I (2) := (Tag => "ABCD", N => 7);
   J := I;
   I (2).Tag (1 .. 2) := "XY";
   Put_Line (I (2).Tag & " " & J (2).Tag & Integer'Image (J (2).N));
   P := new Holder'(V => (5, 6, 7, 8));
   Q := new Holder'(P.all);
   P.V (1) := 50;
   Show (P.V);
   Show (Q.V);
   Q := P;
   Q.V (4) := 80;
   Show (P.V);
   Put_Line (Boolean'Image (A = B) & Boolean'Image (A (1 .. 1) = B (1 .. 1))
             & Boolean'Image (S (1 .. 2) = "aa"));
end Array_Copies;
