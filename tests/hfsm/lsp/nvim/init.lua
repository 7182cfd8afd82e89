-- Neovim (0.7 or later) starts hfsm-lsp for YAML files: the set-up of docs/EDITORS.md, plus a
-- function the test calls to wait for the diagnostics and write them to a file as JSON.
local cmd = os.getenv("HFSM_LSP") or "hfsm-lsp"

vim.api.nvim_create_autocmd("FileType", {
  pattern = "yaml",
  callback = function(args)
    local id = vim.lsp.start_client({
      name = "hfsm",
      cmd = { cmd },
      root_dir = vim.fn.getcwd(),
      init_options = { world = os.getenv("HFSM_WORLD") },
    })
    vim.lsp.buf_attach_client(args.buf, id)
  end,
})

function HfsmWriteDiagnostics(path)
  local buf = vim.api.nvim_get_current_buf()
  vim.wait(60000, function() return #vim.diagnostic.get(buf) > 0 end, 50)
  local found = {}
  for _, d in ipairs(vim.diagnostic.get(buf)) do
    local code = d.code or (d.user_data and d.user_data.lsp and d.user_data.lsp.code) or ""
    table.insert(found, { d.lnum, d.col, d.end_col, code, d.severity, d.message })
  end
  local file = io.open(path, "w")
  file:write(vim.fn.json_encode(found))
  file:close()
end
