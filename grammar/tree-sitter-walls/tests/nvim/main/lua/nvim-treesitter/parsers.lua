-- A stand-in for nvim-treesitter's `main` branch, as far as registering a parser goes:
-- the module is the table of parsers itself (no `get_parser_configs`), which
-- nvim-treesitter reloads before an install or update and then fires `User TSUpdate`.
return {
  lua = {
    install_info = { url = 'https://github.com/tree-sitter-grammars/tree-sitter-lua' },
    tier = 1,
  },
}
