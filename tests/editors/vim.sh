# vim.sh: editors/vim: Vim loads the ftdetect and syntax files without an error, gives a
# .scn file the filetype scn and highlights sample.scn as sample.codes says (the classes
# that the TextMate grammar gives: textmate.sh); it highlights each word of the language
# (lib.sh reads them from lang/) as its class, and the file lists no keyword that lang/ lacks.
. "$SCN_SRCDIR/tests/lib.sh"
. "$SCN_SRCDIR/tests/editors/lib.sh"

command -v vim >/dev/null || { echo "SKIP: vim is not installed (apt-get install vim)"; exit 77; }
vim --version | grep -q '+syntax' ||
	{ echo "SKIP: this vim has no syntax highlighting (vim-tiny?); apt-get install vim"; exit 77; }

# highlight FILE: runs Vim on FILE with no set-up but editors/vim; $work/letters gets
# groups.vim's letters, and $work/filetype the filetype
highlight() {
	OUT=$work/codes vim -Nu NONE -i NONE -es --noplugin --cmd "set rtp^=$SCN_SRCDIR/editors/vim" \
		--cmd 'filetype on' --cmd 'syntax on' "$1" -c "source $editors/groups.vim" \
		</dev/null >"$work/vim.out" 2>&1
	status=$?
	[ "$status" -eq 0 ] || { fail "vim on $1 exited $status"; cat "$work/vim.out" "$work/codes.messages"; }
	[ -s "$work/vim.out" ] && { fail "vim on $1 printed:"; cat "$work/vim.out"; }
	sed -n 1p "$work/codes" >"$work/filetype"
	sed 1d "$work/codes" >"$work/letters"
}

highlight "$editors/sample.scn"
[ "$(cat "$work/filetype")" = scn ] || fail "sample.scn's filetype is '$(cat "$work/filetype")', not scn"
expect_sample Vim "$work/letters"

words_scene
highlight "$work/words.scn"
expect_words Vim "$work/letters"

# the syntax file's keyword lists, in their classes
sed -n 's/^syn keyword scn//p' "$SCN_SRCDIR/editors/vim/syntax/scn.vim" | grep -v '^Todo ' |
	while read -r group words; do
		case $group in
		Statement) class=statement ;; Attribute) class=attribute ;; Operator) class=operator ;;
		Function) class=function ;; Constant) class=constant ;; PovColour) class=povray ;;
		*) class="scn$group?" ;;
		esac
		for w in $words; do
			case $w in # the options of a keyword line
			*=* | contained | transparent | skipwhite | skipnl | skipempty | conceal) ;;
			*) echo "$class $w" ;;
			esac
		done
	done >"$work/listed"
expect_listed editors/vim/syntax/scn.vim "$work/listed"
finish
