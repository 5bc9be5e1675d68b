--  A three-station cell: the loader's entry family has one member per
--  station; the cell controller renames members as procedures. A member
--  whose index is a variable is the member the index names at each call.
with Ada.Text_IO; use Ada.Text_IO;
procedure Renaming_Entry_Family_Member is
   type Station is range 1 .. 3;
   type Part_Id is range 0 .. 999;

   protected Cell is
      entry Load (Station) (Part : Part_Id);
      function Total return Natural;
   private
      Sum : Natural := 0;
   end Cell;

   protected body Cell is
      entry Load (for S in Station) (Part : Part_Id) when True is
      begin
         Put_Line ("  station" & Station'Image (S) & " gets part" & Part_Id'Image (Part));
         Sum := Sum + Natural (S) * Natural (Part);
      end Load;

      function Total return Natural is
      begin
         return Sum;
      end Total;
   end Cell;

   task Press is
      entry Stroke (Station) (Force : Natural);
   end Press;

   task body Press is
   begin
      for K in 1 .. 2 loop
         select
            accept Stroke (1) (Force : Natural) do
               Put_Line ("  press 1, force" & Natural'Image (Force));
            end Stroke;
         or
            accept Stroke (3) (Force : Natural) do
               Put_Line ("  press 3, force" & Natural'Image (Force));
            end Stroke;
         end select;
      end loop;
   end Press;

   Next : Station := 2;
   procedure Load_Last (Part : Part_Id) renames Cell.Load (3);
   procedure Load_Next (Part : Part_Id) renames Cell.Load (Next);
   procedure Press_First (Force : Natural) renames Press.Stroke (Station'First);
   procedure Press_Next (Force : Natural) renames Press.Stroke (Next);
begin
   Load_Last (1);
   Load_Next (Part => 10);
   Next := 1;
   Load_Next (5);
   Put_Line ("total" & Natural'Image (Cell.Total));
   Press_First (40);
   Next := 3;
   Press_Next (Force => 70);
end Renaming_Entry_Family_Member;
