// header_smoke.cpp: the headers in C++, using the vendor's default arguments.
#include "MCCL_Fun.h"
#include "mccl.h"
#include "mcl.h"
#include "MCCL_Sim.h"

static void MCC_CALLBACK isr(ENCINT *p) { (void)p; }
// The manuals write routines with _stdcall.
static void _stdcall isr2(LIOINT *p) { (void)p; }

int smoke();
int smoke()
{
    SYS_MAC_PARAM m;
    ENCISR cb = isr;
    LIOISR cb2 = isr2;
    (void)cb;
    (void)cb2;
    m.dwPPR = 1;
    (void)mcl_set_motor_maximum_velocity(0, 0, 100);   // direction_modifier defaulted
    (void)mcl_synchronous_move_motor(0, 1, 0, 1, 0, 1, 0); // execute defaulted
    // wCardIndex and wGroupIndex defaulted, as vendor C++ code writes them.
    return MCC_GetMacParam(&m, 0) + MCC_GetCmdQueueSize() + MCC_GetMotionStatus()
         + MCC_CreateGroupEx(0, 1, 2, 3, 4, 5, 6, 7, 0);
}
