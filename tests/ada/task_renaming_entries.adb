--  A conveyor feeds a protected part queue and a loader task; the cell
--  controller calls them through renamings: a protected procedure, entry
--  and function, and a task entry, each renamed as a subprogram with its
--  own parameter names.
with Ada.Text_IO; use Ada.Text_IO;
procedure Task_Renaming_Entries is
   type Part_Id is range 0 .. 999;
   type Slots is array (1 .. 4) of Part_Id;

   protected Queue is
      procedure Put (Part : Part_Id);
      entry Take (Part : out Part_Id);
      function Length return Natural;
   private
      Items : Slots := (others => 0);
      Count : Natural := 0;
   end Queue;

   protected body Queue is
      procedure Put (Part : Part_Id) is
      begin
         Count := Count + 1;
         Items (Count) := Part;
      end Put;

      entry Take (Part : out Part_Id) when Count > 0 is
      begin
         Part := Items (1);
         Items (1 .. 3) := Items (2 .. 4);
         Count := Count - 1;
      end Take;

      function Length return Natural is
      begin
         return Count;
      end Length;
   end Queue;

   task Loader is
      entry Load (Part : Part_Id; Station : Positive);
      entry Done (Total : out Natural);
   end Loader;

   task body Loader is
      Loaded : Natural := 0;
   begin
      loop
         select
            accept Load (Part : Part_Id; Station : Positive) do
               Put_Line ("  loader: part" & Part_Id'Image (Part)
                         & " to station" & Positive'Image (Station));
               Loaded := Loaded + 1;
            end Load;
         or
            accept Done (Total : out Natural) do
               Total := Loaded;
            end Done;
            exit;
         end select;
      end loop;
   end Loader;

   procedure Feed (Id : Part_Id) renames Queue.Put;
   procedure Next (Into : out Part_Id) renames Queue.Take;
   function Waiting return Natural renames Queue.Length;
   procedure Place (Id : Part_Id; At_Station : Positive := 1) renames Loader.Load;

   P     : Part_Id;
   Total : Natural;
begin
   Feed (101);
   Feed (Id => 102);
   Feed (103);
   Put_Line ("waiting" & Natural'Image (Waiting));
   for K in 1 .. 3 loop
      Next (Into => P);
      Place (P, At_Station => K);
      Put_Line ("placed" & Part_Id'Image (P) & ", waiting" & Natural'Image (Waiting));
   end loop;
   Place (P);
   Loader.Done (Total);
   Put_Line ("loaded" & Natural'Image (Total));
end Task_Renaming_Entries;
