" groups.vim: for vim.sh: writes to $OUT the buffer's filetype, then one line per line of the
" buffer with one letter per byte for its syntax group (the letters of sample.codes), and to
" $OUT.messages Vim's messages, where an error in the files under test shows.
let s:code = {'scnStatement': 'k', 'scnAttribute': 'a', 'scnFunction': 'f', 'scnConstant': 'c',
      \ 'scnDefName': 'F', 'scnPovColour': 'P', 'scnDirective': 'D', 'scnNumber': 'n',
      \ 'scnOperator': 'o', 'scnCompare': 'o', 'scnString': 's', 'scnEscape': 'e',
      \ 'scnBadEscape': 'E', 'scnVectorDelim': 'v', 'scnTodo': 'T', 'scnComment': '/'}
let s:out = [&filetype]
for s:l in range(1, line('$'))
  let s:s = ''
  for s:c in range(1, col([s:l, '$']) - 1)
    let s:s .= get(s:code, synIDattr(synID(s:l, s:c, 1), 'name'), '.')
  endfor
  call add(s:out, s:s)
endfor
call writefile(s:out, $OUT)
call writefile(split(execute('messages'), "\n"), $OUT . '.messages')
qa!
