-- An end-to-end session of Neovim's built-in LSP client with `rapid-sem lsp` (run by
-- test/test_lsp.ml in a copy of test/lsp/cell): open the task's three modules, wait for the
-- diagnostics of Wrong.mod and check where Neovim puts them, hover, go to definition, find
-- references, complete, rename. Each result is a line of $RESULT, which the test checks; a Lua
-- error is written there too. Neovim 0.8 and later start the client with vim.lsp.start;
-- Neovim 0.7 (Debian bookworm's) has only vim.lsp.start_client and buf_attach_client.

local bin = os.getenv("RAPID_SEM")
local result = os.getenv("RESULT")
local out = {}
local function emit(s) table.insert(out, s) end

local function finish()
  local f = io.open(result, "w")
  f:write(table.concat(out, "\n") .. "\n")
  f:close()
  vim.cmd("qa!")
end

local function request(buf, method, params)
  local responses = vim.lsp.buf_request_sync(buf, method, params, 20000)
  if not responses then error(method .. ": no response") end
  for _, r in pairs(responses) do
    if r.err then error(method .. ": " .. vim.inspect(r.err)) end
    return r.result
  end
end

local function at(buf, line, character)
  return { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = { line = line, character = character } }
end

local function session()
  local cwd = vim.fn.getcwd()
  vim.cmd("edit Cell.mod")
  local cell = vim.api.nvim_get_current_buf()
  vim.cmd("edit Tools.mod")
  local tools = vim.api.nvim_get_current_buf()
  vim.cmd("edit Wrong.mod")
  local wrong = vim.api.nvim_get_current_buf()
  local config = { name = "rapid-sem", cmd = { bin, "lsp" }, root_dir = cwd }
  local client
  if vim.lsp.start then
    -- Neovim 0.8 and later: one client for the root, attached to each buffer made current.
    for _, b in ipairs({ cell, tools, wrong }) do
      vim.api.nvim_set_current_buf(b)
      client = vim.lsp.start(config)
    end
  else
    client = vim.lsp.start_client(config)
    if client then
      for _, b in ipairs({ cell, tools, wrong }) do vim.lsp.buf_attach_client(b, client) end
    end
  end
  if not client then error("the server did not start") end
  emit("client " .. (vim.lsp.start and "vim.lsp.start" or "vim.lsp.start_client"))

  -- Diagnostics: where Neovim puts them (it makes byte columns of the server's UTF-16 ones;
  -- they are counted back in UTF-16 here), and the text it finds there.
  vim.wait(30000, function() return #vim.diagnostic.get(wrong) > 0 end, 50)
  local ds = vim.diagnostic.get(wrong)
  table.sort(ds, function(a, b) return a.lnum < b.lnum or (a.lnum == b.lnum and a.col < b.col) end)
  emit("diagnostics " .. #ds)
  for _, d in ipairs(ds) do
    local line = vim.api.nvim_buf_get_lines(wrong, d.lnum, d.lnum + 1, false)[1]
    local _, c1 = vim.str_utfindex(line, d.col)
    local _, c2 = vim.str_utfindex(line, d.end_col)
    emit(string.format("diagnostic %d:%d-%d:%d %d %s", d.lnum, c1, d.end_lnum, c2, d.severity,
      (d.message:gsub("\n.*", ""):gsub("^semantic error: ", ""))))
    emit("diagtext " .. string.sub(line, d.col + 1, d.end_col))
  end

  -- Hover: a data object, an installed routine.
  local h = request(cell, "textDocument/hover", at(cell, 13, 12))
  emit("hover pHome " .. h.contents.value:match("```rapid\n([^\n]*)"))
  h = request(cell, "textDocument/hover", at(cell, 13, 5))
  emit("hover MoveL " .. h.contents.value:match("```rapid\n([^\n]*)"))

  -- Definition in another module, references across the task.
  local d = request(cell, "textDocument/definition", at(cell, 15, 5))
  local loc = d[1] or d
  emit(string.format("definition Pick %s %d:%d", vim.fn.fnamemodify(vim.uri_to_fname(loc.uri), ":t"),
    loc.range.start.line, loc.range.start.character))
  local refs = at(cell, 9, 12)
  refs.context = { includeDeclaration = true }
  emit("references nCount " .. #request(cell, "textDocument/references", refs))

  -- Completion: installed routines in a routine of Tools.mod.
  local c = request(tools, "textDocument/completion", at(tools, 6, 4))
  local items = c.items or c
  local found = "no"
  for _, i in ipairs(items) do if i.label == "MoveL" then found = "yes" end end
  emit("completion MoveL " .. found)

  -- Signature help: the parameter at the cursor, by its offsets in the signature.
  local sh = request(tools, "textDocument/signatureHelp", at(tools, 4, 37))
  local sig = sh.signatures[1]
  local range = sig.parameters[sh.activeParameter + 1].label
  emit("signature " .. sig.label:match("PROC (%w+)") .. " " .. string.sub(sig.label, range[1] + 1, range[2]))

  -- Rename, applied by Neovim to both buffers.
  local params = at(cell, 9, 12)
  params.newName = "nPicks"
  local edit = request(cell, "textDocument/rename", params)
  local n = 0
  for _, edits in pairs(edit.changes) do n = n + #edits end
  emit("rename nCount nPicks " .. n)
  vim.lsp.util.apply_workspace_edit(edit, "utf-16")
  emit("renamed Cell.mod " .. vim.trim(vim.api.nvim_buf_get_lines(cell, 16, 17, false)[1]))

  -- Record components after '.', typed into the buffer (the module does not parse meanwhile).
  vim.api.nvim_buf_set_lines(cell, 17, 18, false, { '    TPWrite "x" \\Num := pHome.trans.' })
  vim.wait(200)
  c = request(cell, "textDocument/completion", at(cell, 17, 36))
  local labels = {}
  for _, i in ipairs(c.items or c) do table.insert(labels, i.label) end
  table.sort(labels)
  emit("completion components " .. table.concat(labels, ","))

  vim.lsp.stop_client(client)
  emit("done")
end

local ok, err = pcall(session)
if not ok then emit("error " .. tostring(err)) end
finish()
