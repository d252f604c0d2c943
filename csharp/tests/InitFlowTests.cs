// The InitSys flow of the examples manual (section 2-4) through the C# binding, and the
// vendor return codes for bad input. Only functions the library exports today.
using System;
using System.Text;

public static class InitFlowTests
{
    const ushort CARD = Fixture.CARD;

    [MonoTest(200)]
    static void Version()
    {
        var sb = new StringBuilder(16);
        MCCL.MCC_GetVersion(sb);
        Check.Eq(sb.ToString(), "6.00", "MCC_GetVersion(StringBuilder)");
        var buf = new byte[16];
        MCCL.MCC_GetVersion(buf);
        Check.Eq(Encoding.ASCII.GetString(buf, 0, 5), "6.00\0", "MCC_GetVersion(byte[])");
    }

    [MonoTest(201)]
    static void ParametersRoundTrip()
    {
        Check.Eq(MCCL.MCC_SetSysMaxSpeed(100.0), MCCL.NO_ERR, "SetSysMaxSpeed(100)");
        Check.Eq(MCCL.MCC_GetSysMaxSpeed(), 100.0, "GetSysMaxSpeed");
        Check.Eq(MCCL.MCC_SetSysMaxSpeed(-1.0), MCCL.PARAMETER_ERR, "SetSysMaxSpeed(-1)");
        Check.Eq(MCCL.MCC_SetSysMaxSpeed(double.NaN), MCCL.PARAMETER_ERR, "SetSysMaxSpeed(NaN)");

        // Every field goes through at its offset: distinct values, read back.
        var p = Fixture.MacParam();
        p.wPosToEncoderDir = 1; p.wRPM = 1234; p.dwPPR = 70000; p.dfPitch = 2.5;
        p.dfGearRatio = 3.0; p.dfHighLimit = 111.0; p.dfLowLimit = -222.0;
        p.dfHighLimitOffset = 3.5; p.dfLowLimitOffset = -4.5; p.wPulseMode = MCCL.DDA_FMT_AB;
        p.wPulseWidth = 77; p.wCommandMode = MCCL.OCM_VOLTAGE; p.wPaddle = 9;
        p.wOverTravelUpSensorMode = MCCL.SL_NORMAL_CLOSE; p.wOverTravelDownSensorMode = MCCL.SL_NORMAL_OPEN;
        Check.Eq(MCCL.MCC_SetMacParam(ref p, 7, CARD), MCCL.NO_ERR, "SetMacParam ch 7");
        var q = new SYS_MAC_PARAM();
        Check.Eq(MCCL.MCC_GetMacParam(ref q, 7, CARD), MCCL.NO_ERR, "GetMacParam ch 7");
        Check.Eq(q.wRPM, (ushort)1234, "wRPM"); Check.Eq(q.dwPPR, 70000u, "dwPPR");
        Check.Eq(q.dfPitch, 2.5, "dfPitch"); Check.Eq(q.dfGearRatio, 3.0, "dfGearRatio");
        Check.Eq(q.dfHighLimit, 111.0, "dfHighLimit"); Check.Eq(q.dfLowLimit, -222.0, "dfLowLimit");
        Check.Eq(q.dfHighLimitOffset, 3.5, "dfHighLimitOffset"); Check.Eq(q.dfLowLimitOffset, -4.5, "dfLowLimitOffset");
        Check.Eq(q.wPulseMode, (ushort)MCCL.DDA_FMT_AB, "wPulseMode"); Check.Eq(q.wPulseWidth, (ushort)77, "wPulseWidth");
        Check.Eq(q.wCommandMode, (ushort)MCCL.OCM_VOLTAGE, "wCommandMode");
        Check.Eq(q.wOverTravelUpSensorMode, (ushort)MCCL.SL_NORMAL_CLOSE, "wOverTravelUpSensorMode");
        Check.Eq(q.wOverTravelDownSensorMode, (ushort)MCCL.SL_NORMAL_OPEN, "wOverTravelDownSensorMode (last field)");
        // wPosToEncoderDir 1 reverses the output: the factor reads negative, as the vendor's
        // library answers.
        Check.Eq(MCCL.MCC_GetConvFactor(7, CARD), -70000.0 * 3.0 / 2.5, "GetConvFactor = -(dwPPR x gear / pitch)");
        // Bad channel / card / content.
        Check.Eq(MCCL.MCC_SetMacParam(ref p, 8, CARD), MCCL.PARAMETER_ERR, "SetMacParam ch 8");
        Check.Eq(MCCL.MCC_SetMacParam(ref p, 0, MCCL.MAX_CARD_NUM), MCCL.PARAMETER_ERR, "SetMacParam card 12");
        var bad = Fixture.MacParam(); bad.dwPPR = 0;
        Check.Eq(MCCL.MCC_SetMacParam(ref bad, 0, CARD), MCCL.PARAMETER_ERR, "SetMacParam dwPPR 0");

        // A default-constructed struct (null ByValArray) marshals as zeros.
        var enc = new SYS_ENCODER_CONFIG();
        enc.wType = MCCL.ENC_TYPE_AB; enc.wInputRate = 4; enc.wABSwap = 1;
        Check.Eq(MCCL.MCC_SetEncoderConfig(ref enc, 3, CARD), MCCL.NO_ERR, "SetEncoderConfig (null wPaddle)");
        var enc2 = new SYS_ENCODER_CONFIG();
        Check.Eq(MCCL.MCC_GetEncoderConfig(ref enc2, 3, CARD), MCCL.NO_ERR, "GetEncoderConfig");
        Check.Eq(enc2.wType, (ushort)MCCL.ENC_TYPE_AB, "encoder wType");
        Check.Eq(enc2.wABSwap, (ushort)1, "encoder wABSwap");
        Check.Eq(enc2.wInputRate, (ushort)4, "encoder wInputRate");
        Check.True(enc2.wPaddle != null && enc2.wPaddle.Length == 2, "encoder wPaddle comes back as ushort[2]");
        enc.wInputRate = 5;
        Check.Eq(MCCL.MCC_SetEncoderConfig(ref enc, 3, CARD), MCCL.PARAMETER_ERR, "SetEncoderConfig rate 5");

        var home = new SYS_HOME_CONFIG();
        home.wMode = 3; home.wDirection = 1; home.wSensorMode = MCCL.SL_NORMAL_OPEN; home.nIndexCount = 2;
        home.dfAccTime = 100; home.dfDecTime = 200; home.dfHighSpeed = 10; home.dfLowSpeed = 1; home.dfOffset = -7.25;
        Check.Eq(MCCL.MCC_SetHomeConfig(ref home, 1, CARD), MCCL.NO_ERR, "SetHomeConfig");
        var home2 = new SYS_HOME_CONFIG();
        Check.Eq(MCCL.MCC_GetHomeConfig(ref home2, 1, CARD), MCCL.NO_ERR, "GetHomeConfig");
        Check.Eq(home2.nIndexCount, 2, "home nIndexCount"); Check.Eq(home2.dfOffset, -7.25, "home dfOffset (last field)");
        // Modes 0..19 are kept, as the vendor's library keeps them; 20 is refused.
        home.wMode = 20;
        Check.Eq(MCCL.MCC_SetHomeConfig(ref home, 1, CARD), MCCL.PARAMETER_ERR, "SetHomeConfig mode 20");
    }

