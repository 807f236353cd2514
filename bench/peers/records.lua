local function shift(p, dx, dy, dz)
  local q = { x = p.x, y = p.y, z = p.z }
  q.x = p.x + dx
  q.y = p.y + dy
  q.z = p.z + dz
  return q
end

local function main()
  local p = { x = 0, y = 0, z = 0 }
  for k = 1, 200000 do
    p = shift(p, 1, -1, 0.5)
    p.z = p.z - 0.25
  end
  print(string.format("x=%d", p.x))
  print(string.format("y=%d", p.y))
  print(string.format("z=%d", p.z))
end
main()
