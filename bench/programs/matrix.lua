local function mul(a, b)
  local c = {}
  for i = 1, 4 do
    c[i] = {0.0, 0.0, 0.0, 0.0}
    for j = 1, 4 do
      for k = 1, 4 do
        c[i][j] = c[i][j] + a[i][k] * b[k][j]
      end
    end
  end
  return c
end
local r = {{1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}, {0.0, 0.0, 0.0, 1.0}}
local t = {{0.0, -1.0, 0.0, 1.0}, {1.0, 0.0, 0.0, 2.0}, {0.0, 0.0, 1.0, 3.0}, {0.0, 0.0, 0.0, 1.0}}
for n = 1, 200000 do r = mul(r, t) end
print(r[1][4], r[2][4], r[3][4])