    [MonoTest(202)]
    static void InitSystemFlow()
    {
        // Before init: no running system.
        Check.Eq(MCCL.MCC_GetMotionStatus(0), MCCL.INITIAL_MOTION_ERR, "GetMotionStatus before init");
        var p = Fixture.MacParam();
        for (ushort ch = 0; ch < MCCL.MAX_AXIS_NUM; ch++)
            Check.Eq(MCCL.MCC_SetMacParam(ref p, ch, CARD), MCCL.NO_ERR, "SetMacParam ch " + ch);
        Check.Eq(MCCL.MCC_CloseAllGroups(), MCCL.NO_ERR, "CloseAllGroups");
        Check.Eq(MCCL.MCC_CreateGroup(0, 1, 2, -1, -1, -1, -1, -1, CARD), 0, "CreateGroup -> 0");
        Check.Eq(MCCL.MCC_CreateGroupEx(3, 4, 5, -1, -1, -1, -1, -1, CARD, 50), 1, "CreateGroupEx -> 1");
        Check.Eq(MCCL.MCC_CreateGroupEx(6, -1, -1, -1, -1, -1, -1, -1, CARD), 2, "CreateGroupEx (default queue) -> 2");
        Check.Eq(MCCL.MCC_GetCmdQueueSize(1), 50, "GetCmdQueueSize(1)");
        Check.Eq(MCCL.MCC_GetCmdQueueSize(2), MCCL.MOTION_QUEUE_SIZE, "GetCmdQueueSize(2) = MOTION_QUEUE_SIZE");
        Check.Eq(MCCL.MCC_CloseGroup(2), MCCL.NO_ERR, "CloseGroup(2)");
        // A group on a card InitSystem will not have.
        Check.Eq(MCCL.MCC_CreateGroup(0, -1, -1, -1, -1, -1, -1, -1, 1), 2, "CreateGroup on card 1");

        var cards = new SYS_CARD_CONFIG[MCCL.MAX_CARD_NUM];
        cards[CARD].wCardType = MCCL.IMP_III_8_AXIS_PCI_CARD;
        Check.Eq(MCCL.MCC_InitSystem(2, cards, 1), MCCL.GROUP_PARAMETER_ERR, "InitSystem with a group on a missing card");
        Check.Eq(MCCL.MCC_CloseGroup(2), MCCL.NO_ERR, "CloseGroup(2)");
        Check.Eq(MCCL.MCC_InitSystem(2, cards, 0), MCCL.PARAMETER_ERR, "InitSystem 0 cards");
        Check.Eq(MCCL.MCC_InitSystem(2, cards, MCCL.MAX_CARD_NUM + 1), MCCL.PARAMETER_ERR, "InitSystem 13 cards");
        Check.Eq(MCCL.MCC_InitSystem(0, cards, 1), MCCL.PARAMETER_ERR, "InitSystem period 0");
        Check.Eq(MCCL.MCC_InitSystem(MCCL.IPO_PERIOD_MAX + 1, cards, 1), MCCL.PARAMETER_ERR, "InitSystem period 51");
        // A null card table is taken as IMP-III cards, as the vendor's library takes it; a
        // close forgets the group table, so the groups are made again.
        Check.Eq(MCCL.MCC_InitSystem(2, null, 1), MCCL.NO_ERR, "InitSystem null cards");
        Check.Eq(MCCL.MCC_CloseSystem(), MCCL.NO_ERR, "CloseSystem after the null table");
        Check.Eq(MCCL.MCC_CreateGroup(0, 1, 2, -1, -1, -1, -1, -1, CARD), 0, "CreateGroup -> 0 again");
        Check.Eq(MCCL.MCC_CreateGroupEx(3, 4, 5, -1, -1, -1, -1, -1, CARD, 50), 1, "CreateGroupEx -> 1 again");

        Check.Eq(MCCL.MCC_InitSystem(2, cards, 1), MCCL.NO_ERR, "MCC_InitSystem(2, cards, 1)");
        Check.Eq(MCCL.MCC_GetMotionStatus(0), MCCL.GMS_STOP, "GetMotionStatus(0)");
        Check.Eq(MCCL.MCC_GetMotionStatus(1), MCCL.GMS_STOP, "GetMotionStatus(1)");
        Check.Eq(MCCL.MCC_GetMotionStatus(2), MCCL.GROUP_PARAMETER_ERR, "GetMotionStatus(2)");
        Check.Eq(MCCL.MCC_GetMotionStatus(), MCCL.GMS_STOP, "GetMotionStatus() (default group 0)");
        Check.Eq(MCCL.MCC_GetConvFactor(0), 500.0, "GetConvFactor(0) (default card)");
        Check.Eq(MCCL.MCC_CheckDryRun(), 1, "CheckDryRun (off)");
        Check.Eq(MCCL.MCC_EnableDryRun(), MCCL.NO_ERR, "EnableDryRun");
        Check.Eq(MCCL.MCC_CheckDryRun(), 0, "CheckDryRun (on)");
        Check.Eq(MCCL.MCC_DisableDryRun(), MCCL.NO_ERR, "DisableDryRun");
        Check.Eq(MCCL.MCC_UpdateParam(), MCCL.NO_ERR, "UpdateParam");
        Check.Eq(MCCL.MCC_ResetMotion(), MCCL.NO_ERR, "ResetMotion");
        while (MCCL.MCC_GetMotionStatus(0) != MCCL.GMS_STOP)
            MCCL.MCC_TimeDelay(1);
        MCCL.MCC_TimeDelay(1);
        Check.Eq(MCCL.MCC_CloseSystem(), MCCL.NO_ERR, "MCC_CloseSystem()");
        Check.Eq(MCCL.MCC_GetMotionStatus(0), MCCL.INITIAL_MOTION_ERR, "GetMotionStatus after close");
    }

