#!/bin/sh
# check.sh: the layering of the sources, from the code itself. Run by make check (in the
# build tree, after the libraries are built), or by hand from a build tree:
#   sh tests/layout/check.sh [-v]
# It reads two graphs and fails when either has a cycle or a reference goes the wrong way:
#  - includes: every #include "X" of lang/, render/ and src/, resolved as the compiler
#    resolves it (the including file's folder first, then its library's include path,
#    which holds the folders below it: README.md's Layout). A folder that includes from
#    a folder containing it is an upward reference: only those listed in ALLOWED_UP may
#    stand, each argued in README.md. An include that names a folder is refused, since
#    it would step around the include paths.
#  - calls: which object of the nine libraries uses a symbol that another defines (nm),
#    the only way to see a cycle of calls that a shared header hides. flex's and bison's
#    output calls into each other by design (yyparse, yylex) and is left out.
# -v prints every folder's edges as well.
set -u
top=${SCN_SRCDIR:-$(cd "$(dirname "$0")/../.." && pwd)}
build=$(pwd)
verbose=${1:-}
ALLOWED_UP="render/pov>render render/dist>render"
tmp=${TMPDIR:-/tmp}/scn-layout.$$
mkdir -p "$tmp" || exit 99
trap 'rm -rf "$tmp"' EXIT
status=0

# ---- includes ----
(cd "$top" && find lang render src -name '*.[chly]' ! -name lexer.c ! -name parser.c \
	! -name parser_nolac.c ! -name parser.h | sort) >"$tmp/files"
# FILE<TAB>NAME for every quoted include
while read -r f; do
	sed -n 's/^[ \t]*#[ \t]*include[ \t]*"\([^"]*\)".*/\1/p' "$top/$f" | while read -r name; do
		printf '%s\t%s\n' "$f" "$name"
	done
done <"$tmp/files" >"$tmp/includes"
awk -F'\t' -v allowed="$ALLOWED_UP" -v verbose="$verbose" '
function dir(p) { sub(/\/[^\/]*$/, "", p); return p }
function base(p) { sub(/.*\//, "", p); return p }
NR == FNR { files[$0] = 1; n = split($0, a, "/"); where[base($0)] = where[base($0)] ? where[base($0)] " " $0 : $0; next }
{
	f = $1; name = $2; total++
	if (name ~ /\//) { printf "include names a folder: %s: \"%s\"\n", f, name; bad++; next }
	if ((dir(f) "/" name) in files) target = dir(f) "/" name
	else if (name in where && where[name] !~ / /) target = where[name]
	else if (name in where) { printf "include is ambiguous: %s: \"%s\" (%s)\n", f, name, where[name]; bad++; next }
	else next                                  # config.h, generated parser.h
	fadj[f] = fadj[f] " " target
	from = dir(f); to = dir(target)
	if (from == to) next
	edge[from ">" to] = edge[from ">" to] (edge[from ">" to] ? ", " : "") base(f) ": " name
	fedge[from ">" to] = 1
}
END {
	n = split(allowed, ok, " "); for (i = 1; i <= n; i++) allow[ok[i]] = 1
	for (e in fedge) { split(e, p, ">"); nodes[p[1]] = 1; nodes[p[2]] = 1; adj[p[1]] = adj[p[1]] " " p[2] }
	# file cycles: a file that reaches itself through its includes
	for (s in files) {
		delete seen; stack = fadj[s]; cyc = 0
		while (stack != "") {
			m = split(stack, q, " "); v = q[m]; stack = ""; for (i = 1; i < m; i++) stack = stack " " q[i]
			if (v == s) { cyc = 1; break }
			if (v in seen) continue
			seen[v] = 1; stack = stack fadj[v]
		}
		if (cyc) { printf "include cycle through file %s\n", s; bad++ }
	}
	# folder cycles: a folder that reaches itself
	for (s in nodes) {
		delete seen; stack = adj[s]; cyc = 0
		while (stack != "") {
			m = split(stack, q, " "); v = q[m]; stack = ""; for (i = 1; i < m; i++) stack = stack " " q[i]
			if (v == s) { cyc = 1; break }
			if (v in seen) continue
			seen[v] = 1; stack = stack adj[v]
		}
		if (cyc) { printf "include cycle through folder %s\n", s; bad++ }
	}
	up = 0
	for (e in edge) {
		split(e, p, ">")
		if (index(p[1] "/", p[2] "/") == 1) {     # a folder inside the one it includes from
			up++
			printf "upward reference: %s -> %s (%s)%s\n", p[1], p[2], edge[e], e in allow ? "" : ": NOT ALLOWED"
			if (!(e in allow)) bad++
		}
		if (verbose == "-v") printf "  %s -> %s: %s\n", p[1], p[2], edge[e]
	}
	printf "includes: %d in %d files; cycles of files or folders: %s; upward references: %d\n", total,
	       length(files), bad ? "see above" : "0", up
	exit bad ? 1 : 0
}' "$tmp/files" "$tmp/includes" || status=1

# ---- calls ----
libs="lang/util/libscnutil.a lang/libscnlang.a render/image/libscnimage.a render/mesh/libscnmesh.a
render/shape/libscnshape.a render/accel/libscnaccel.a render/libscnrender.a render/libscnlower.a
render/pov/libscnpov.a"
for l in $libs; do
	[ -f "$build/$l" ] || { echo "check.sh: $build/$l is not built (run make first)"; exit 99; }
	# MEMBER<TAB>U|D<TAB>SYMBOL, the member named folder/file
	nm -A "$build/$l" 2>/dev/null | awk -v folder="$(dirname "$l")" '
		{ split($1, a, ":"); m = a[2]; sub(/^lib[a-z]*_a-/, "", m); sub(/\.o$/, "", m)
		  if (m == "lexer" || m == "parser" || m == "parser_quick") next
		  if ($2 == "U") print folder "/" m "\tU\t" $3
		  else if ($(NF-1) ~ /^[TDBRC]$/) print folder "/" m "\tD\t" $NF }'
done >"$tmp/symbols"
awk -F'\t' -v verbose="$verbose" '
$2 == "D" { def[$3] = $1; objs[$1] = 1; next }
{ use[NR] = $1 "\t" $3 }
END {
	for (i in use) { split(use[i], u, "\t"); if ((u[2] in def) && def[u[2]] != u[1]) { e = u[1] ">" def[u[2]]; if (!(e in edge)) { edge[e] = 1; adj[u[1]] = adj[u[1]] " " def[u[2]]; n++ } } }
	bad = 0
	for (s in objs) {
		delete seen; stack = adj[s]; cyc = 0
		while (stack != "") {
			m = split(stack, q, " "); v = q[m]; stack = ""; for (i = 1; i < m; i++) stack = stack " " q[i]
			if (v == s) { cyc = 1; break }
			if (v in seen) continue
			seen[v] = 1; stack = stack adj[v]
		}
		if (cyc) { printf "call cycle through %s, which calls", s; for (e in edge) { split(e, p, ">"); if (p[1] == s) printf " %s", p[2] } print ""; bad++ }
	}
	if (verbose == "-v") for (e in edge) { split(e, p, ">"); printf "  %s calls %s\n", p[1], p[2] }
	printf "calls: %d objects, %d edges between them; cycles: %d\n", length(objs), n, bad
	exit bad ? 1 : 0
}' "$tmp/symbols" || status=1
exit $status
