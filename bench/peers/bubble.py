def main():
    a = [0] * 2000
    x = 1
    for k in range(2000):
        x = (x * 75 + 74) % 65537
        a[k] = x
    for i in range(1999, 0, -1):
        for j in range(i):
            if a[j] > a[j + 1]:
                t = a[j]
                a[j] = a[j + 1]
                a[j + 1] = t
    s = 0
    for k in range(0, 2000, 100):
        s = (s + a[k]) % 65537
    print("first=" + str(a[0]))
    print("last=" + str(a[1999]))
    print("check=" + str(s))

main()
