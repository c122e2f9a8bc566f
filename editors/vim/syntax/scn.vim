" editors/vim/syntax/scn.vim: Vim syntax for scn scenes (.scn), the scene language of
" the scn ray tracer: the reserved words of lang/keywords.c (statements, attributes, the
" operators and, or, not and the constants true, false), the functions and constants of
" lang/builtins.c, the name a def defines, comments, strings, numbers, vectors and
" comparisons, as lang/lexer.l reads them. POV-Ray's colour words and '#' directives, which
" scn rejects, show as errors. tests/editors/vim.sh checks the word lists against lang/.

if exists('b:current_syntax')
  finish
endif

" statements, then attributes, then operators; every one of them is reserved. A keyword line
" that sets options lists its words before them (tests/editors/vim.sh reads the words).
syn keyword scnStatement let include for in camera light material sphere plane triangle mesh
syn keyword scnStatement skybox samples max_depth box cylinder cone disc torus union merge
syn keyword scnStatement intersection difference if else fog
syn keyword scnStatement def nextgroup=scnDefName skipwhite
syn keyword scnAttribute location look_at up fov resolution position direction color
syn keyword scnAttribute intensity shadowless like diffuse specular shininess reflect transmit
syn keyword scnAttribute ior fresnel emit translate rotate scale smooth vertices faces normals
syn keyword scnAttribute zenith horizon image count pattern seed target_error open inverse
syn keyword scnAttribute inside_vector frequency phase turbulence octaves omega lambda colors map
syn keyword scnAttribute interpolate once normal uvs fade_distance fade_power spotlight
syn keyword scnAttribute point_at falloff tightness
syn keyword scnAttribute orthographic width distance
syn keyword scnAttribute area jitter circular orient aperture focal_point
syn keyword scnOperator and or not
" the builtins are names, and true and false values: a '<' after one compares
syn keyword scnFunction sqrt exp log abs floor ceil sin cos tan asin acos radians degrees
      \ nextgroup=scnCompare skipwhite
syn keyword scnFunction pow mod atan2 min max dot cross normalize length rand len str checker
      \ nextgroup=scnCompare skipwhite
syn keyword scnConstant pi clock frame true false nextgroup=scnCompare skipwhite
" reserved so that scn can say an scn colour is a plain vector
syn keyword scnPovColour rgb rgbf rgbt rgbft srgb srgbf srgbt srgbft
syn match scnDirective /#\h\w*/

" the name that def defines: def disc_area(r) = ..., def column(base, h) { ... }
syn match scnDefName /\h\w*/ contained

" a name other than a keyword (they come first); what follows it is as after a value
syn match scnName /\<\h\w*/ nextgroup=scnCompare skipwhite

" 12 3.5 .5 1e-6 2E+3; in a range (0..n) the dot after the digits is not the number's
syn match scnNumber /\<\d\+\%(\.\.\@!\d*\)\=\%([eE][+-]\=\d\+\)\=/ nextgroup=scnCompare skipwhite
syn match scnNumber /\%(\.\|\w\)\@<!\.\d\+\%([eE][+-]\=\d\+\)\=/ nextgroup=scnCompare skipwhite
" '>' compares outside a vector (inside one it closes it); '<' compares after a value (a
" name, a number, a string, a closing bracket: scnCompare) and opens a vector elsewhere
syn match scnOperator /\.\.\|[=!]=\|>=\=\|[-+*\/=?:]/
syn match scnCompare /<=\=/ contained

" one line; \" and \\ are the only escapes
syn region scnString start=/"/ skip=/\\./ end=/"/ end=/$/ oneline contains=scnEscape,scnBadEscape
      \ nextgroup=scnCompare skipwhite
syn match scnBadEscape /\\./ contained
syn match scnEscape /\\["\\]/ contained

" a vector <x, y, z>, which the first '>' outside other brackets closes: inside ( ) and
" [ ] a '>' compares (<(a > b) ? 1 : 0, 0, 0>). Each ends a value, which '<' may compare.
syn region scnVector matchgroup=scnVectorDelim start=/</ end=/>/ transparent
      \ nextgroup=scnCompare skipwhite
syn region scnParens start=/(/ end=/)/ transparent nextgroup=scnCompare skipwhite
syn region scnBrackets start=/\[/ end=/]/ transparent nextgroup=scnCompare skipwhite

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
hi def link scnCompare Operator
hi def link scnDefName Function
hi def link scnString String
hi def link scnEscape SpecialChar
hi def link scnBadEscape Error
hi def link scnVectorDelim Delimiter
hi def link scnTodo Todo
hi def link scnComment Comment

let b:current_syntax = 'scn'
