/* check_names.c: the checker's symbol table: one chain of bindings per name, innermost
 * first, in a hash table that a hostile scene cannot degrade; scopes, and the warnings
 * for what a closing scope bound and never used. */
#include "check_internal.h"

#include <stdlib.h>
#include <string.h>

#include "arena.h"
#include "builtins.h"
#include "xalloc.h"

/* FNV-1a with a final mix: unlike h * 33 + c, whose collisions a scene can spell
 * ("az" and "bY" hash alike, so do all 2^k strings of k such pairs), it does not let a
 * hostile scene put every name in one bucket and make each lookup linear. */
static size_t hash_name(const char *s)
{
	uint64_t h = 0xcbf29ce484222325u;
	while (*s)
		h = (h ^ (unsigned char)*s++) * 0x100000001b3u;
	h ^= h >> 33;
	h *= 0xff51afd7ed558ccdu;
	h ^= h >> 33;
	return (size_t)h;
}

static struct name_entry *entry_for(struct checker *c, const char *name, bool create)
{
	struct name_entry **slot = &c->buckets[hash_name(name) & (c->nbuckets - 1)];
	for (struct name_entry *e = *slot; e; e = e->next)
		if (strcmp(e->name, name) == 0)
			return e;
	if (!create)
		return NULL;
	if (c->nentries >= 2 * c->nbuckets) {
		size_t n = c->nbuckets * 4;
		struct name_entry **b = xcalloc(n, sizeof *b);
		for (size_t i = 0; i < c->nbuckets; i++)
			for (struct name_entry *e = c->buckets[i], *next; e; e = next) {
				next = e->next;
				size_t h = hash_name(e->name) & (n - 1);
				e->next = b[h];
				b[h] = e;
			}
		free(c->buckets);
		c->buckets = b;
		c->nbuckets = n;
		slot = &c->buckets[hash_name(name) & (n - 1)];
	}
	struct name_entry *e = arena_alloc(c->arena, sizeof *e);
	e->name = name;
	e->next = *slot;
	*slot = e;
	c->nentries++;
	return e;
}

struct binding *names_lookup(struct checker *c, const char *name)
{
	struct name_entry *e = entry_for(c, name, false);
	return e ? e->top : NULL;
}

void names_suggest_visible(struct checker *c, struct suggestion *s, enum name_class what)
{
	for (size_t i = 0; i < c->nbuckets; i++)
		for (struct name_entry *e = c->buckets[i]; e; e = e->next)
			if (e->top && names_class(e->top->kind) == what)
				suggest_consider(s, e->name);
	for (int k = 0; k < BUILTIN_COUNT; k++)
		if ((what == NAMES_VALUES && !builtin_is_function(k)) || (what == NAMES_FUNCTIONS && builtin_is_function(k)))
			suggest_consider(s, builtin_name(k));
}

enum name_class names_class(enum binding_kind kind)
{
	switch (kind) {
	case BIND_MATERIAL: return NAMES_MATERIALS;
	case BIND_FUNCTION: return NAMES_FUNCTIONS;
	case BIND_MACRO: return NAMES_MACROS;
	default: return NAMES_VALUES;
	}
}

/* "'x' is never used", with what x is when that is not a value. */
static const char *unused_format(enum binding_kind kind)
{
	switch (kind) {
	case BIND_MATERIAL: return "material '%s' is never used";
	case BIND_FUNCTION: return "function '%s' is never used";
	case BIND_MACRO: return "macro '%s' is never used";
	default: return "'%s' is never used";
	}
}

void names_push_scope(struct checker *c)
{
	c->scope_bindings[++c->scope] = NULL;
}

/* Leaves a scope: warns about what it bound and never used, and unhides what it hid.
 * After an error the warning is left out: the use may be what the error was about, or
 * in text that recovery skipped. */
void names_pop_scope(struct checker *c)
{
	/* the list is newest first: reversed, the warnings come in the order of the file */
	struct binding *oldest = NULL;
	for (struct binding *b = c->scope_bindings[c->scope], *next; b; b = next) {
		next = b->scope_next;
		b->scope_next = oldest;
		oldest = b;
	}
	for (struct binding *b = oldest; b; b = b->scope_next) {
		/* nor for what an included file defines: a library need not use all it offers */
		if (!b->used && b->kind != BIND_LOOP && b->kind != BIND_PARAM && c->diag->errors == 0 &&
		    !diag_source_at(c->diag, b->span.start)->included)
			diag_warning(c->diag, b->span, unused_format(b->kind), b->name);
		b->entry->top = b->shadowed;
	}
	c->scope--;
}

/* Functions are only ever called, so they live apart from bindings: a material may be
 * called 'floor' (LANGUAGE.md's own example does). A binding may also hide 'pi'. */
struct binding *names_bind(struct checker *c, const char *name, struct span sp, enum binding_kind kind,
                           enum ast_type type)
{
	struct name_entry *e = entry_for(c, name, true);
	if (e->top && e->top->scope == c->scope) {
		diag_error(c->diag, sp, "'%s' is already defined in this scope", name);
		diag_note(c->diag, e->top->span, "'%s' was defined here", name);
		return NULL;
	}
	struct binding *b = arena_alloc(c->arena, sizeof *b);
	b->name = name;
	b->span = sp;
	b->kind = kind;
	b->type = type;
	b->slot = c->nslots++;
	b->scope = c->scope;
	b->entry = e;
	b->shadowed = e->top;
	e->top = b;
	b->scope_next = c->scope_bindings[c->scope];
	c->scope_bindings[c->scope] = b;
	return b;
}
