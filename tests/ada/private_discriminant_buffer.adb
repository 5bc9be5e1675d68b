--  A sample buffer for an axis: a private type whose partial view has a
--  discriminant (the buffer's size). Outside the package the size is
--  visible (`Trace.Size`), objects are constrained by a discriminant
--  constraint or by their initial value, and the samples stay hidden.
with Ada.Text_IO; use Ada.Text_IO;

procedure Private_Discriminant_Buffer is
   type Sample_Array is array (Positive range <>) of Float;

   package Samples is
      type Sample_Buffer (Size : Positive) is private;
      subtype Short_Buffer is Sample_Buffer (Size => 2);

      function Make (Size : Positive) return Sample_Buffer;
      function Capacity (B : Sample_Buffer) return Positive is (B.Size);
      function Length (B : Sample_Buffer) return Natural;
      function Mean (B : Sample_Buffer) return Float;
      procedure Push (B : in out Sample_Buffer; X : Float);
      procedure Clear (B : out Sample_Buffer);
   private
      type Sample_Buffer (Size : Positive) is record
         Data  : Sample_Array (1 .. Size) := (others => 0.0);
         Count : Natural := 0;
         Next  : Positive := 1;
      end record;
   end Samples;

   package body Samples is
      function Make (Size : Positive) return Sample_Buffer is
      begin
         return (Size => Size, Data => (1 .. Size => 0.0), Count => 0, Next => 1);
      end Make;

      function Length (B : Sample_Buffer) return Natural is (B.Count);

      function Mean (B : Sample_Buffer) return Float is
         Sum : Float := 0.0;
      begin
         if B.Count = 0 then
            return 0.0;
         end if;
         for I in 1 .. B.Count loop
            Sum := Sum + B.Data (I);
         end loop;
         return Sum / Float (B.Count);
      end Mean;

      --  A ring: the oldest sample goes when the buffer is full.
      procedure Push (B : in out Sample_Buffer; X : Float) is
      begin
         B.Data (B.Next) := X;
         B.Next := (if B.Next = B.Size then 1 else B.Next + 1);
         B.Count := Natural'Min (B.Count + 1, B.Size);
      end Push;

      procedure Clear (B : out Sample_Buffer) is
      begin
         for I in B.Data'Range loop
            B.Data (I) := 0.0;
         end loop;
         B.Count := 0;
         B.Next := 1;
      end Clear;
   end Samples;

   use Samples;

   type Axis_Log is record
      Axis  : Positive;
      Trace : Sample_Buffer (3);
   end record;

   type Short_Logs is array (1 .. 2) of Short_Buffer;
   type Buffer_Ref is access Sample_Buffer;
   type Tool_Trace is new Sample_Buffer;

   Shoulder : Sample_Buffer (4);
   Elbow    : Sample_Buffer := Make (6);
   Wrist    : Short_Buffer;
   Log      : Axis_Log := (Axis => 5, Trace => Make (3));
   Logs     : Short_Logs;
   Spare    : Buffer_Ref := new Sample_Buffer (5);
   Tool     : Tool_Trace (Size => 7);

   procedure Report (Name : String; B : Sample_Buffer) is
   begin
      Put_Line (Name & ": size" & Positive'Image (B.Size)
                & ", samples" & Natural'Image (Length (B))
                & ", mean" & Integer'Image (Integer (Mean (B) * 10.0))
                & ", constrained " & Boolean'Image (B'Constrained));
   end Report;

   procedure Fill (B : in out Sample_Buffer; From : Float) is
   begin
      for I in 1 .. B.Size + 1 loop
         Push (B, From + Float (I));
      end loop;
   end Fill;
begin
   Report ("shoulder", Shoulder);
   Fill (Shoulder, 10.0);
   Report ("shoulder", Shoulder);
   Fill (Elbow, 0.5);
   Report ("elbow", Elbow);
   Put_Line ("elbow capacity" & Positive'Image (Capacity (Elbow)));
   Push (Wrist, 2.0);
   Report ("wrist", Wrist);
   Fill (Log.Trace, 1.0);
   Report ("log" & Positive'Image (Log.Axis), Log.Trace);
   Put_Line ("log trace size" & Positive'Image (Log.Trace.Size));
   for L of Logs loop
      Push (L, 4.0);
   end loop;
   Report ("logs 2", Logs (2));
   Fill (Spare.all, 3.0);
   Report ("spare", Spare.all);
   Put_Line ("spare size" & Positive'Image (Spare.Size));
   Clear (Shoulder);
   Report ("shoulder", Shoulder);
   Shoulder := Make (4);
   Put_Line ("shoulder remade, equal to a new one: "
             & Boolean'Image (Shoulder = Make (4)));
   begin
      Shoulder := Make (5);
      Put_Line ("assigned a buffer of another size");
   exception
      when Constraint_Error =>
         Put_Line ("size 5 into shoulder: Constraint_Error");
   end;
   begin
      Elbow := Make (2);
      Put_Line ("assigned a buffer of another size");
   exception
      when Constraint_Error =>
         Put_Line ("size 2 into elbow: Constraint_Error");
   end;
   declare
      Copy : constant Sample_Buffer := Elbow;
   begin
      Report ("copy", Copy);
   end;
   Spare := new Sample_Buffer'(Make (1));
   Report ("spare", Spare.all);
   Put_Line ("tool trace size" & Positive'Image (Tool.Size)
             & ", constrained " & Boolean'Image (Tool'Constrained));
end Private_Discriminant_Buffer;
