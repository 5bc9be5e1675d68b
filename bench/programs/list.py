class Node:
    __slots__ = ("value", "next")
    def __init__(self, value, next):
        self.value = value
        self.next = next
head = None
for i in range(1, 100001):
    head = Node(i % 1000, head)
p = head
s = 0
count = 0
while p is not None:
    s += p.value
    count += 1
    p = p.next
print(count, s)
