with Ada.Text_IO; use Ada.Text_IO;
procedure Elab_Call_Before_Body is

   --  A direct call in an object declaration, before the body.
   procedure Direct is
      function F return Integer;
      X : Integer := F;
      function F return Integer is
      begin
         return 42;
      end F;
   begin
      Put_Line ("Direct: X =" & Integer'Image (X));
   end Direct;

   --  An indirect one: G has its body, F not yet.
   procedure Indirect is
      function F return Integer;
      function G return Integer is
      begin
         return F + 1;
      end G;
      X : Integer := G;
      function F return Integer is
      begin
         return 42;
      end F;
   begin
      Put_Line ("Indirect: X =" & Integer'Image (X));
   end Indirect;

   --  After the body: fine, also through G.
   procedure After is
      function F return Integer;
      function G return Integer is
      begin
         return F + 1;
      end G;
      function F return Integer is
      begin
         return 42;
      end F;
      X : Integer := G;
   begin
      Put_Line ("After: X =" & Integer'Image (X));
   end After;

   --  A package spec's function called before the package body.
   procedure Early_Package is
      package P is
         function F return Integer;
      end P;
      Y : Integer := P.F;
      package body P is
         function F return Integer is
         begin
            return 7;
         end F;
      end P;
   begin
      Put_Line ("Early_Package: Y =" & Integer'Image (Y));
   end Early_Package;

   --  Inside the package body, before the function's body.
   procedure In_Body is
      package P is
         function F return Integer;
         Z : Integer := 0;
      end P;
      package body P is
         function H return Integer is
         begin
            return F * 2;
         end H;
         Local : Integer := H;
         function F return Integer is
         begin
            return 5;
         end F;
      begin
         Z := Local;
      end P;
   begin
      Put_Line ("In_Body: Z =" & Integer'Image (P.Z));
   end In_Body;

   --  Procedures too, and mutual recursion through a declaration.
   procedure Mutual is
      function Even (N : Natural) return Boolean;
      function Odd (N : Natural) return Boolean is
      begin
         return N /= 0 and then Even (N - 1);
      end Odd;
      function Even (N : Natural) return Boolean is
      begin
         return N = 0 or else Odd (N - 1);
      end Even;
      procedure Say;
      procedure Say is
      begin
         Put_Line ("Mutual: Odd (7) = " & Boolean'Image (Odd (7)));
      end Say;
   begin
      Say;
   end Mutual;

   --  Each elaboration of the declarative part checks again: the
   --  first one elaborates F's body, the next ones call it before.
   procedure Again (N : Integer) is
      function F return Integer;
      function G return Integer is
      begin
         if N > 0 then
            return F;
         else
            return 0;
         end if;
      end G;
      X : Integer := G;
      function F return Integer is
      begin
         return N;
      end F;
   begin
      Put_Line ("Again: X =" & Integer'Image (X) & ", F =" & Integer'Image (F));
   end Again;

begin
   begin
      Direct;
   exception
      when Program_Error => Put_Line ("Direct: Program_Error");
   end;
   begin
      Indirect;
   exception
      when Program_Error => Put_Line ("Indirect: Program_Error");
   end;
   After;
   begin
      Early_Package;
   exception
      when Program_Error => Put_Line ("Early_Package: Program_Error");
   end;
   begin
      In_Body;
   exception
      when Program_Error => Put_Line ("In_Body: Program_Error");
   end;
   Mutual;
   for I in 0 .. 2 loop
      begin
         Again (I);
      exception
         when Program_Error => Put_Line ("Again: Program_Error");
      end;
   end loop;
end Elab_Call_Before_Body;
