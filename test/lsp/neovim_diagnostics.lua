-- Run by test_neovim.rb in a headless Neovim whose init.lua is the editor
-- guide's configuration: opens a file (the configuration starts `syskit
-- lsp` and attaches it), waits for the file's diagnostics and writes them
-- as JSON to a file the test reads.
local out, file = unpack(vim.g.syskit_lsp_test)
vim.cmd('edit ' .. vim.fn.fnameescape(file))
local buffer = vim.api.nvim_get_current_buf()
local published = vim.wait(20000, function() return #vim.diagnostic.get(buffer) > 0 end, 50)
local diagnostics = {}
for _, d in ipairs(vim.diagnostic.get(buffer)) do
  local lsp = (d.user_data or {}).lsp or {}
  local related = (lsp.relatedInformation or {})[1] or {}
  table.insert(diagnostics, { line = d.lnum, message = d.message, severity = d.severity, source = d.source,
                              hint = related.message })
end
vim.fn.writefile({ vim.fn.json_encode({ published = published, diagnostics = diagnostics }) }, out)
vim.cmd('qa!')
