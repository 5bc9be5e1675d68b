with Ada.Text_IO;
package body Geo_Lib is
   function Double (X : Integer) return Integer is
   begin
      Calls := Calls + 1;
      return 2 * X;
   end Double;
begin
   Ada.Text_IO.Put_Line ("Geo_Lib elaborated");
end Geo_Lib;
