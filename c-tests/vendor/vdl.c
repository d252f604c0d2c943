/* The one platform-dependent part of the differential scenarios: load a motion library by
 * path and look its functions up by name (LoadLibrary/GetProcAddress on Windows, dlopen/dlsym
 * elsewhere), and sleep. Kept apart from the scenarios so that they never include
 * <windows.h> beside MCCL.h. */
#include "vdl.h"
#include <stdio.h>
#include <stdlib.h>

#ifdef _WIN32
#include <windows.h>
static HMODULE lib;

int vdl_open(const char *path)
{
    char dir[MAX_PATH];
    const char *slash = strrchr(path, '\\');
    if (slash && (size_t)(slash - path) < sizeof dir) {
        memcpy(dir, path, (size_t)(slash - path));
        dir[slash - path] = 0;
        SetDllDirectoryA(dir); /* the vendor's DLL loads its driver DLLs from its folder */
    }
    lib = LoadLibraryA(path);
    if (!lib)
        fprintf(stderr, "vdiff: LoadLibrary(%s) failed: error %lu\n", path, GetLastError());
    return lib != NULL;
}

void *vdl_sym(const char *name)
{
    return lib ? (void *)GetProcAddress(lib, name) : NULL;
}

void vdl_sleep_ms(int ms)
{
    Sleep((DWORD)ms);
}
#else
#include <dlfcn.h>
#include <time.h>
static void *lib;

int vdl_open(const char *path)
{
    lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!lib)
        fprintf(stderr, "vdiff: dlopen(%s) failed: %s\n", path, dlerror());
    return lib != NULL;
}

void *vdl_sym(const char *name)
{
    return lib ? dlsym(lib, name) : NULL;
}

void vdl_sleep_ms(int ms)
{
    struct timespec ts = {ms / 1000, (long)(ms % 1000) * 1000000L};
    nanosleep(&ts, NULL);
}
#endif
