--  The declarations of a package's private part are visible in its body.
with Ada.Text_IO; use Ada.Text_IO;
procedure Package_Private_Part is
   package P is
      function Get return Integer;
   private
      Hidden : Integer := 3;
   end P;
   package body P is
      function Get return Integer is (Hidden);
   end P;
begin
   Put_Line (Integer'Image (P.Get));
end Package_Private_Part;
