/* fuzz.h: what the libFuzzer harnesses share: the entry point libFuzzer (or replay.c)
 * calls, and the private temporary file through which inputs reach readers that take a
 * path. */
#ifndef SCN_FUZZ_H
#define SCN_FUZZ_H

#include <stddef.h>
#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Writes data to the file called name in a directory of this process's own (made on the
 * first call, removed with its file at exit) and returns the file's path. Each call
 * replaces the file of the call before. A failure to write is the machine's, not the
 * input's: it aborts. */
const char *fuzz_file(const char *name, const uint8_t *data, size_t size);

#endif
