local function main()
  local s = ""
  local total = 0
  for k = 1, 100000 do
    s = s .. "ab"
    if #s > 70 then
      s = string.sub(s, 11)
    end
    total = total + #s
  end
  print("s=" .. s)
  print("total=" .. total)
end
main()
