-- walls for Neovim 0.7 to 0.11: attaches walls-lsp to walls buffers.
--
--   require('walls').setup({ cmd = { 'walls-lsp' }, mode = 'ssdem', max_walls = 20 })
--
-- Neovim 0.8 and later use vim.lsp.start (one client per root, reused); 0.7 uses
-- vim.lsp.start_client and vim.lsp.buf_attach_client with a client shared by buffers.
local M = {
  config = { cmd = { 'walls-lsp' }, mode = 'ssdem', max_walls = 20 },
  client_id = nil,
}

function M.setup(opts)
  M.config = vim.tbl_extend('force', M.config, opts or {})
end

local function root(buf)
  local name = vim.api.nvim_buf_get_name(buf)
  return vim.fn.fnamemodify(name ~= '' and name or vim.fn.getcwd(), ':p:h')
end

function M.attach(buf)
  local init = { mode = M.config.mode, maxWalls = M.config.max_walls }
  if vim.lsp.start then
    vim.lsp.start({
      name = 'walls-lsp',
      cmd = M.config.cmd,
      root_dir = root(buf),
      init_options = init,
    }, { bufnr = buf })
    return
  end
  if not (M.client_id and vim.lsp.get_client_by_id(M.client_id)) then
    M.client_id = vim.lsp.start_client({
      name = 'walls-lsp',
      cmd = M.config.cmd,
      root_dir = root(buf),
      init_options = init,
    })
  end
  if M.client_id then
    vim.lsp.buf_attach_client(buf, M.client_id)
  end
end

-- Registers the tree-sitter parser of this repository's grammar/tree-sitter-walls with
-- nvim-treesitter, then `:TSInstall walls` builds and installs it. Both branches:
--  * `master`: an entry in `get_parser_configs()`;
--  * `main` (the rewrite): the `nvim-treesitter.parsers` module is the table of parsers,
--    which nvim-treesitter reloads before each install or update and then fires the
--    `User TSUpdate` autocommand; the entry is set now and again on that event. It names
--    the grammar's `queries` folder, which `main` installs with the parser.
-- Returns the branch ('master' or 'main'), or false without nvim-treesitter.
function M.register_parser(grammar_dir)
  local ok, parsers = pcall(require, 'nvim-treesitter.parsers')
  if not ok then
    return false
  end
  if type(parsers.get_parser_configs) == 'function' then
    parsers.get_parser_configs().walls = {
      install_info = { url = grammar_dir, files = { 'src/parser.c' } },
      filetype = 'walls',
    }
    return 'master'
  end
  local function register()
    require('nvim-treesitter.parsers').walls = {
      install_info = { path = grammar_dir, queries = 'queries' },
    }
  end
  register()
  vim.api.nvim_create_autocmd('User', {
    group = vim.api.nvim_create_augroup('walls_treesitter', { clear = true }),
    pattern = 'TSUpdate',
    callback = register,
  })
  return 'main'
end

return M
