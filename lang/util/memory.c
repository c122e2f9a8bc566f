/* memory.c: the memory a run may have, from sysconf, getrlimit and /proc/self/statm.
 * Physical memory and not what is free now: the page cache gives way, and a request
 * that fits the machine is the user's to make. */
#include "memory.h"

#include <stdio.h>
#include <sys/resource.h>
#include <unistd.h>

/* Fields of /proc/self/statm in bytes: the address space mapped (field 1) and the data
 * and stack (field 6); 0 when unknown. */
static void mapped(uint64_t *vm, uint64_t *data)
{
	*vm = *data = 0;
	FILE *f = fopen("/proc/self/statm", "r");
	if (!f)
		return;
	unsigned long long size, resident, shared, text, lib, dat;
	if (fscanf(f, "%llu %llu %llu %llu %llu %llu", &size, &resident, &shared, &text, &lib, &dat) == 6) {
		uint64_t page = (uint64_t)sysconf(_SC_PAGESIZE);
		*vm = size * page;
		*data = dat * page;
	}
	fclose(f);
}

/* limit less used (0 if used is more), or UINT64_MAX for no limit. */
static uint64_t left(int resource, uint64_t used)
{
	struct rlimit r;
	if (getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY)
		return UINT64_MAX;
	return (uint64_t)r.rlim_cur > used ? (uint64_t)r.rlim_cur - used : 0;
}

uint64_t memory_available(const char **what)
{
	long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
	uint64_t best = pages > 0 && page > 0 ? (uint64_t)pages * (uint64_t)page : UINT64_MAX;
	*what = "this machine has";
	uint64_t vm, data;
	mapped(&vm, &data);
	uint64_t as = left(RLIMIT_AS, vm), ds = left(RLIMIT_DATA, data);
	if (as < best)
		best = as, *what = "ulimit -v leaves";
	if (ds < best)
		best = ds, *what = "ulimit -d leaves";
	return best;
}

void memory_text(uint64_t bytes, char *buf, size_t n)
{
	static const char *const units[] = { "bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB" };
	double v = (double)bytes;
	int u = 0;
	while (v >= 1024 && u < 6)
		v /= 1024, u++;
	if (u == 0)
		snprintf(buf, n, "%llu bytes", (unsigned long long)bytes);
	else
		snprintf(buf, n, "%.1f %s", v, units[u]);
}

bool memory_fits(uint64_t need, char *msg, size_t n)
{
	const char *what;
	uint64_t have = memory_available(&what);
	if (need <= have)
		return true;
	char a[32], b[32];
	memory_text(need, a, sizeof a);
	memory_text(have, b, sizeof b);
	snprintf(msg, n, "needs %s; %s %s", a, what, b);
	return false;
}
