class Ref:
    __slots__ = ("v",)

    def __init__(self, v):
        self.v = v


calls_made = Ref(0)


def update(a, b, c, d):
    b.v = b.v + a
    c.v = c.v + 1
    d.v = d.v + 1


def main():
    b = Ref(0)
    c = Ref(0)
    calls_made.v = 0
    for k in range(1000000):
        update(2, b, c, calls_made)
    print("b=" + str(b.v))
    print("c=" + str(c.v))
    print("d=" + str(calls_made.v))

main()
