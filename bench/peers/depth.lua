local function depth(n)
  if n == 0 then return 0 end
  return depth(n - 1) + 1
end

local function main()
  local total = 0
  for r = 1, 100 do
    total = total + depth(9000)
  end
  print("total=" .. total)
end
main()
