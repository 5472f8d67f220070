-- Checks the Neovim integration in editors/neovim: a walls file opened with only the
-- plugin on the runtime path gets filetype `walls`, `#` comments and walls-lsp
-- diagnostics. Environment: WALLS_LSP (server binary), WALLS_OUT (JSON written).

local function main()
  require('walls').setup({ cmd = { os.getenv('WALLS_LSP') } })
  vim.cmd('edit ' .. os.getenv('WALLS_FILE'))
  local buf = vim.api.nvim_get_current_buf()
  local got = vim.wait(15000, function() return #vim.diagnostic.get(buf) > 0 end, 50)
  assert(got, 'diagnostics arrive')
  local codes = {}
  for _, d in ipairs(vim.diagnostic.get(buf)) do table.insert(codes, d.code) end
  vim.fn.writefile({ vim.fn.json_encode({
    filetype = vim.bo.filetype,
    commentstring = vim.bo.commentstring,
    codes = codes,
  }) }, os.getenv('WALLS_OUT'))
end

local ok, err = pcall(main)
if not ok then
  io.stderr:write('walls nvim plugin test: ' .. tostring(err) .. '\n')
  vim.cmd('cquit 1')
end
vim.cmd('qall!')
