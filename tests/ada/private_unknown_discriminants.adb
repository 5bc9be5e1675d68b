--  Unknown discriminants (`type Job (<>) is private;`): outside the
--  package an object of the type needs an initial value, from the
--  package's functions, which also constrains it. The full views: a
--  record with a discriminant (a welding job of so many seams), an
--  unconstrained array (a path of waypoints) and a record (a
--  cell permit, limited outside the package, built in place).
with Ada.Text_IO; use Ada.Text_IO;

procedure Private_Unknown_Discriminants is
   package Cell is
      type Job (<>) is private;
      type Path (<>) is private;
      type Permit (<>) is limited private;

      function Weld (Seams : Positive; Speed : Float) return Job;
      function Seams (J : Job) return Positive;
      function Done (J : Job) return Natural;
      procedure Step (J : in out Job);

      function Line (Points : Positive; Step : Float) return Path;
      function Points (P : Path) return Natural;
      function Length (P : Path) return Float;

      function Grant (Zone : Positive) return Permit;
      function Zone (P : Permit) return Positive;
   private
      type Seam_Flags is array (Positive range <>) of Boolean;
      type Job (Seams : Positive) is record
         Speed : Float := 1.0;
         Welded : Seam_Flags (1 .. Seams) := (others => False);
      end record;
      type Path is array (Positive range <>) of Float;
      type Permit is record
         Zone : Positive := 1;
      end record;
   end Cell;

   package body Cell is
      function Weld (Seams : Positive; Speed : Float) return Job is
         J : Job (Seams);
      begin
         J.Speed := Speed;
         return J;
      end Weld;

      function Seams (J : Job) return Positive is (J.Seams);

      function Done (J : Job) return Natural is
         N : Natural := 0;
      begin
         for W of J.Welded loop
            if W then
               N := N + 1;
            end if;
         end loop;
         return N;
      end Done;

      procedure Step (J : in out Job) is
      begin
         for I in J.Welded'Range loop
            if not J.Welded (I) then
               J.Welded (I) := True;
               return;
            end if;
         end loop;
      end Step;

      function Line (Points : Positive; Step : Float) return Path is
         P : Path (1 .. Points);
      begin
         for I in P'Range loop
            P (I) := Float (I - 1) * Step;
         end loop;
         return P;
      end Line;

      function Points (P : Path) return Natural is (P'Length);
      function Length (P : Path) return Float is (P (P'Last) - P (P'First));

      function Grant (Zone : Positive) return Permit is
      begin
         return (Zone => Zone);
      end Grant;

      function Zone (P : Permit) return Positive is (P.Zone);
   end Cell;

   --  Whether an object's discriminants can change is its full view's
   --  business: a tool whose partial view has unknown discriminants, a
   --  socket whose partial view has none, both completed by records whose
   --  discriminants have defaults, are mutable outside the package too.
   package Tools is
      type Tool (<>) is private;
      type Socket is private;
      function Jaws return Tool;
      procedure Swap (T : in out Tool; Width : Positive);
      function Width (T : Tool) return Positive;
      procedure Widen (S : in out Socket);
      function Size (S : Socket) return Positive;
      function Checked_Size (S : in out Socket) return Positive is (Size (S));
   private
      type Tool (Width : Positive := 20) is record
         Uses : Natural := 0;
      end record;
      type Socket (Size : Positive := 1) is record
         Pins : Natural := 0;
      end record;
   end Tools;

   package body Tools is
      function Jaws return Tool is ((Width => 20, Uses => 0));

      procedure Swap (T : in out Tool; Width : Positive) is
      begin
         T := (Width => Width, Uses => T.Uses + 1);
      exception
         when Constraint_Error =>
            Put_Line ("swap: Constraint_Error");
      end Swap;

      function Width (T : Tool) return Positive is (T.Width);

      procedure Widen (S : in out Socket) is
      begin
         S := (Size => S.Size + 1, Pins => S.Pins + 2);
      exception
         when Constraint_Error =>
            Put_Line ("widen: Constraint_Error");
      end Widen;

      function Size (S : Socket) return Positive is (S.Size);
   end Tools;

   use Cell;

   type Job_Ref is access Job;

   Door   : Job := Weld (3, 0.5);
   Frame  : constant Job := Weld (2, 1.0);
   Approach : Path := Line (4, 0.25);
   Welding  : constant Permit := Grant (2);
   Queue  : Job_Ref := new Job'(Weld (5, 2.0));
   Hand   : Tools.Tool := Tools.Jaws;
   Plug   : Tools.Socket;

   procedure Show (Tag : String; J : Job) is
   begin
      Put_Line (Tag & ":" & Natural'Image (Done (J)) & " of"
                & Positive'Image (Seams (J)) & " seams");
   end Show;
begin
   Step (Door);
   Step (Door);
   Show ("door", Door);
   Show ("frame", Frame);
   Door := Weld (3, 0.8);
   Show ("door again", Door);
   begin
      Door := Frame;
      Put_Line ("assigned a job of another size");
   exception
      when Constraint_Error =>
         Put_Line ("frame into door: Constraint_Error");
   end;
   Put_Line ("approach:" & Natural'Image (Points (Approach)) & " points,"
             & Integer'Image (Integer (Length (Approach) * 100.0)) & " cm");
   Approach := Line (4, 0.5);
   Put_Line ("approach:" & Integer'Image (Integer (Length (Approach) * 100.0)) & " cm");
   begin
      Approach := Line (2, 0.5);
   exception
      when Constraint_Error =>
         Put_Line ("a shorter path: Constraint_Error");
   end;
   Put_Line ("permit for zone" & Positive'Image (Zone (Welding)));
   for I in 1 .. 4 loop
      Step (Queue.all);
   end loop;
   Show ("queue", Queue.all);
   Queue := new Job'(Frame);
   Show ("queue", Queue.all);
   Tools.Swap (Hand, 35);
   Put_Line ("hand width" & Positive'Image (Tools.Width (Hand)));
   Hand := Tools.Jaws;
   Put_Line ("hand width" & Positive'Image (Tools.Width (Hand)));
   Tools.Widen (Plug);
   Tools.Widen (Plug);
   Put_Line ("plug size" & Positive'Image (Tools.Size (Plug)));
   Tools.Widen (Plug);
   Put_Line ("plug size" & Positive'Image (Tools.Checked_Size (Plug)));
end Private_Unknown_Discriminants;
