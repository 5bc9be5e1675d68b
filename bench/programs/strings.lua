-- Labels made by concatenation, read back character by character and
-- compared by substrings (as strings.adb).
local sum, count = 0, 0
for i = 1, 200000 do
  local s = "P " .. i .. ": " .. (i % 97)
  for k = 1, #s do
    sum = sum + s:byte(k)
  end
  if s:sub(-2) == " 1" then count = count + 1 end
end
print(" " .. count .. " " .. sum)
