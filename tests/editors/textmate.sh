# textmate.sh: editors/textmate/scn.tmLanguage.json is JSON, and a TextMate tokenizer
# (textmate.py) highlights sample.scn with it as sample.codes says (the classes that Vim's
# syntax gives: vim.sh) and each word of the language (lib.sh reads them from lang/) as its
# class; the keyword rules list no word that lang/ lacks.
. "$SCN_SRCDIR/tests/lib.sh"
. "$SCN_SRCDIR/tests/editors/lib.sh"

command -v python3 >/dev/null || { echo "SKIP: python3 is not installed"; exit 77; }
grammar=$SCN_SRCDIR/editors/textmate/scn.tmLanguage.json

expect_status 0 python3 -m json.tool "$grammar"
# tokenize FILE: $work/letters gets textmate.py's letters for FILE
tokenize() {
	expect_status 0 python3 "$editors/textmate.py" "$grammar" "$1"
	mv "$work/out" "$work/letters"
}

tokenize "$editors/sample.scn"
expect_sample TextMate "$work/letters"

words_scene
tokenize "$work/words.scn"
expect_words TextMate "$work/letters"

expect_status 0 python3 "$editors/textmate.py" --words "$grammar"
expect_listed editors/textmate/scn.tmLanguage.json "$work/out"
finish
