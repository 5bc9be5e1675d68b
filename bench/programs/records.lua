-- A list of 100,000 parts, each with a 4-character tag built character by
-- character, walked with a substring comparison (as records.adb).
local letters = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
local head = nil
for i = 1, 100000 do
  local n, t = i, ""
  for k = 1, 4 do
    local c = n % 26 + 1
    t = t .. letters:sub(c, c)
    n = n // 26
  end
  head = {tag = t, count = i % 7, next = head}
end
local p, matches, total = head, 0, 0
while p do
  if p.tag:sub(1, 2) == "BA" then matches = matches + 1 end
  total = total + p.count
  p = p.next
end
print(" " .. matches .. " " .. total)
