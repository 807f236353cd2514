def main():
    s = ""
    total = 0
    for k in range(100000):
        s = s + "ab"
        if len(s) > 70:
            s = s[10:]
        total = total + len(s)
    print("s=" + s)
    print("total=" + str(total))

main()
