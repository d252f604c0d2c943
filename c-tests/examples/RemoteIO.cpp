// RemoteIO.cpp: examples manual §33 (ARIOCtrl.cpp: set and read remote outputs and
// inputs) and §34 (ARIOStatus.cpp: transfer status), plus a remote input trigger.
//
// The virtual card's remote I/O slaves loop their outputs back to their inputs (a wire
// from output n to input n), so what the program writes it reads back after the next
// transfer; data moves once per tick (1 ms here), ARIO data once per bus cycle (by
// default shorter than a tick). Then the calls the manuals do not document: the vendor
// test's MCC_SetRIOTransError(5, 0, 0) and the ARIO update rate, clock divider and
// node-to-node delay (docs/compatibility.md "ARIO timing": the cycle formula).
// Signatures are the B/C ones with wSet (docs/decisions.md, "Vendor interface"); the
// manual's A-form calls
// MCC_EnableARIOSlaveControl(RIO_SLAVE0, CARD_INDEX) and
// MCC_GetARIOTransStatus(&w, CARD_INDEX) compile to the same calls here for slave 0 of
// card 0 (wSet = 0 and the C++ defaults). The slave status is a WORD in B/C (the manual's
// DWORD is the A form).
#include "MotionSys.h"

static volatile int nRDI0 = 0;

