local function main()
  local a = {}
  local x = 1
  for k = 1, 2000 do
    x = (x * 75 + 74) % 65537
    a[k] = x
  end
  for i = 2000, 2, -1 do
    for j = 1, i - 1 do
      if a[j] > a[j + 1] then
        local t = a[j]
        a[j] = a[j + 1]
        a[j + 1] = t
      end
    end
  end
  local s = 0
  for k = 1, 2000, 100 do
    s = (s + a[k]) % 65537
  end
  print("first=" .. a[1])
  print("last=" .. a[2000])
  print("check=" .. s)
end
main()
