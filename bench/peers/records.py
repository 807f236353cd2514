class Pos:
    __slots__ = ("x", "y", "z")

    def __init__(self, x, y, z):
        self.x = x
        self.y = y
        self.z = z


def shift(p, dx, dy, dz):
    q = Pos(p.x, p.y, p.z)
    q.x = p.x + dx
    q.y = p.y + dy
    q.z = p.z + dz
    return q


def main():
    p = Pos(0, 0, 0)
    for k in range(200000):
        p = shift(p, 1, -1, 0.5)
        p.z = p.z - 0.25
    print("x=" + str(int(p.x)))
    print("y=" + str(int(p.y)))
    print("z=" + str(int(p.z)))

main()
