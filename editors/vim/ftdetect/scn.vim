" editors/vim/ftdetect/scn.vim: files ending in .scn are scn scenes (syntax/scn.vim).
autocmd BufNewFile,BufRead *.scn setfiletype scn
