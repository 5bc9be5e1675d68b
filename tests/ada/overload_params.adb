with Ada.Text_IO; use Ada.Text_IO;

procedure Overload_Params is
   type Status is (Ready, Busy, Error);
   type Terminal is (Console, Serial);
   procedure PutS (T : Terminal; Text : String) is
   begin
      Put_Line (Terminal'Image (T) & " text: " & Text);
   end PutS;
   procedure PutS (T : Terminal; S : Status) is
   begin
      Put_Line (Terminal'Image (T) & " status: " & Status'Image (S));
   end PutS;
   procedure PutS (T : Terminal; N : Integer) is
   begin
      Put_Line (Terminal'Image (T) & " integer:" & Integer'Image (N));
   end PutS;
   procedure PutS (T : Terminal; F : Float) is
   begin
      Put_Line (Terminal'Image (T) & " float:" & Float'Image (F));
   end PutS;
   procedure PutS (T : Terminal; C : Character) is
   begin
      Put_Line (Terminal'Image (T) & " char: " & C);
   end PutS;
   procedure PutS (T : Terminal; B : Boolean) is
   begin
      Put_Line (Terminal'Image (T) & " bool: " & Boolean'Image (B));
   end PutS;
   function Double (X : Integer) return Integer is
   begin
      return 2 * X;
   end Double;
   function Double (X : Float) return Float is
   begin
      return 2.0 * X;
   end Double;
   function Double (S : String) return String is
   begin
      return S & S;
   end Double;
   procedure Show (A : Integer; B : Integer) is
   begin
      Put_Line ("two integers:" & Integer'Image (A + B));
   end Show;
   procedure Show (A : Integer) is
   begin
      Put_Line ("one integer:" & Integer'Image (A));
   end Show;
   St : constant Status := Busy;
begin
   PutS (Console, "text");
   PutS (Serial, St);
   PutS (Console, Error);
   PutS (Serial, 42);
   PutS (Console, 4.5);
   PutS (Serial, 'x');
   PutS (Console, St = Busy);
   PutS (Serial, Double (21));
   PutS (Console, Double (1.25));
   PutS (Serial, Double ("ab"));
   PutS (Console, Double (Double (3)));
   PutS (T => Serial, S => Ready);
   PutS (T => Serial, Text => "named text");
   Show (1);
   Show (1, 2);
   Show (A => 5, B => 6);
end Overload_Params;
