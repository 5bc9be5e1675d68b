package Geo_Lib is
   Calls : Integer := 0;
   function Double (X : Integer) return Integer;
end Geo_Lib;
