-- Checks require('walls').register_parser against stand-ins of nvim-treesitter's two
-- branches (nvim/master and nvim/main): without nvim-treesitter, with `master`, with
-- `main`, and with `main` after it reloads its parsers table for `:TSUpdate`.
-- Environment: WALLS_GRAMMAR (the grammar folder), WALLS_STUBS (the stand-ins' folder),
-- WALLS_OUT (JSON written).

local function use(branch)
  package.loaded['nvim-treesitter.parsers'] = nil
  vim.opt.runtimepath:remove(os.getenv('WALLS_STUBS') .. '/master')
  vim.opt.runtimepath:remove(os.getenv('WALLS_STUBS') .. '/main')
  if branch then
    vim.opt.runtimepath:prepend(os.getenv('WALLS_STUBS') .. '/' .. branch)
  end
end

local function main()
  local grammar = os.getenv('WALLS_GRAMMAR')
  local walls = require('walls')
  local result = {}

  use(nil)
  result.without = walls.register_parser(grammar)

  use('master')
  result.master = walls.register_parser(grammar)
  local configs = require('nvim-treesitter.parsers').get_parser_configs()
  result.master_walls = configs.walls
  result.master_keeps_lua = configs.lua ~= nil

  use('main')
  result.main = walls.register_parser(grammar)
  result.main_walls = require('nvim-treesitter.parsers').walls
  -- What nvim-treesitter's `main` does before installing: a fresh parsers table, then
  -- the event. Registering twice leaves one autocommand.
  walls.register_parser(grammar)
  package.loaded['nvim-treesitter.parsers'] = nil
  result.reloaded_without_event = require('nvim-treesitter.parsers').walls or vim.NIL
  vim.api.nvim_exec_autocmds('User', { pattern = 'TSUpdate' })
  local parsers = require('nvim-treesitter.parsers')
  result.after_tsupdate = parsers.walls
  result.main_keeps_lua = parsers.lua ~= nil
  result.autocommands = #vim.api.nvim_get_autocmds({ event = 'User', pattern = 'TSUpdate' })

  vim.fn.writefile({ vim.fn.json_encode(result) }, os.getenv('WALLS_OUT'))
end

local ok, err = pcall(main)
if not ok then
  io.stderr:write('register_parser test: ' .. tostring(err) .. '\n')
  vim.cmd('cquit 1')
end
vim.cmd('qall!')
