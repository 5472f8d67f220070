-- Highlights a walls file with the tree-sitter parser in `parser/walls.so` on the runtime
-- path and the highlight queries of editors/neovim (the grammar's `queries`): the file
-- parses without an error node, the highlighter attaches, and every capture is written to
-- WALLS_OUT as `LINE:COLUMN @CAPTURE TEXT` (1-based), in the order of the file.
-- Neovim 0.7 names the functions differently from 0.9 and later; both are tried.
-- Environment: WALLS_FILE (the file), WALLS_OUT (the captures written).

local function main()
  local ts, query = vim.treesitter, vim.treesitter.query
  vim.cmd('edit ' .. vim.fn.fnameescape(os.getenv('WALLS_FILE')))
  local buf = vim.api.nvim_get_current_buf()
  local parser = ts.get_parser(buf, 'walls')
  local root = parser:parse()[1]:root()
  assert(not root:has_error(), 'the sample parses without error: ' .. root:sexpr())
  local highlights = (query.get or query.get_query)('walls', 'highlights')
  assert(highlights, 'the highlight query is on the runtime path')
  ts.highlighter.new(parser)
  assert(ts.highlighter.active[buf], 'the highlighter attaches')
  local text = ts.get_node_text or query.get_node_text
  local lines = {}
  for id, node in highlights:iter_captures(root, buf, 0, -1) do
    local row, col = node:start()
    table.insert(lines, string.format('%d:%d @%s %s', row + 1, col + 1, highlights.captures[id], text(node, buf)))
  end
  vim.fn.writefile(lines, os.getenv('WALLS_OUT'))
end

local ok, err = pcall(main)
if not ok then
  io.stderr:write('tree-sitter highlight test: ' .. tostring(err) .. '\n')
  vim.cmd('cquit 1')
end
vim.cmd('qall!')
