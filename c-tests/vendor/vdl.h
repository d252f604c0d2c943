/* Loading the library under test by path and finding its functions by name. */
#ifndef VDIFF_VDL_H
#define VDIFF_VDL_H
#include <string.h>

/* Loads the library at `path`; 1 on success, 0 (and a message on stderr) otherwise. */
int vdl_open(const char *path);
/* The address of the exported function `name`, NULL when the library has none. */
void *vdl_sym(const char *name);
/* Sleeps about `ms` milliseconds of wall time. */
void vdl_sleep_ms(int ms);
#endif
