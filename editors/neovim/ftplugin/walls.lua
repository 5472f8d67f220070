-- Walls buffers: `#` comments, and the walls-lsp language server attached.
vim.bo.commentstring = '# %s'
require('walls').attach(vim.api.nvim_get_current_buf())
