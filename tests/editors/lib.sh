# lib.sh: what the editor tests share, sourced after tests/lib.sh: the words of the scene
# language as the front end has them (scn_words), and the checks of an editor's highlighting
# against sample.codes and against those words. A list that cannot be read from lang/ fails
# the test (exit 99), so that a changed layout there is not a test that passes on nothing.
editors=$SCN_SRCDIR/tests/editors

# block FILE START: the lines of FILE from the first that holds START to the first from
# there that holds '};' (a C array's initialiser)
block() {
	awk -v start="$2" 'index($0, start) { on = 1 } on { print } on && /};/ { exit }' "$1"
}

# quoted FILE START: the double-quoted words of that block
quoted() {
	block "$1" "$2" | grep -o '"[a-z_0-9]*"' | tr -d '"'
}

# scn_words: prints one "CLASS WORD" a line: statement, attribute, operator and constant
# (lang/keywords.c's names, grouped as lang/keywords.h's enum groups them under its comments:
# of the group of operators and constants, an operator is a word whose token has a
# precedence in lang/parser.y, as and, or and not have; true and false have none), function
# and constant (lang/builtins.c's table: a constant takes no argument), povray (POV-Ray's
# colour words, which lang/lexer.l reserves)
scn_words() {
	lang=$SCN_SRCDIR/lang
	# "GROUP WORD" for each KW_ of the enum, GROUP being the comment the lines follow
	groups=$(block "$lang/keywords.h" 'enum kw {' | awk '
		/^[ \t]*\/\*.*\*\/[ \t]*$/ { sub(/^[ \t]*\/\*[ \t]*/, ""); sub(/[ \t]*\*\/.*/, "")
			group = $0; gsub(/ /, "_", group); next }
		{ sub(/\/\*.*/, "")
		  while (match($0, /KW_[A-Z_0-9]*/)) {
			w = tolower(substr($0, RSTART + 3, RLENGTH - 3)); $0 = substr($0, RSTART + RLENGTH)
			if (w != "count_all") print group, w } }')
	[ -n "$groups" ] || { echo "words.sh: no keywords in lang/keywords.h" >&2; exit 99; }
	# the tokens that have a precedence: %left OR, %precedence NOT, ...
	ranked=" $(grep -E '^%(left|right|nonassoc|precedence)' "$lang/parser.y" | cut -d' ' -f2- | tr '\n' ' ') "
	[ "$ranked" != "  " ] || { echo "words.sh: no precedences in lang/parser.y" >&2; exit 99; }
	keywords=$(quoted "$lang/keywords.c" 'names[KW_COUNT_ALL] = {')
	[ -n "$keywords" ] || { echo "words.sh: no keywords in lang/keywords.c" >&2; exit 99; }
	for w in $keywords; do
		group=$(echo "$groups" | awk -v w="$w" '$2 == w { print $1 }')
		case $group in
		statements) echo "statement $w" ;;
		attributes) echo "attribute $w" ;;
		operators_and_constants)
			token=$(echo "$w" | tr '[:lower:]' '[:upper:]')
			case $ranked in
			*" $token "*) echo "operator $w" ;;
			*) echo "constant $w" ;;
			esac ;;
		'') echo "words.sh: '$w' of lang/keywords.c is in no group of lang/keywords.h" >&2; exit 99 ;;
		*) echo "words.sh: lang/keywords.h has a group '$group' (of '$w') that lib.sh does not know" >&2; exit 99 ;;
		esac
	done
	builtins=$(block "$lang/builtins.c" 'table[BUILTIN_COUNT] = {' |
		grep -o '{ "[a-z_0-9]*", [0-9-]*' | sed 's/{ "\([^"]*\)", \(.*\)/\1 \2/')
	[ -n "$builtins" ] || { echo "words.sh: no functions in lang/builtins.c" >&2; exit 99; }
	echo "$builtins" | while read -r w min; do
		[ "$min" = 0 ] && echo "constant $w" || echo "function $w"
	done
	pov=$(quoted "$lang/lexer.l" 'static const char *const words[] = {')
	[ -n "$pov" ] || { echo "words.sh: no POV-Ray colour words in lang/lexer.l" >&2; exit 99; }
	for w in $pov; do echo "povray $w"; done
}

# expect_sample WHO OUTPUT: OUTPUT, WHO's letters for sample.scn, is sample.codes
expect_sample() {
	grep -v '^#' "$editors/sample.codes" | diff -u - "$2" >"$work/diff" ||
		{ fail "$1 highlights sample.scn otherwise than sample.codes (+ is $1's)"; cat "$work/diff"; }
}

# words_scene: writes the words of scn_words to $work/words, and one a line to
# $work/words.scn for the editor to highlight
words_scene() {
	scn_words >"$work/words"
	awk '{ print $2 }' "$work/words" >"$work/words.scn"
}

# expect_words WHO OUTPUT: OUTPUT, WHO's letters for $work/words.scn, gives each word the
# letter of its class, over the whole word
expect_words() {
	paste -d ' ' "$work/words" "$2" | while read -r class word got; do
		case $class in
		statement) c=k ;; attribute) c=a ;; operator) c=o ;; function) c=f ;; constant) c=c ;;
		povray) c=P ;;
		esac
		[ "$got" = "$(printf "%${#word}s" | tr ' ' "$c")" ] || echo "FAIL: $1 highlights the $class '$word' as '$got'"
	done >"$work/bad"
	[ -s "$work/bad" ] && { cat "$work/bad"; fails=$((fails + $(wc -l <"$work/bad"))); }
}

# expect_listed FILE LISTED: LISTED, the "CLASS WORD" lines that FILE's keyword lists give,
# holds the words of scn_words and no other
expect_listed() {
	sort "$work/words" >"$work/want"
	sort "$2" | diff -u "$work/want" - >"$work/diff" ||
		{ fail "the keywords of $1 are not those of lang/ (+ is the file's)"; cat "$work/diff"; }
}
