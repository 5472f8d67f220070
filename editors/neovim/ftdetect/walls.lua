-- Walls files: *.walls, and pkdgrav's customary walls*.dat names.
vim.cmd([[autocmd BufRead,BufNewFile *.walls,walls*.dat setfiletype walls]])
