/* panel_demo.c: an ordinary vendor-style program, with nothing of the panel in it, for
 * the browser panel's test and the README's screenshot (MCCL_PANEL, docs/panel.md).
 *
 * Group 0 on channels 0..2 of one card at 2 ms: a line to (10, 0), then circles of radius
 * 10 about the origin (62.8 UU each at 20 UU/s, about 3.1 s) for at most `seconds`
 * (argv[1], default 120). It waits until the group stops, which happens early when the
 * emergency stop is pressed (on the panel), prints the status and the error record,
 * stays up `linger` ms (argv[2], default 8000) so the panel can be read, and exits 0. C99. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "MCCL.h"
#include "MCCL_Fun.h"

int main(int argc, char **argv)
{
    SYS_CARD_CONFIG card[1];
    int seconds = argc > 1 ? atoi(argv[1]) : 120;
    int linger = argc > 2 ? atoi(argv[2]) : 8000;
    int circles, i, err;
    memset(card, 0, sizeof card);
    card[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    if (MCC_CreateGroup(0, 1, 2, -1, -1, -1, -1, -1, 0) < 0)
        return 1;
    if (MCC_InitSystem(2, card, 1) != NO_ERR)
        return 1;
    MCC_SetFeedSpeed(20, 0);
    MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL);
    circles = seconds / 3 + 1;
    for (i = 0; i < circles; i++)
        if (MCC_CircleXY(0, 0, i % 4 == 3 ? CIR_CW : CIR_CCW, 0) < 0)
            break;
    printf("panel_demo: %d circles queued\n", i);
    fflush(stdout);
    while (MCC_GetMotionStatus(0) != GMS_STOP)
        MCC_TimeDelay(20);
    err = MCC_GetErrorCode(0);
    printf("panel_demo: stopped, status %d, error record 0x%X\n", MCC_GetMotionStatus(0), err);
    fflush(stdout);
    MCC_TimeDelay(linger);
    MCC_CloseSystem();
    return 0;
}
