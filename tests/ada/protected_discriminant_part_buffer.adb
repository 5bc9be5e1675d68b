--  A bounded part buffer between a feeder and a packer (RM 9.4, 3.7):
--  the protected type's discriminant sizes its storage array, closes its
--  entry barriers (Put when Count < Size), is read by its functions and
--  from outside (Belt.Size); a counter whose discriminant has a default;
--  buffers of several sizes, in an array of constrained objects and by
--  allocators.
with Ada.Text_IO; use Ada.Text_IO;
procedure Protected_Discriminant_Part_Buffer is
   type Part is record
      Serial : Positive;
      Weight : Natural;
   end record;
   type Part_Array is array (Positive range <>) of Part;

   protected type Part_Buffer (Size : Positive) is
      entry Put (P : Part);
      entry Get (P : out Part);
      function Count return Natural;
      function Free return Natural;
   private
      Items : Part_Array (1 .. Size);
      First : Positive := 1;
      Used : Natural := 0;
   end Part_Buffer;

   protected body Part_Buffer is
      entry Put (P : Part) when Used < Size is
      begin
         Items ((First + Used - 1) mod Size + 1) := P;
         Used := Used + 1;
      end Put;
      entry Get (P : out Part) when Used > 0 is
      begin
         P := Items (First);
         First := First mod Size + 1;
         Used := Used - 1;
      end Get;
      function Count return Natural is
      begin
         return Used;
      end Count;
      function Free return Natural is
      begin
         return Size - Used;
      end Free;
   end Part_Buffer;

   protected type Counter (Start : Natural := 100) is
      procedure Next (N : out Natural);
   private
      Value : Natural := Start;
   end Counter;

   protected body Counter is
      procedure Next (N : out Natural) is
      begin
         N := Value;
         Value := Value + 1;
      end Next;
   end Counter;

   type Buffer_Ref is access Part_Buffer;

   Belt : Part_Buffer (3);
   Tray : Part_Buffer (Size => 1);
   Serials : Counter;
   Lots : Counter (Start => 7);
   Bins : array (1 .. 2) of Part_Buffer (2);
   Spare : Buffer_Ref := new Part_Buffer (5);
   P : Part;
   N : Natural;
begin
   Put_Line ("sizes:" & Positive'Image (Belt.Size) & Positive'Image (Tray.Size)
             & Positive'Image (Bins (2).Size) & Positive'Image (Spare.Size)
             & Natural'Image (Serials.Start) & Natural'Image (Lots.Start));
   Lots.Next (N);
   Put_Line ("lot" & Natural'Image (N));
   Tray.Put ((1, 5));
   Put_Line ("tray free" & Natural'Image (Tray.Free));
   select
      Tray.Put ((2, 6));
      Put_Line ("tray took a second part?");
   else
      Put_Line ("tray full");
   end select;
   Tray.Get (P);
   Put_Line ("tray gave" & Positive'Image (P.Serial));
   for B in Bins'Range loop
      for I in 1 .. 2 loop
         Bins (B).Put ((B * 10 + I, I));
      end loop;
      Put_Line ("bin" & Integer'Image (B) & " holds" & Natural'Image (Bins (B).Count)
                & ", free" & Natural'Image (Bins (B).Free));
   end loop;
   for I in 1 .. 4 loop
      Spare.Put ((40 + I, 0));
   end loop;
   Put_Line ("spare holds" & Natural'Image (Spare.Count) & " of" & Positive'Image (Spare.Size));
   declare
      --  The feeder fills the belt and waits at Put's barrier until the
      --  packer makes room.
      task Feeder;
      task Packer;

      task body Feeder is
         N : Natural;
      begin
         for I in 1 .. 6 loop
            Serials.Next (N);
            Belt.Put ((Serial => N, Weight => I * 10));
         end loop;
      end Feeder;

      task body Packer is
         P : Part;
      begin
         delay 0.01;
         Put_Line ("belt full:" & Natural'Image (Belt.Count) & " of" & Positive'Image (Belt.Size));
         for I in 1 .. 6 loop
            Belt.Get (P);
            Put_Line ("packed" & Positive'Image (P.Serial) & Natural'Image (P.Weight));
         end loop;
      end Packer;
   begin
      null;
   end;
   Put_Line ("belt empty:" & Natural'Image (Belt.Count));
end Protected_Discriminant_Part_Buffer;
