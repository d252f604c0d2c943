/* bcryptprimitives.c: a stand-in for Wine 8, whose prefix lacks bcryptprimitives.dll.
 * Rust's standard library (Windows 10 and later) imports ProcessPrng from it; real
 * Windows has it. Test-only: wine-prefix.sh puts it into the test prefix when Wine has
 * none, and it is never shipped. ProcessPrng fills the buffer from RtlGenRandom
 * (advapi32's SystemFunction036), which Wine 8 does have. */
#include <windows.h>

BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

__declspec(dllexport) BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length)
{
    while (length > 0) {
        ULONG chunk = length > 0x40000000 ? 0x40000000 : (ULONG)length;
        if (!SystemFunction036(data, chunk))
            return FALSE;
        data += chunk;
        length -= chunk;
    }
    return TRUE;
}
