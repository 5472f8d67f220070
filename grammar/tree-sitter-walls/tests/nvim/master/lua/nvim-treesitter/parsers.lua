-- A stand-in for nvim-treesitter's `master` branch, as far as registering a parser goes:
-- `get_parser_configs()` returns the table of parser configurations that `:TSInstall`
-- reads (one parser of its own here).
local configs = {
  lua = {
    install_info = { url = 'https://github.com/MunifTanjim/tree-sitter-lua', files = { 'src/parser.c', 'src/scanner.c' } },
    filetype = 'lua',
  },
}

return {
  get_parser_configs = function()
    return configs
  end,
}
