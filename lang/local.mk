# lang/local.mk: the front end: lexer, parser, AST, checker, evaluator, diagnostics.
# no render/ here: the front end knows nothing of the renderer (parser.h is built in
# the build tree's lang/)
LANG_INCLUDES = -I$(srcdir)/%D% -I%D% $(UTIL_INCLUDES)
noinst_LIBRARIES += lang/libscnlang.a
lang_libscnlang_a_CPPFLAGS = $(BASE_CPPFLAGS) $(LANG_INCLUDES)
lang_libscnlang_a_SOURCES = \
	%D%/arena.c %D%/arena.h \
	%D%/ast.c %D%/ast.h \
	%D%/diag.c %D%/diag.h \
	%D%/keywords.c %D%/keywords.h \
	%D%/lang.h \
	%D%/lexer.l \
	%D%/parser.y
BUILT_SOURCES += %D%/parser.h
# parser.y once more, without LAC: see parser_quick.c
lang_libscnlang_a_SOURCES += %D%/parser_quick.c
BUILT_SOURCES += %D%/parser_nolac.c
EXTRA_DIST += %D%/parser_nolac.c
%D%/parser_nolac.c: %D%/parser.y
	$(AM_V_GEN)$(YACC) -Wall -Wno-yacc -Fparse.lac=none -o $@ $(srcdir)/%D%/parser.y
lang_libscnlang_a_SOURCES += \
	%D%/builtins.c %D%/builtins.h \
	%D%/check.c %D%/check.h %D%/check_internal.h %D%/check_block.c %D%/check_expr.c \
	%D%/check_names.c %D%/check_solid.c \
	%D%/eval.c %D%/eval.h %D%/eval_internal.h %D%/eval_call.c %D%/eval_expr.c %D%/eval_object.c %D%/eval_report.c \
	%D%/eval_texture.c %D%/eval_xform.c \
	%D%/file.c %D%/file.h \
	%D%/scene_desc.c %D%/scene_desc.h \
	%D%/value.c %D%/value.h
lang_libscnlang_a_SOURCES += %D%/load.c %D%/load.h
lang_libscnlang_a_SOURCES += %D%/suggest.c %D%/suggest.h
