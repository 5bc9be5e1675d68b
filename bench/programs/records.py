# A list of 100,000 parts, each with a 4-character tag built character by
# character, walked with a slice comparison (as records.adb).
class Part:
    __slots__ = ("tag", "count", "next")

    def __init__(self, tag, count, next):
        self.tag, self.count, self.next = tag, count, next


def main():
    letters = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
    head = None
    for i in range(1, 100001):
        n, t = i, ""
        for _ in range(4):
            t += letters[n % 26]
            n //= 26
        head = Part(t, i % 7, head)
    p, matches, total = head, 0, 0
    while p is not None:
        if p.tag[0:2] == "BA":
            matches += 1
        total += p.count
        p = p.next
    print(f" {matches} {total}")


main()
