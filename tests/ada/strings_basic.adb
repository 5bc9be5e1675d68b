with Ada.Text_IO; use Ada.Text_IO;

procedure Strings_Basic is
   Greeting : constant String := "Hello";
   Name     : String (1 .. 5) := "World";
   Quote    : constant String := "She said ""hi"" twice";
   Only_Quote : constant String := """";
   Empty    : constant String := "";
   function Shout (S : String) return String is
   begin
      return S & "!";
   end Shout;
   function Id (S : String) return String is
   begin
      return S;
   end Id;
   function Repeat (S : String; N : Natural) return String is
   begin
      if N = 0 then
         return "";
      else
         return S & Repeat (S, N - 1);
      end if;
   end Repeat;
begin
   Put_Line (Greeting & ", " & Name & '!');
   Put_Line (Quote);
   Put_Line ("Quote length:" & Integer'Image (Quote'Length));
   Put_Line ("Only quote: " & Only_Quote & " length" & Integer'Image (Only_Quote'Length));
   Put_Line ("Empty length:" & Integer'Image (Empty'Length) & " [" & Empty & "]");
   Put_Line ('<' & "chars" & '>');
   Put_Line ("a" & 'b' & 'c' & "de");
   Put_Line (Shout (Shout (Greeting)));
   Put_Line (Repeat ("ab", 3) & "|" & Repeat ("x", 0) & "|");
   Put_Line ("Repeat length:" & Integer'Image (Repeat ("xyz", 4)'Length));
   Name (1) := 'w';
   Name (5) := 'D';
   Put_Line (Name & " first char " & Name (1) & " last char " & Name (Name'Last));
   Put_Line ("abc < abd: " & Boolean'Image (Id ("abc") < "abd"));
   Put_Line ("abc < ab: " & Boolean'Image (Id ("abc") < "ab"));
   Put_Line ("ab < abc: " & Boolean'Image (Id ("ab") < "abc"));
   Put_Line ("Zebra < apple: " & Boolean'Image (Id ("Zebra") < "apple"));
   Put_Line ("Hello = Greeting: " & Boolean'Image (Id ("Hello") = Greeting));
   Put_Line ("hello = Greeting: " & Boolean'Image (Id ("hello") = Greeting));
   Put_Line ("Greeting /= Name: " & Boolean'Image (Greeting /= Name));
   Put_Line ("abc >= abc: " & Boolean'Image (Id ("abc") >= "abc"));
   Put_Line ("b > abc: " & Boolean'Image (Id ("b") > "abc"));
   Put_Line ("Empty < a: " & Boolean'Image (Id (Empty) < "a"));
   Put_Line ("String'(""x"") <= ""x"": " & Boolean'Image (Id (String'("x")) <= "x"));
   declare
      Line : constant String := Greeting & " " & Name;
   begin
      Put_Line ("Line'First =" & Integer'Image (Line'First) & " Line'Last =" & Integer'Image (Line'Last));
      for I in Line'Range loop
         if Line (I) = 'l' then
            Put_Line ("  'l' at" & Integer'Image (I));
         end if;
      end loop;
   end;
end Strings_Basic;
