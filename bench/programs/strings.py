# Labels made by concatenation, read back character by character and
# compared by slices (as strings.adb).
def main():
    total, count = 0, 0
    for i in range(1, 200001):
        s = "P " + str(i) + ": " + str(i % 97)
        for c in s:
            total += ord(c)
        if s[-2:] == " 1":
            count += 1
    print(f" {count} {total}")


main()
