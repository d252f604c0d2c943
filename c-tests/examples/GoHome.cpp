// GoHome.cpp: examples manual §15 (go home), written the way the manual writes it. Run
// with MCCL_SIM=c-tests/sim/home_x.toml: X's home sensor is active on [-3, -2] UU.
//
// The manual's parameters: mode 3, negative direction, normally open, 300 ms to reach and
// to leave dfHighSpeed = 10 UU/s. By hand (user manual §2.8.1 mode 3, 500 pulses/UU):
// accelerating covers 10 x 0.3 / 2 = 1.5 UU in 300 ms, then 0.01 UU a 1 ms tick: the
// sensor's edge at -2 UU is reached at 350 ms and seen in the next tick; decelerating over
// 300 ms covers 1.5 UU more: the machine home is -3.5 UU (-1750 pulses). Phase 3
// (dfOffset 0) ends there; the next tick zeroes it: homing completes at 652 ms. Then the
// command position, the pulse counter and the encoder read 0.
// A second run with dfOffset = 1.5 UU moves from that machine home to the working home
// 1.5 UU above it (-2 UU of the machine), and that is 0.
#include "MotionSys.h"
#include "MCCL_Sim.h"

static double MotorX()
{
    double dfPos = 0;
    long long llPulses = 0;
    CHECK_EQ(MCCL_SimGetMotor(CARD_INDEX, 0, &dfPos, &llPulses), NO_ERR);
    return dfPos;
}

int main()
{
    // InitSys.cpp's start-up, with X's limit switches wired (normally open): the search
    // of a go home that starts inside the sensor runs to a limit switch first (§2.8.1).
    CHECK_EQ(MCC_SetSysMaxSpeed(EX_MAX_SPEED), NO_ERR);
    SetMacParams();
    SYS_MAC_PARAM stAxisParam;
    CHECK_EQ(MCC_GetMacParam(&stAxisParam, 0, CARD_INDEX), NO_ERR);
    stAxisParam.wOverTravelUpSensorMode   = SL_NORMAL_OPEN;
    stAxisParam.wOverTravelDownSensorMode = SL_NORMAL_OPEN;
    CHECK_EQ(MCC_SetMacParam(&stAxisParam, 0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_CloseAllGroups(), NO_ERR);
    g_nGroupIndex = MCC_CreateGroup(0, 1, 2, 3, 4, 5, 6, 7, CARD_INDEX);
    CHECK_EQ(g_nGroupIndex, 0);
    if (StartSystem() != NO_ERR)
        return check_done("GoHome");

    // Step 1: the go-home parameters.
    SYS_HOME_CONFIG stHomeConfig;
    memset(&stHomeConfig, 0, sizeof(SYS_HOME_CONFIG));
    stHomeConfig.wMode       = 3;    // the go-home mode
    stHomeConfig.wDirection  = 1;    // go home in the negative direction
    stHomeConfig.wSensorMode = 0;    // Normal Open
    stHomeConfig.nIndexCount = 0;    // the encoder index pulse's number
    stHomeConfig.dfAccTime   = 300;  // ms
    stHomeConfig.dfDecTime   = 300;  // ms
    stHomeConfig.dfHighSpeed = 10;   // UU/sec
    stHomeConfig.dfLowSpeed  = 2;    // UU/sec
    stHomeConfig.dfOffset    = 0;    // UU

    // Step 2: set them for every channel.
    for (WORD wChannel = 0; wChannel < MAX_AXIS_NUM; wChannel++)
        CHECK_EQ(MCC_SetHomeConfig(&stHomeConfig, wChannel, CARD_INDEX), NO_ERR);

    WORD wHome = 9;
    CHECK_EQ(MCC_GetHomeSensorStatus(&wHome, 0, CARD_INDEX), NO_ERR);
    CHECK_EQ(wHome, 0);   // the wiring setting is right: not active away from the sensor

    // Step 3: go home; 0xff: that axis does not go home.
    CHECK_EQ(MCC_Home(0, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_GetGoHomeStatus(), 0);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
    // Motion commands wait for the homing: the group refuses them meanwhile.
    CHECK_EQ(MCC_Line(1, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), COMMAND_NOTACCEPTED_ERR);
    CHECK_EQ(MCC_Home(0, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, CARD_INDEX), COMMAND_NOTFINISHED_ERR);

    // Step 5: nStatus 1 means the go home has completed.
    int nStatus = 0;
    long lMs = 0;
    while ((nStatus = MCC_GetGoHomeStatus()) == 0 && lMs < 100000)
    {
        MCC_TimeDelay(1);
        lMs++;
    }
    CHECK_EQ(nStatus, 1);
    if (SteppedClock())
        CHECK(lMs >= 651 && lMs <= 653);
    printf("Go home (mode 3): done after %ld ms, X's motor at %.4f UU of the machine\n", lMs, MotorX());
    CHECK_NEAR(MotorX(), -3.5, POS_TOL);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);
    long lPulse[8], lEnc = -1;
    CHECK_EQ(MCC_GetPulsePos(&lPulse[0], &lPulse[1], &lPulse[2], &lPulse[3], &lPulse[4],
                             &lPulse[5], &lPulse[6], &lPulse[7], g_nGroupIndex), NO_ERR);
    CHECK_EQ(lPulse[0], 0);
    CHECK_EQ(MCC_GetENCValue(&lEnc, 0, CARD_INDEX), NO_ERR);
    CHECK_EQ(lEnc, 0);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);

    // Motion is relative to the home now.
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    CHECK(MCC_Line(1, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    WaitStop(g_nGroupIndex);
    CHECK_NEAR(MotorX(), -2.5, POS_TOL);

    // With a working-home offset of 1.5 UU: the machine home is found again (the same
    // -3.5 UU: the search starts at -2.5 UU, inside the sensor, so Case 2 applies: to the
    // - limit switch, back up through the sensor, then as before), and phase 3 moves
    // 1.5 UU up from it.
    stHomeConfig.dfOffset = 1.5;
    CHECK_EQ(MCC_SetHomeConfig(&stHomeConfig, 0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_Home(0, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, CARD_INDEX), NO_ERR);
    for (lMs = 0; (nStatus = MCC_GetGoHomeStatus()) == 0 && lMs < 100000; lMs++)
        MCC_TimeDelay(1);
    CHECK_EQ(nStatus, 1);
    printf("Go home with dfOffset 1.5: X's motor at %.4f UU of the machine, X = 0\n", MotorX());
    CHECK_NEAR(MotorX(), -2.0, POS_TOL);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);

    // Step 4 (abort) is in home_abort.c; after a completed homing it has nothing to stop.
    CHECK_EQ(MCC_AbortGoHome(), NO_ERR);
    CHECK_EQ(MCC_Home(8, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_Home(0, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 1), PARAMETER_ERR);
    Close();
    CHECK_EQ(MCC_GetGoHomeStatus(), INITIAL_MOTION_ERR);
    return check_done("GoHome");
}