    [MonoTest(203)]
    static void InitTwoCardsByRef()
    {
        // Vendor style `ref cards[0]` with two cards: the library reads both elements, so the
        // marshaller must pass the array in place (SYS_CARD_CONFIG is blittable).
        var p = Fixture.MacParam();
        for (ushort card = 0; card < 2; card++)
            for (ushort ch = 0; ch < MCCL.MAX_AXIS_NUM; ch++)
                Check.Eq(MCCL.MCC_SetMacParam(ref p, ch, card), MCCL.NO_ERR, "SetMacParam");
        Check.Eq(MCCL.MCC_CloseAllGroups(), MCCL.NO_ERR, "CloseAllGroups");
        Check.Eq(MCCL.MCC_CreateGroup(0, 1, -1, -1, -1, -1, -1, -1, 0), 0, "group on card 0");
        Check.Eq(MCCL.MCC_CreateGroup(0, 1, -1, -1, -1, -1, -1, -1, 1), 1, "group on card 1");
        var cards = new SYS_CARD_CONFIG[2];
        cards[0].wCardType = MCCL.IMP_III_8_AXIS_PCI_CARD;
        cards[1].wCardType = MCCL.IMP_III_8_AXIS_PCI_CARD;
        Check.Eq(MCCL.MCC_InitSystem(2, ref cards[0], 2), MCCL.NO_ERR, "InitSystem(2, ref cards[0], 2)");
        Check.Eq(MCCL.MCC_GetMotionStatus(1), MCCL.GMS_STOP, "group on card 1 runs");
        Check.Eq(MCCL.MCC_CloseSystem(), MCCL.NO_ERR, "CloseSystem");
        Check.Eq(MCCL.MCC_InitSystemEx(2.5, cards, 2), MCCL.NO_ERR, "InitSystemEx(2.5, cards, 2)");
        Check.Eq(MCCL.MCC_CloseSystem(), MCCL.NO_ERR, "CloseSystem");
        Check.Eq(MCCL.MCC_InitSimulation(1, cards, 2), MCCL.NO_ERR, "InitSimulation(1, cards, 2)");
        Check.Eq(MCCL.MCC_CloseSystem(), MCCL.NO_ERR, "CloseSystem");
        Check.Eq(MCCL.MCC_CloseAllGroups(), MCCL.NO_ERR, "CloseAllGroups");
    }

    [MonoTest(204)]
    static void FixtureInit()
    {
        Check.Eq(Fixture.InitOneCard(), MCCL.NO_ERR, "Fixture.InitOneCard");
        Check.Eq(MCCL.MCC_GetMotionStatus(0), MCCL.GMS_STOP, "GetMotionStatus(0)");
    }
}
