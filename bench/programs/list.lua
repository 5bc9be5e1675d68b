local head = nil
for i = 1, 100000 do head = {value = i % 1000, next = head} end
local p, s, count = head, 0, 0
while p do
  s = s + p.value
  count = count + 1
  p = p.next
end
print(count, s)
