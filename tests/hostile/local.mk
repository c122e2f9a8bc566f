# tests/hostile/local.mk: hostile input: deep nesting, huge and garbage files, floods of
# errors, names and includes. Each script caps scn's time and memory (lib-hostile.sh).
HOSTILE_TESTS = \
	tests/hostile/nesting.sh \
	tests/hostile/loops.sh \
	tests/hostile/language.sh \
	tests/hostile/big.sh \
	tests/hostile/garbage.sh \
	tests/hostile/names.sh \
	tests/hostile/errors.sh \
	tests/hostile/files.sh \
	tests/hostile/numbers.sh
TESTS += $(HOSTILE_TESTS)
EXTRA_DIST += $(HOSTILE_TESTS) tests/hostile/lib-hostile.sh
