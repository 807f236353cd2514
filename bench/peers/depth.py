import sys

sys.setrecursionlimit(20000)


def depth(n):
    if n == 0:
        return 0
    return depth(n - 1) + 1


def main():
    total = 0
    for r in range(100):
        total = total + depth(9000)
    print("total=" + str(total))

main()
