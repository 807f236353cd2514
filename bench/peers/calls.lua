local calls_made = { v = 0 }

local function update(a, b, c, d)
  b.v = b.v + a
  c.v = c.v + 1
  d.v = d.v + 1
end

local function main()
  local b = { v = 0 }
  local c = { v = 0 }
  calls_made.v = 0
  for k = 1, 1000000 do
    update(2, b, c, calls_made)
  end
  print("b=" .. b.v)
  print("c=" .. c.v)
  print("d=" .. calls_made.v)
end
main()
