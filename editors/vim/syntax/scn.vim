" editors/vim/syntax/scn.vim: Vim syntax for scn scenes (.scn), the scene language of
" the scn ray tracer: the reserved words of lang/keywords.c (statements and attributes), the
" functions and constant of lang/builtins.c, comments, strings, numbers and vectors, as
" lang/lexer.l reads them. POV-Ray's colour words and '#' directives, which scn rejects,
" show as errors. tests/editors/vim.sh checks the word lists against lang/.

if exists('b:current_syntax')
  finish
endif

" statements, then attributes; every one of them is reserved
syn keyword scnStatement let include for in camera light material sphere plane triangle mesh
syn keyword scnStatement skybox samples max_depth box cylinder cone disc torus union merge
syn keyword scnStatement intersection difference
syn keyword scnAttribute location look_at up fov resolution position direction color
syn keyword scnAttribute intensity shadowless like diffuse specular shininess reflect transmit
syn keyword scnAttribute ior fresnel emit translate rotate scale smooth vertices faces normals
syn keyword scnAttribute zenith horizon image count pattern seed target_error open inverse
syn keyword scnAttribute inside_vector
syn keyword scnFunction sqrt exp log abs floor ceil sin cos tan asin acos radians degrees pow
syn keyword scnFunction mod atan2 min max dot cross normalize length rand checker
syn keyword scnConstant pi clock frame
" reserved so that scn can say an scn colour is a plain vector
syn keyword scnPovColour rgb rgbf rgbt rgbft srgb srgbf srgbt srgbft
syn match scnDirective /#\h\w*/

" 12 3.5 .5 1e-6 2E+3; in a range (0..n) the dot after the digits is not the number's
syn match scnNumber /\<\d\+\%(\.\.\@!\d*\)\=\%([eE][+-]\=\d\+\)\=/
syn match scnNumber /\%(\.\|\w\)\@<!\.\d\+\%([eE][+-]\=\d\+\)\=/
syn match scnOperator /\.\.\|[-+*\/=]/

" one line; \" and \\ are the only escapes
syn region scnString start=/"/ skip=/\\./ end=/"/ end=/$/ oneline contains=scnEscape,scnBadEscape
syn match scnBadEscape /\\./ contained
syn match scnEscape /\\["\\]/ contained

" a vector <x, y, z>: no operator uses '<' or '>'
syn region scnVector matchgroup=scnVectorDelim start=/</ end=/>/ transparent

" not nested
syn keyword scnTodo TODO FIXME XXX NOTE contained
syn match scnComment +//.*$+ contains=scnTodo,@Spell
syn region scnComment start=+/\*+ end=+\*/+ contains=scnTodo,@Spell

hi def link scnStatement Statement
hi def link scnAttribute Type
hi def link scnFunction Function
hi def link scnConstant Constant
hi def link scnPovColour Error
hi def link scnDirective Error
hi def link scnNumber Number
hi def link scnOperator Operator
hi def link scnString String
hi def link scnEscape SpecialChar
hi def link scnBadEscape Error
hi def link scnVectorDelim Delimiter
hi def link scnTodo Todo
hi def link scnComment Comment

let b:current_syntax = 'scn'
