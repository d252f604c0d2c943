/* header_smoke.c: includes every header (both spellings) and uses a little of each, so
 * that -Wall -Wextra -Werror under every standard sees the declarations. */
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "mccl.h"
#include "MCCL.h"
#include "mcl.h"
#include "MCCL_Sim.h"

/* A routine has the library's calling convention (stdcall on 32-bit Windows). */
static void MCC_CALLBACK isr(ENCINT *p) { (void)p; }

int smoke(void);
int smoke(void)
{
    SYS_MAC_PARAM m;
    ENCISR cb = isr;
    (void)cb;
    m.dwPPR = 1;
    int v = 0;
    (void)mcl_get_library_version(&v);
    return MCC_GetMacParam(&m, 0, 0) + (int)MCC_GetSysMaxSpeed() + GROUP_INVALID - GROUP_INVALID;
}
