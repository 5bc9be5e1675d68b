"""Writes the checker's two pathological inputs into the directory argv[1]:
minus.adb, a 10,000-term `1 - 1 - ...`, and star.adb, `F * F * ... * F`
(22 factors) with two user-defined "*" overloads."""
import sys

d = sys.argv[1]
terms = int(sys.argv[2]) if len(sys.argv) > 2 else 10_000
factors = int(sys.argv[3]) if len(sys.argv) > 3 else 22
with open(f"{d}/minus.adb", "w") as f:
    f.write("with Ada.Text_IO; use Ada.Text_IO;\nprocedure Minus is\n")
    f.write("   X : constant Integer := " + " - ".join(["1"] * terms) + ";\n")
    f.write("begin\n   Put_Line (Integer'Image (X));\nend Minus;\n")
with open(f"{d}/star.adb", "w") as f:
    f.write(
        """with Ada.Text_IO; use Ada.Text_IO;
procedure Star is
   type V is record A : Integer; end record;
   type W is record B : Integer; end record;
   function "*" (L, R : V) return V is begin return (A => L.A + R.A); end "*";
   function "*" (L, R : W) return W is begin return (B => L.B * R.B); end "*";
   F : constant V := (A => 1);
   X : V;
begin
   X := """
        + " * ".join(["F"] * factors)
        + """;
   Put_Line (Integer'Image (X.A));
end Star;
"""
    )