void MCC_CALLBACK RIO_ISR_Function(RIOINT *pstINTSource)
{
    if (pstINTSource->RDI0)
        nRDI0++;
}

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("RemoteIO");

    // §33: start data transfer with the first slave (RIO_SLAVE0).
    CHECK_EQ(MCC_EnableARIOSlaveControl(RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    // The manual's A-form call: wSet = RIO_SLAVE0 = 0, wSlave = CARD_INDEX = 0.
    CHECK_EQ(MCC_EnableARIOSlaveControl(RIO_SLAVE0, CARD_INDEX), NO_ERR);

    WORD wValue = 0xFFFF;
    CHECK_EQ(MCC_SetARIOOutputValue(0x00FF, RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetARIOInputValue(&wValue, RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    printf("  slave 0: outputs 0x00FF -> inputs 0x%04X\n", wValue);
    CHECK_EQ(wValue, 0x00FF);
    CHECK_EQ(MCC_SetARIOOutputValue(0x8001, RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_GetARIOInputValue(&wValue, RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    CHECK_EQ(wValue, 0x00FF);     // not transferred yet
    MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetARIOInputValue(&wValue, RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    CHECK_EQ(wValue, 0x8001);
    CHECK_EQ(MCC_GetARIOOutputValue(&wValue, RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    CHECK_EQ(wValue, 0x8001);

    // A slave whose transfer is off keeps its inputs.
    CHECK_EQ(MCC_SetARIOOutputValue(0x1234, RIO_SET0, RIO_SLAVE31, CARD_INDEX), NO_ERR);
    MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetARIOInputValue(&wValue, RIO_SET0, RIO_SLAVE31, CARD_INDEX), NO_ERR);
    CHECK_EQ(wValue, 0);
    CHECK_EQ(MCC_EnableARIOSlaveControl(RIO_SET0, RIO_SLAVE31, CARD_INDEX), NO_ERR);
    MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetARIOInputValue(&wValue, RIO_SET0, RIO_SLAVE31, CARD_INDEX), NO_ERR);
    CHECK_EQ(wValue, 0x1234);

    // §34: 1 = transferring normally, 0 = transfer error.
    WORD wTransStatus = 9, wMasterStatus = 9, wSlaveStatus = 9;
    DWORD dwSlaveFail = 9;
    CHECK_EQ(MCC_GetARIOTransStatus(&wTransStatus, RIO_SET0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_GetARIOMasterStatus(&wMasterStatus, RIO_SET0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_GetARIOSlaveStatus(&wSlaveStatus, RIO_SET0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_GetARIOSlaveFail(&dwSlaveFail, RIO_SET0, CARD_INDEX), NO_ERR);
    printf("  transfer %d, master %d, slave %d, failed slaves 0x%lX\n", wTransStatus,
           wMasterStatus, wSlaveStatus, (unsigned long)dwSlaveFail);
    CHECK_EQ(wTransStatus, 1);
    CHECK_EQ(wMasterStatus, 1);
    CHECK_EQ(wSlaveStatus, 1);
    CHECK_EQ(dwSlaveFail, 0);
    CHECK_EQ(MCC_DisableARIOSlaveControl(RIO_SET0, RIO_SLAVE31, CARD_INDEX), NO_ERR);

    // RIO: set 1, port 0; digital input 0 (bit 0 of port 0) calls the RIO routine on
    // its rising edge.
    CHECK_EQ(MCC_SetRIORoutine(RIO_ISR_Function, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableRIOSetControl(RIO_SET1, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableRIOSlaveControl(RIO_SET1, 0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetRIOTriggerType(RIO_INT_RISE, RIO_SET1, RIO_DI0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableRIOInputTrigger(RIO_SET1, RIO_DI0, CARD_INDEX), NO_ERR);
    MCC_TimeDelay(1);
    for (int i = 0; i < 5; i++)
    {
        CHECK_EQ(MCC_SetRIOOutputValue(0x0001, RIO_SET1, RIO_PORT0, CARD_INDEX), NO_ERR);
        MCC_TimeDelay(2);
        CHECK_EQ(MCC_SetRIOOutputValue(0x0000, RIO_SET1, RIO_PORT0, CARD_INDEX), NO_ERR);
        MCC_TimeDelay(2);
    }
    printf("  RIO DI0 toggled 5 times: %d rising-edge interrupts\n", nRDI0);
    CHECK_EQ(nRDI0, 5);
    CHECK_EQ(MCC_GetRIOInputValue(&wValue, RIO_SET1, RIO_PORT0, CARD_INDEX), NO_ERR);
    CHECK_EQ(wValue, 0);

    // The vendor test's call: set 0 tolerates 5 consecutive failed transfers of a slave
    // before it reports it. With working slaves the statuses stay 1.
    CHECK_EQ(MCC_SetRIOTransError(5, RIO_SET0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetRIOTransError(5, 2, CARD_INDEX), PARAMETER_ERR);
    MCC_TimeDelay(10);
    CHECK_EQ(MCC_GetRIOTransStatus(&wTransStatus, RIO_SET1, CARD_INDEX), NO_ERR);
    CHECK_EQ(wTransStatus, 1);

    // ARIO set 0 at 100 updates per second: the outputs reach the slave (and come back)
    // 10 ms after the call, not before.
    CHECK_EQ(MCC_SetARIOUpdateRate(100.0, RIO_SET0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetARIOOutputValue(0x0F0F, RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    MCC_TimeDelay(9);
    CHECK_EQ(MCC_GetARIOInputValue(&wValue, RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    CHECK_EQ(wValue, 0x8001);
    MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetARIOInputValue(&wValue, RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    CHECK_EQ(wValue, 0x0F0F);
    // A bit every 1000 system clocks (10 us: 32 bits = 320 us per slave) and 68000 clocks
    // (680 us) between slaves: 1 ms per slave. With 20 slaves transmitting a cycle takes
    // 20 ms, longer than the 10 ms asked for, so the bus sets the pace.
    for (WORD wSlave = RIO_SLAVE1; wSlave < RIO_SLAVE20; wSlave++)
        CHECK_EQ(MCC_EnableARIOSlaveControl(RIO_SET0, wSlave, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetARIOClockDivider(1000, RIO_SET0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetARIONode2NodeDelay(68000), NO_ERR);    // C++ default: card 0
    CHECK_EQ(MCC_SetARIOOutputValue(0xF0F0, RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    MCC_TimeDelay(19);
    CHECK_EQ(MCC_GetARIOInputValue(&wValue, RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    CHECK_EQ(wValue, 0x0F0F);
    MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetARIOInputValue(&wValue, RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    printf("  ARIO, 20 slaves at divider 1000 and 680 us apart: 0x%04X after 20 ms\n", wValue);
    CHECK_EQ(wValue, 0xF0F0);
    CHECK_EQ(MCC_SetARIOUpdateRate(0.0, RIO_SET0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetARIOUpdateRate(-1.0, RIO_SET0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetARIOClockDivider(0, RIO_SET0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetARIONode2NodeDelay(0, 12), PARAMETER_ERR);

    // Bad set, slave, port: PARAMETER_ERR.
    CHECK_EQ(MCC_SetARIOOutputValue(1, 2, RIO_SLAVE0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetARIOOutputValue(1, RIO_SET0, 32, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetRIOOutputValue(1, RIO_SET0, 4, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_GetARIOInputValue(NULL, RIO_SET0, RIO_SLAVE0, CARD_INDEX), PARAMETER_ERR);

    CHECK_EQ(MCC_DisableARIOSlaveControl(RIO_SET0, RIO_SLAVE0, CARD_INDEX), NO_ERR);
    Close();
    return check_done("RemoteIO");
}
