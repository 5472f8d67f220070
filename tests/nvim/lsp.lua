-- Drives walls-lsp from a real Neovim (0.7+), headless, as a user's editor would:
-- opens a file, waits for diagnostics, asks for hover, completion, symbols, fixes and
-- formatting, and writes what it saw as JSON for the Rust test to check.
-- Environment: WALLS_LSP (server binary), WALLS_FILE (file to open), WALLS_OUT (JSON).

local function main()
  local file = os.getenv("WALLS_FILE")
  vim.cmd("edit " .. file)
  local buf = vim.api.nvim_get_current_buf()
  local client_id = vim.lsp.start_client({
    name = "walls-lsp",
    cmd = { os.getenv("WALLS_LSP") },
    root_dir = vim.fn.fnamemodify(file, ":h"),
  })
  assert(client_id, "the server starts")
  vim.lsp.buf_attach_client(buf, client_id)
  local got = vim.wait(15000, function() return #vim.diagnostic.get(buf) > 0 end, 50)
  assert(got, "diagnostics arrive")
  local client = vim.lsp.get_client_by_id(client_id)
  local doc = { uri = vim.uri_from_bufnr(buf) }
  local function request(method, params)
    local response = client.request_sync(method, params, 10000, buf)
    assert(response and not response.err, method .. " answers")
    return response.result
  end

  local result = {}
  result.diagnostics = {}
  for _, d in ipairs(vim.diagnostic.get(buf)) do
    table.insert(result.diagnostics, { code = d.code, line = d.lnum, col = d.col, severity = d.severity })
  end
  local hover = request("textDocument/hover", { textDocument = doc, position = { line = 1, character = 4 } })
  result.hover = hover.contents.value
  local items = request("textDocument/completion", { textDocument = doc, position = { line = 0, character = 10 } })
  result.completion = {}
  for _, item in ipairs(items) do table.insert(result.completion, item.label) end
  local symbols = request("textDocument/documentSymbol", { textDocument = doc })
  result.symbols = {}
  for _, s in ipairs(symbols) do table.insert(result.symbols, s.name) end
  local diagnostic = vim.diagnostic.get(buf)[1]
  local actions = request("textDocument/codeAction", {
    textDocument = doc,
    range = { start = { line = diagnostic.lnum, character = diagnostic.col },
              ["end"] = { line = diagnostic.end_lnum, character = diagnostic.end_col } },
    context = { diagnostics = {} },
  })
  result.actions = {}
  for _, a in ipairs(actions) do table.insert(result.actions, a.title) end
  vim.lsp.buf.formatting_sync(nil, 10000)
  result.formatted = vim.api.nvim_buf_get_lines(buf, 0, -1, false)
  vim.fn.writefile({ vim.fn.json_encode(result) }, os.getenv("WALLS_OUT"))
end

local ok, err = pcall(main)
if not ok then
  io.stderr:write("walls nvim test: " .. tostring(err) .. "\n")
  vim.cmd("cquit 1")
end
vim.cmd("qall!")
